#!/usr/bin/env python3
"""Builds the Earth land/water mask and land-cover pyramid (eoir-raster v1).

Sources (Debian packages, read at build time only):
  * GSHHG 2.3.7 shorelines, "high" resolution (Debian gmt-gshhg-high), through
    GMT 6.4 `gmt grdlandmask` (Debian gmt): Wessel, P. and W. H. F. Smith
    (1996), A Global Self-consistent, Hierarchical, High-resolution Shoreline
    Database, J. Geophys. Res. 101(B4), 8741-8743. Levels: ocean = water,
    land = land, lake = water, island in lake = land, pond = water.
    Antarctica uses the GSHHG ice-front line (ice shelves are land).
  * The Earth image of Debian xplanet-images 1.3.1
    (/usr/share/xplanet/images/earth.jpg, 2048x1024 plate carree, NASA Visible
    Earth "Blue Marble" record 11612, R. Stockli et al., NASA Earth
    Observatory, MODIS 2001 composite), classified by colour and latitude into
    IGBP classes (rules in classify_image below and in README.md).

Outputs (in --out): landmask_L{0,1,2}.json + data, landcover_L{0,1,2}.json +
data, earth_rasters.json (the pyramid index). See data/earth/README.md.

Levels:  L0 1/4 deg (1440x720, raw uint8), L1 1/30 deg (10800x5400, rle),
L2 1/120 deg = 30 arcsec (43200x21600, rle; 0.926 km at the equator).
L2 is GSHHG at cell centres; L1 and L0 are the majority (land if at least half
of the L2 cells of the block are land) of L2.
"""
import argparse
import concurrent.futures as cf
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import eoir_raster as er  # noqa: E402

IGBP = {
    1: "Evergreen Needleleaf Forest", 2: "Evergreen Broadleaf Forest",
    3: "Deciduous Needleleaf Forest", 4: "Deciduous Broadleaf Forest",
    5: "Mixed Forest", 6: "Closed Shrubland", 7: "Open Shrubland",
    8: "Woody Savannas", 9: "Savannas", 10: "Grasslands",
    11: "Permanent Wetlands", 12: "Croplands", 13: "Urban and Built-Up",
    14: "Cropland/Natural Vegetation Mosaic", 15: "Snow and Ice",
    16: "Barren", 17: "Water Bodies", 18: "Tundra",
}
WATER = 17
MASK_CLASSES = {"0": "water (GSHHG ocean, lake, pond)", "1": "land (GSHHG land, island in lake, Antarctic ice shelf)"}

FINE_PER_DEG = 120          # L2: 30 arcsec
BAND_DEG = 15               # grdlandmask is run in latitude bands of this height
LEVELS = [  # name, cells per degree, encoding
    ("L0", 4, "uint8"),
    ("L1", 30, "uint8-rle"),
    ("L2", 120, "uint8-rle"),
]

GSHHG_SRC = ("GSHHG 2.3.7 (Wessel & Smith 1996), {res} resolution shorelines of Debian "
             "gmt-gshhg-{res}, rasterised with GMT 6.4 grdlandmask -r -D{r} -N0/1/0/1/0 "
             "at cell centres (30 arcsec)")


# --------------------------------------------------------------------------
# Land cover from the xplanet Blue Marble image
# --------------------------------------------------------------------------
def classify_image(path):
    """Returns (classes[1024, 2048] uint8 with every pixel a land class 1..18,
    image_water[1024, 2048] bool). Pixel (r, c) covers lon -180 + c*360/W ..,
    lat 90 - r*180/H ..; the image is plate carree centred on Greenwich."""
    rgb = np.asarray(Image.open(path).convert("RGB")).astype(np.float32)
    H, W, _ = rgb.shape
    R, G, B = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    mn = rgb.min(axis=2)
    # Water in the image (deep navy and shallow cyan): blue dominant, not white.
    water = (B > R + 5) & (B >= G - 5) & ~(mn > 170)
    land = ~water
    # 3x3 mean of the land pixels (JPEG noise), longitude wrapped.
    acc = np.zeros_like(rgb)
    cnt = np.zeros((H, W), np.float32)
    w = land.astype(np.float32)
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            rs = np.clip(np.arange(H) + dr, 0, H - 1)
            acc += np.roll(rgb * w[..., None], -dc, axis=1)[rs]
            cnt += np.roll(w, -dc, axis=1)[rs]
    sm = acc / np.maximum(cnt, 1)[..., None]
    R, G, B = sm[..., 0], sm[..., 1], sm[..., 2]
    V = sm.max(axis=2)
    mn = sm.min(axis=2)
    S = (V - mn) / np.maximum(V, 1)
    gr = G / np.maximum(R, 1)
    br = B / np.maximum(R, 1)
    lat = (90 - (np.arange(H) + 0.5) * 180.0 / H)[:, None] * np.ones((1, W))
    lon = (-180 + (np.arange(W) + 0.5) * 360.0 / W)[None, :] * np.ones((H, 1))
    alat = np.abs(lat)
    tropics = alat < 23.5
    larch = (lon >= 100) & (lon <= 170) & (lat >= 50) & (lat <= 72)

    cls = np.zeros((H, W), np.uint8)

    def put(cond, value):
        sel = (cls == 0) & cond
        cls[sel] = value

    put(lat < -60, 15)                                   # Antarctica: ice sheet
    put((mn > 190) & (S < 0.2) & (br >= 0.93), 15)       # neutral white: ice caps, glaciers
    put(V >= 200, 16)                                    # bright sand: barren
    boreal_forest = (br < 0.40) & (gr >= 1.10)
    put((lat >= 60) & boreal_forest & larch, 3)          # east Siberian larch
    put((lat >= 60) & boreal_forest, 1)                  # boreal forest
    put(lat >= 60, 18)                                   # north of the tree line
    forest = (gr >= 1.25) & (br < 0.35) & (V < 110)      # dark saturated green
    put(forest & tropics, 2)
    put(forest & (lat >= 50) & larch, 3)
    put(forest & (lat >= 50), 1)
    put(forest & (lat >= 23.5), 5)
    put(forest & (lat <= -23.5), 2)                      # southern temperate evergreen
    put(gr < 0.80, 7)                                    # red arid: open shrubland
    put((V >= 165) & (br >= 0.63), 16)                   # pale desert
    put(V >= 165, 7)
    # Colour alone from here: a latitude cut (the tropics' savannas against
    # grassland and cropland, dry shrubland within 35 deg) left straight
    # seams where classes of unlike materials met (issue 20 item 7).
    put(gr >= 1.15, 12)                                  # green: croplands
    put(gr >= 0.95, 10)                                  # olive: grasslands
    put(V >= 130, 7)                                     # brown, dry: open shrubland
    put(np.ones_like(tropics), 10)
    assert (cls > 0).all()

    # Pixels that the image shows as water take the class of the nearest
    # image-land pixel (GSHHG, not the image, decides where water is).
    filled = land.copy()
    out = np.where(filled, cls, 0).astype(np.uint8)
    while not filled.all():
        for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            rs = np.clip(np.arange(H) - dr, 0, H - 1)
            nb_f = np.roll(filled, dc, axis=1)[rs]
            nb_v = np.roll(out, dc, axis=1)[rs]
            take = ~filled & nb_f
            out[take] = nb_v[take]
            filled = filled | take
    return out, water


def lookup(img_cls, lat_c, lon_c):
    """Image classes at cell centres (1-D lat, 1-D lon arrays) -> 2-D array."""
    H, W = img_cls.shape
    ri = np.clip(np.floor((90.0 - lat_c) / 180.0 * H).astype(np.int64), 0, H - 1)
    ci = np.floor((lon_c + 180.0) / 360.0 * W).astype(np.int64) % W
    return img_cls[ri[:, None], ci[None, :]]


# --------------------------------------------------------------------------
# GSHHG through GMT
# --------------------------------------------------------------------------
def landmask_band(lat_south, lat_north, res, tmpdir, gmt="gmt"):
    w = 360 * FINE_PER_DEG
    h = (lat_north - lat_south) * FINE_PER_DEG
    out = os.path.join(tmpdir, f"band_{lat_south:+03d}.bin")
    cmd = [gmt, "grdlandmask", f"-R-180/180/{lat_south}/{lat_north}",
           f"-I{3600 // FINE_PER_DEG}s", "-r", f"-D{res[0]}", "-N0/1/0/1/0",
           f"-G{out}=bb"]
    subprocess.run(cmd, check=True, cwd=tmpdir,
                   env=dict(os.environ, GMT_USERDIR=tmpdir, GMT_TMPDIR=tmpdir))
    raw = np.fromfile(out, dtype=np.uint8)
    os.remove(out)
    hdr = raw.size - w * h  # GMT native binary grid header (892 bytes)
    assert hdr in (892,), hdr
    return raw[hdr:].reshape(h, w)  # GMT stores the north row first


def block_majority(mask, k):
    h, w = mask.shape
    s = mask.reshape(h // k, k, w // k, k).sum(axis=(1, 3), dtype=np.int32)
    return (2 * s >= k * k).astype(np.uint8)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--image", default="/usr/share/xplanet/images/earth.jpg")
    ap.add_argument("--gshhg", default="high", choices=["low", "intermediate", "high", "full"])
    ap.add_argument("--gmt", default="gmt", help="the gmt executable")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    t0 = time.time()

    img_cls, _ = classify_image(a.image)
    src_mask = GSHHG_SRC.format(res=a.gshhg, r=a.gshhg[0])
    src_cover = ("land: IGBP class from the colour and latitude of Debian xplanet-images "
                 "1.3.1 earth.jpg (NASA Blue Marble 2002, 2048x1024 plate carree, nearest "
                 "pixel to the cell centre; rules in data/earth/README.md); water (17): "
                 + src_mask)

    fine_w, fine_h = 360 * FINE_PER_DEG, 180 * FINE_PER_DEG
    names = {}
    writers = {}
    for kind in ("landmask", "landcover"):
        p = os.path.join(a.out, f"{kind}_L2.rle")
        writers[kind] = er.RleWriter(p, fine_w, fine_h)
    coarse_mask = {lvl: [] for lvl, _, _ in LEVELS[:2]}
    fine_lon = -180 + (np.arange(fine_w) + 0.5) / FINE_PER_DEG

    bands = [(n - BAND_DEG, n) for n in range(90, -90, -BAND_DEG)]
    with tempfile.TemporaryDirectory() as tmp, cf.ThreadPoolExecutor(a.jobs) as pool:
        futs = [pool.submit(landmask_band, s, n, a.gshhg, tmp, a.gmt) for s, n in bands]
        for (s, n), fut in zip(bands, futs):
            m = fut.result()
            lat_c = n - (np.arange(m.shape[0]) + 0.5) / FINE_PER_DEG
            cover = np.where(m == 1, lookup(img_cls, lat_c, fine_lon), WATER).astype(np.uint8)
            writers["landmask"].add_block(m)
            writers["landcover"].add_block(cover)
            for lvl, per_deg, _ in LEVELS[:2]:
                coarse_mask[lvl].append(block_majority(m, FINE_PER_DEG // per_deg))
            print(f"band {n:+d}..{s:+d} done at {time.time() - t0:.0f} s", flush=True)
    for w in writers.values():
        w.close()

    index = {"format": "eoir-raster-pyramid", "version": 1, "body": "Earth",
             "levels": []}
    for lvl, per_deg, enc in LEVELS:
        cell = 1.0 / per_deg
        w, h = 360 * per_deg, 180 * per_deg
        ext = "u8" if enc == "uint8" else "rle"
        if lvl != "L2":
            m = np.concatenate(coarse_mask[lvl])
            lat_c = 90 - (np.arange(h) + 0.5) * cell
            lon_c = -180 + (np.arange(w) + 0.5) * cell
            cover = np.where(m == 1, lookup(img_cls, lat_c, lon_c), WATER).astype(np.uint8)
            for kind, arr in (("landmask", m), ("landcover", cover)):
                p = os.path.join(a.out, f"{kind}_{lvl}.{ext}")
                if enc == "uint8":
                    arr.tofile(p)
                else:
                    wr = er.RleWriter(p, w, h)
                    wr.add_block(arr)
                    wr.close()
        rule = ("GSHHG land/water at the cell centre" if lvl == "L2" else
                "majority of the 30-arcsec cells of the block (land if >= 1/2 land)")
        level_entry = {"level": lvl, "cell_deg": cell, "cells_per_degree": per_deg,
                       "cell_km_equator": round(cell * 111.32, 3), "encoding": enc}
        for kind, classes, src in (
                ("landmask", MASK_CLASSES, src_mask + "; " + rule),
                ("landcover", {str(k): v for k, v in IGBP.items()}, src_cover + "; land/water: " + rule)):
            fn = f"{kind}_{lvl}.{ext}"
            hdr = er.header(source=src, width=w, height=h, lon_west_deg=-180.0,
                            lat_north_deg=90.0, cell_deg=cell, encoding=enc,
                            classes=classes, file=fn, body="Earth", cells_per_degree=per_deg,
                            datum="WGS84 geodetic latitude, longitude east of Greenwich")
            er.write_header(os.path.join(a.out, f"{kind}_{lvl}.json"), hdr)
            level_entry[kind] = f"{kind}_{lvl}.json"
        index["levels"].append(level_entry)
    er.write_header(os.path.join(a.out, "earth_rasters.json"), index)
    print(f"earth rasters written to {a.out} in {time.time() - t0:.0f} s")


if __name__ == "__main__":
    main()
