#!/usr/bin/env python3
"""Moon and Mars normal-albedo maps (eoir-raster v1, value = albedo / scale).

Sources (Debian stellarium-data 0.22.2-1, read at build time only):
  * Moon: /usr/share/stellarium/textures/moon_4k.jpg, 4096x2048 grey, the
    texture Stellarium's ssystem_major.ini assigns to [moon]. Stellarium's
    credits (CREDITS.md, 4.4): combined from USGS Astrogeology maps and
    Celestia lunar textures based on Clementine data (public domain).
  * Mars: /usr/share/stellarium/textures/mars.png, 512x256 RGB; credits 4.5m:
    from David Seal's site maps.jpl.nasa.gov.
  Both are plate carree, north up, the left edge at longitude 180 W, the
  centre on the prime meridian, east longitude increasing to the right
  (checked on the image: Tycho at 43.3 S 11.2 W, Mare Crisium at 17 N 59 E;
  Olympus Mons at 18.7 N 133.8 W, Syrtis Major at 9 N 69 E, Hellas at 42 S
  70 E all fall in the expected cells).

Method: albedo is taken proportional to the pixel luminance (Rec. 709 weights
for Mars, the grey level for the Moon), with no gamma removal (the texture's
mare/highland contrast of about 2 matches the measured one; a gamma of 2.2
would make it about 5), and scaled to the geometric albedo of the NSSDC fact
sheets (D. R. Williams, NASA NSSDC, Moon Fact Sheet: 0.12; Mars Fact Sheet:
0.170; Stellarium's ssystem_major.ini uses 0.12 and 0.150). Mars: the
area-weighted (cos latitude) mean. The Moon: the mean over the full near-side
disc seen from the mean sub-Earth point (weights cos^2(lat) cos(lon), |lon| <
90 deg), because the engine's lunar surface is a Lommel-Seeliger one
(engine/radiometry/disk_photometry.hpp) whose full disc is uniform, I/F =
normal albedo, so this mean is the disc's geometric albedo (issue 21: the
albedo map normalised to the photometric model). Topographic shading baked into the
textures remains; the polar caps of the lunar texture above about 80 degrees
are smooth fill.
"""
import argparse
import json
import os

import numpy as np
from PIL import Image

SCALE = 0.002  # albedo = value * SCALE (0 .. 0.51)
BODIES = {
    "moon": dict(
        image="/usr/share/stellarium/textures/moon_4k.jpg", mean=0.12, body="Moon", weighting="near_side_disc",
        mean_src="geometric albedo 0.12 (NASA NSSDC Moon Fact Sheet, D. R. Williams) as the mean over the "
                 "near-side disc (weights cos^2 lat cos lon) of the lunar Lommel-Seeliger surface",
        tex_src="Debian stellarium-data 0.22.2-1, textures/moon_4k.jpg (USGS Astrogeology + "
                "Celestia/Clementine, public domain)",
        lon="selenographic (mean-Earth/polar-axis) longitude, east positive, 0 = mean sub-Earth meridian",
        levels=[("L0", 4), ("L1", 1)]),
    "mars": dict(
        image="/usr/share/stellarium/textures/mars.png", mean=0.170, body="Mars", weighting="area",
        mean_src="geometric albedo 0.170 (NASA NSSDC Mars Fact Sheet, D. R. Williams)",
        tex_src="Debian stellarium-data 0.22.2-1, textures/mars.png (from maps.jpl.nasa.gov, D. Seal)",
        lon="planetocentric east longitude (IAU), 0 = Airy-0 meridian",
        levels=[("L0", 1)]),
}


def luminance(path):
    im = Image.open(path)
    if im.mode in ("L", "I", "F"):
        return np.asarray(im.convert("F"), dtype=np.float64)
    rgb = np.asarray(im.convert("RGB"), dtype=np.float64)
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def area_mean(a):
    h = a.shape[0]
    lat = 90 - (np.arange(h) + 0.5) * 180.0 / h
    w = np.cos(np.radians(lat))[:, None]
    return float((a * w).sum() / (w.sum() * a.shape[1]))


def near_side_disc_mean(a):
    """Mean over the disc seen from above (lat 0, lon 0): each cell weighted
    by its area (cos lat) times its projected cosine (cos lat cos lon)."""
    h, w = a.shape
    lat = np.radians(90 - (np.arange(h) + 0.5) * 180.0 / h)[:, None]
    lon = np.radians(-180 + (np.arange(w) + 0.5) * 360.0 / w)[None, :]
    wt = np.cos(lat) ** 2 * np.clip(np.cos(lon), 0, None)
    return float((a * wt).sum() / wt.sum())


MEANS = {"area": area_mean, "near_side_disc": near_side_disc_mean}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    for name, b in BODIES.items():
        lum = luminance(b["image"])
        mean = MEANS[b["weighting"]]
        alb = lum * (b["mean"] / mean(lum))
        for lvl, k in b["levels"]:
            h, w = alb.shape[0] // k, alb.shape[1] // k
            blk = alb.reshape(h, k, w, k).mean(axis=(1, 3))
            q = np.clip(np.rint(blk / SCALE), 0, 255).astype(np.uint8)
            fn = f"{name}_albedo_{lvl}.u8"
            q.tofile(os.path.join(a.out, fn))
            hdr = {
                "format": "eoir-raster", "version": 1,
                "source": (f"{b['tex_src']}; luminance scaled to an area-weighted mean of {b['mean_src']}"
                           + (f"; {k}x{k} block mean" if k > 1 else "")),
                "width": w, "height": h, "lon_west_deg": -180.0, "lat_north_deg": 90.0,
                "cell_deg": 360.0 / w, "registration": "cell", "row_order": "north_to_south",
                "encoding": "uint8", "classes": {},
                "quantity": "normal_albedo_visible", "value_scale": SCALE, "value_offset": 0.0,
                "mean_value": round(area_mean(q * SCALE), 4),
                "near_side_disc_mean": round(near_side_disc_mean(q * SCALE), 4),
                "file": fn, "body": b["body"], "longitude": b["lon"],
            }
            with open(os.path.join(a.out, f"{name}_albedo_{lvl}.json"), "w") as f:
                json.dump(hdr, f, indent=1)
                f.write("\n")
            print(f"{name} {lvl}: {w}x{h}, cell {360.0 / w:.6f} deg, mean albedo {hdr['mean_value']}, "
                  f"near-side disc {hdr['near_side_disc_mean']}")


if __name__ == "__main__":
    main()
