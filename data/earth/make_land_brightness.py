#!/usr/bin/env python3
"""Builds the land-brightness map (eoir-raster v1, uint8, 2048 x 1024): per
pixel of the Blue Marble, its brightness relative to the mean brightness of
its land-cover class, by which bitmap mode scales the class's spectral
reflectance (the spectrum keeps its shape; data/earth/README.md, "Land
brightness").

Source (Debian package, read at build time only): xplanet-images 1.3.1,
/usr/share/xplanet/images/earth.jpg, 2048 x 1024 plate carree, NASA Visible
Earth record 11612 ("Blue Marble", R. Stockli et al., NASA Earth Observatory,
MODIS 2001 composite; not copyrighted, /usr/share/doc/xplanet-images/README).

Brightness: the relative luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of the
linear (decoded sRGB, IEC 61966-2-1) pixel. Classes: make_earth_rasters.py's
classify_image (the same pixel classes as the land cover). The class mean is
the area-weighted (cos latitude) mean of Y over the pixels the image shows as
land; ratio = Y / mean of its class. Pixels the image shows as water hold
ratio 1 (land cells of the land cover there take their class's mean).
Value = round(32 ratio), clipped to 1..255 (ratio 1/32 to 7.97), value_scale
1/32.
"""
import argparse
import os
import sys

import numpy as np
from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import eoir_raster as er  # noqa: E402
from make_earth_rasters import classify_image  # noqa: E402

SCALE = 32
SOURCE = ("land brightness: relative luminance of Debian xplanet-images 1.3.1 earth.jpg (NASA Blue Marble, "
          "Visible Earth 11612, not copyrighted) over the area-weighted mean of its IGBP class (classes of "
          "data/earth/make_earth_rasters.py); data/earth/make_land_brightness.py")


def srgb_to_linear(v):
    v = v / 255.0
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def brightness_ratio(image):
    """(ratio[H, W], classes[H, W], image_water[H, W])."""
    rgb = srgb_to_linear(np.asarray(Image.open(image).convert("RGB")).astype(np.float64))
    y = 0.2126 * rgb[..., 0] + 0.7152 * rgb[..., 1] + 0.0722 * rgb[..., 2]
    classes, water = classify_image(image)
    h, w = y.shape
    weight = np.cos(np.deg2rad(90 - (np.arange(h) + 0.5) * 180.0 / h))[:, None] * np.ones((1, w))
    ratio = np.ones_like(y)
    land = ~water
    for c in np.unique(classes[land]):
        sel = land & (classes == c)
        mean = (y[sel] * weight[sel]).sum() / weight[sel].sum()
        ratio[sel] = y[sel] / mean
    return ratio, classes, water


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--image", default="/usr/share/xplanet/images/earth.jpg")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    ratio, _, _ = brightness_ratio(a.image)
    h, w = ratio.shape
    np.clip(np.round(SCALE * ratio), 1, 255).astype(np.uint8).tofile(os.path.join(a.out, "land_brightness_L0.u8"))
    hdr = er.header(source=SOURCE, width=w, height=h, lon_west_deg=-180.0, lat_north_deg=90.0,
                    cell_deg=360.0 / w, encoding="uint8", classes={}, file="land_brightness_L0.u8", body="Earth",
                    cells_per_degree=0, value_scale=1.0 / SCALE, value_offset=0.0,
                    quantity="reflectance scale of the land-cover class",
                    datum="WGS84 geodetic latitude, longitude east of Greenwich")
    er.write_header(os.path.join(a.out, "land_brightness_L0.json"), hdr)
    print(f"land brightness written to {a.out}: ratio 5-95 % {np.percentile(ratio, 5):.2f}-"
          f"{np.percentile(ratio, 95):.2f}")


if __name__ == "__main__":
    main()
