#!/usr/bin/env python3
"""Builds the Earth's cloud-fraction map (eoir-raster v1, uint8, 512 x 256).

Sources (Debian packages, read at build time only):
  * stellarium-data 0.22.2: /usr/share/stellarium/textures/earth-clouds.png,
    512 x 256 plate carree, the Earth with clouds ("includes imagery owned by
    NASA", Visible Earth, free of licensing fees with credit to NASA; "the
    cloud texturing was taken from Celestia (GPL)":
    /usr/share/doc/stellarium-data/copyright, section 4.13).
  * xplanet-images 1.3.1: /usr/share/xplanet/images/earth.jpg, the cloud-free
    NASA Blue Marble (Visible Earth record 11612, not copyrighted), 2048 x
    1024 plate carree on the same registration (-180 deg at the west edge).

The cloudy texture is the clear surface with white cloud composited over it
in its encoded (sRGB) values, C = (1 - f) S + f W. Per 0.7-deg pixel, f is the
least-squares solution over R, G, B, with S the Blue Marble averaged over the
4 x 4 of its pixels in that pixel and W the texture's white (its 99.5th
percentile of grey), clipped to [0, 1]; where the clear surface is itself
near white (ice sheets, |W - S|^2 < 0.05 W^2), clouds cannot be told from it
and f = 0 (the surface beneath is white anyway). Value = round(255 f),
value_scale 1/255. See data/earth/README.md ("Clouds").
"""
import argparse
import os
import sys

import numpy as np
from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import eoir_raster as er  # noqa: E402

SOURCE = ("cloud fraction retrieved from Debian stellarium-data 0.22.2 textures/earth-clouds.png (NASA Visible "
          "Earth imagery with Celestia cloud texturing; copyright file section 4.13: free of licensing fees, "
          "credit to NASA) against the cloud-free Blue Marble of Debian xplanet-images 1.3.1 earth.jpg (NASA "
          "Visible Earth 11612, not copyrighted); data/earth/make_cloud_map.py")


def cloud_fraction(cloudy_png, clear_jpg):
    """f[256, 512] in [0, 1] (rows north to south, -180 deg at column 0's west edge)."""
    c = np.asarray(Image.open(cloudy_png).convert("RGB")).astype(np.float64) / 255.0
    h, w, _ = c.shape
    s = np.asarray(Image.open(clear_jpg).convert("RGB")).astype(np.float64) / 255.0
    k = s.shape[0] // h
    assert s.shape[0] == k * h and s.shape[1] == k * w, (s.shape, c.shape)
    s = s.reshape(h, k, w, k, 3).mean(axis=(1, 3))
    white = np.percentile(c.mean(axis=2), 99.5)
    d = white - s
    den = (d * d).sum(axis=2)
    f = ((c - s) * d).sum(axis=2) / np.maximum(den, 1e-12)
    f = np.clip(f, 0.0, 1.0)
    f[den < 0.05 * white * white] = 0.0
    return f


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--clouds", default="/usr/share/stellarium/textures/earth-clouds.png")
    ap.add_argument("--image", default="/usr/share/xplanet/images/earth.jpg")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    f = cloud_fraction(a.clouds, a.image)
    h, w = f.shape
    np.round(255.0 * f).astype(np.uint8).tofile(os.path.join(a.out, "clouds_L0.u8"))
    hdr = er.header(source=SOURCE, width=w, height=h, lon_west_deg=-180.0, lat_north_deg=90.0,
                    cell_deg=360.0 / w, encoding="uint8", classes={}, file="clouds_L0.u8", body="Earth",
                    cells_per_degree=0, value_scale=1.0 / 255.0, value_offset=0.0, quantity="cloud_fraction",
                    datum="WGS84 geodetic latitude, longitude east of Greenwich")
    er.write_header(os.path.join(a.out, "clouds_L0.json"), hdr)
    print(f"cloud map written to {a.out}: mean fraction {f.mean():.3f}")


if __name__ == "__main__":
    main()
