#!/usr/bin/env python3
"""Build the engine's star catalogue (format v2, data/stars/README.md) from two
Debian packages:

  * kstars-data: /usr/share/kstars/stars.dat, KStars' Hipparcos/Tycho text
    catalogue to V = 8.99 (parsed by convert_kstars.py): every star of it,
    with V and B-V to 0.01 mag, proper motion, parallax, spectral type, names.
  * stellarium-data: /usr/share/stellarium/stars/default/stars_<n>_<t>v<M>_<m>.cat,
    Stellarium's binary catalogues of Hipparcos (type 0) and Tycho-2 (type 1)
    stars to V = 10.5 (Stellarium credits: ESA 1997 Hipparcos; Hog et al.
    2000 Tycho-2; NOMAD): the stars of V >= 9.0 that KStars' file does not
    hold (none within 2" of a KStars star), with V and B-V quantised by the
    files to 0.05 and 0.031 mag.

Stellarium's format, as its loader reads it (src/core/modules/ZoneArray.cpp,
Star.hpp, src/core/StelGeodesicGrid.cpp of Stellarium 0.22, read, not copied):
eight little-endian uint32 (magic 0x835f040a, type, major, minor, level,
mag_min [mmag, signed], mag_range [mmag], mag_steps), the star count of each
of the 20 4^level zones (the triangles of an icosahedron subdivided `level`
times), then the stars zone by zone, brightest first. A star's J2000
direction is centre + (x0 a0 + x1 a1) s, normalised: centre the normalised sum
of the zone's corners, a0 = north x centre (normalised), a1 = centre x a0, s the
largest |mu| / sqrt(1 - mu0^2 - mu1^2) of the level's corners over the type's
largest integer. Type 0 (28 bytes): int24 HIP, uint8 component, int32 x0, x1,
uint8 B-V index, uint8 magnitude index, uint16 spectral index, int32 dx0, dx1,
parallax [0.01 mas]. Type 1 (10 bytes, bit fields from the least significant
bit): x0:20, x1:20, dx0:14, dx1:14 (signed), B-V index:7, magnitude index:5.
V = (mag_min + index mag_range / mag_steps) / 1000; B-V = index 4/127 - 0.5.
dx0, dx1 are the proper motion's mu_alpha* and mu_delta in 0.1 mas/yr (checked
against KStars' Hipparcos values: median difference 1.3 mas/yr for the 20,352
stars of stars_1 that match, against 2.0 mas/yr read along the zone's axes).
Checked: the decoded places of Sirius, Canopus and Vega are their J2000 places
to 0.01"; the Tycho stars of stars_3 match the 176,043 Tycho-2 stars of
astrometry.net's index-tycho2-10 (Debian astrometry-data-tycho2-10-19) that
fall within 3" at a median of 0.018" (V - VT: -0.10 median, as V = VT -
0.09 (BT - VT) expects).

Output: stars sorted by sky cell (1-degree declination bands, each cut into
max(1, round(360 cos(dec_mid))) equal cells of right ascension: 41,2xx cells
of about one square degree) and by V within a cell; a cell's stars are one
run of records, found through the cell start table. Ids: "HIP<n>" for
Hipparcos stars of Stellarium's files, "HT<n>" otherwise (n the star's rank
in V over the catalogue). The header also holds the cumulative V = 0
equivalent flux of the catalogue per 0.1 mag (integrated starlight of the
stars brighter than a limit, spec 4.1.4).

Usage: build_catalogue.py KSTARS_STARS_DAT STELLARIUM_STAR_DIR OUTPUT
"""
import argparse
import hashlib
import math
import os
import struct
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import convert_kstars  # noqa: E402

MAGIC = b"EOIRSTAR"
FORMAT_VERSION = 2
RECORD = np.dtype([("ra", "<f8"), ("dec", "<f8"), ("pm_ra", "<f4"), ("pm_dec", "<f4"), ("plx", "<f4"),
                   ("v", "<f4"), ("bv", "<f4"), ("sp", "S2"), ("flags", "u1"), ("reserved", "u1"),
                   ("number", "<u4"), ("name", "<u4")])
assert RECORD.itemsize == 48
FIXED_HEADER = struct.Struct("<8sIIIIdddIIIIddI")  # 84 bytes (see README.md)
NO_NAME = 0xFFFFFFFF
FLAG_MULTIPLE, FLAG_VARIABLE, FLAG_HIPPARCOS = 1, 2, 4
EPOCH_JULIAN_YEAR = 2000.0
BAND_DEG = 1.0
FLUX_STEP_MAG = 0.1
FLUX_FIRST_MAG = -2.0
FLUX_STEPS = 141  # -2.0 .. 12.0
V_LIMIT = 10.5  # Stellarium's Tycho file (stars_3) stops here

STELLARIUM_MAGIC = 0x835F040A
KSTARS_MATCH_ARCSEC = 2.0


def package_version(package):
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package], check=True, capture_output=True,
                             text=True)
        return out.stdout.strip() or "unknown"
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


# ---- Stellarium's geodesic zones -------------------------------------------------------------------

_G = 0.5 * (1 + math.sqrt(5))
_B = 1 / math.sqrt(1 + _G * _G)
_A = _B * _G
ICOSAHEDRON = np.array([[_A, -_B, 0], [_A, _B, 0], [-_A, _B, 0], [-_A, -_B, 0], [0, _A, -_B], [0, _A, _B],
                        [0, -_A, _B], [0, -_A, -_B], [-_B, 0, _A], [_B, 0, _A], [_B, 0, -_A], [-_B, 0, -_A]])
FACES = [(1, 0, 10), (0, 1, 9), (0, 9, 6), (9, 8, 6), (0, 7, 10), (6, 7, 0), (7, 6, 3), (6, 8, 3), (11, 10, 7),
         (7, 3, 11), (3, 2, 11), (2, 3, 8), (10, 11, 4), (2, 4, 11), (5, 4, 2), (2, 8, 5), (4, 1, 10), (4, 5, 1),
         (5, 9, 1), (8, 9, 5)]


def _unit(v):
    return v / np.linalg.norm(v)


def zone_triangles(level):
    """The zones of a level in Stellarium's order: face i's children are
    4i .. 4i+3 = (c0, e2, e1), (e2, c1, e0), (e1, e0, c2), (e0, e1, e2), e_k the
    normalised midpoint of the edge opposite corner k."""
    tris = [(ICOSAHEDRON[a], ICOSAHEDRON[b], ICOSAHEDRON[c]) for a, b, c in FACES]
    for _ in range(level):
        finer = []
        for c0, c1, c2 in tris:
            e0, e1, e2 = _unit(c1 + c2), _unit(c2 + c0), _unit(c0 + c1)
            finer += [(c0, e2, e1), (e2, c1, e0), (e1, e0, c2), (e0, e1, e2)]
        tris = finer
    return tris


def zone_frames(level, max_position_value):
    north = np.array([0.0, 0.0, 1.0])
    centres, axes0, axes1, scale = [], [], [], 0.0
    for corners in zone_triangles(level):
        c = _unit(corners[0] + corners[1] + corners[2])
        a0 = _unit(np.cross(north, c))
        a1 = np.cross(c, a0)
        for v in corners:
            m0, m1 = (v - c) @ a0, (v - c) @ a1
            f = 1 / math.sqrt(1 - m0 * m0 - m1 * m1)
            scale = max(scale, abs(m0) * f, abs(m1) * f)
        centres.append(c)
        axes0.append(a0)
        axes1.append(a1)
    return np.array(centres), np.array(axes0), np.array(axes1), scale / max_position_value


def _bits(lo, hi, start, width, signed):
    """Bits start .. start+width-1 of the 80-bit little-endian words (lo: bytes 0-7, hi: bytes 8-9)."""
    if start + width <= 64:
        v = (lo >> np.uint64(start)) & np.uint64((1 << width) - 1)
    elif start >= 64:
        v = (hi >> np.uint64(start - 64)) & np.uint64((1 << width) - 1)
    else:
        low_width = 64 - start
        v = (lo >> np.uint64(start)) | ((hi & np.uint64((1 << (width - low_width)) - 1)) << np.uint64(low_width))
    v = v.astype(np.int64)
    if signed:
        v = np.where(v >= (1 << (width - 1)), v - (1 << width), v)
    return v


def read_stellarium(path):
    data = open(path, "rb").read()
    if len(data) < 32:
        sys.exit(f"{path}: shorter than Stellarium's 32-byte header")
    magic, kind, _major, _minor, level, _mag_min, mag_range, mag_steps = struct.unpack("<8I", data[:32])
    mag_min = struct.unpack("<i", data[20:24])[0]
    if magic != STELLARIUM_MAGIC:
        sys.exit(f"{path}: magic {magic:#x}, not a little-endian Stellarium star catalogue")
    if kind not in (0, 1) or level > 8 or mag_steps == 0:
        sys.exit(f"{path}: type {kind}, level {level}: not a Hipparcos (0) or Tycho (1) catalogue")
    zones = 20 * 4 ** level
    sizes = np.frombuffer(data, dtype="<u4", count=zones, offset=32)
    offset = 32 + 4 * zones
    record = 28 if kind == 0 else 10
    n = int(sizes.sum())
    if offset + record * n != len(data):
        sys.exit(f"{path}: {n} stars of {record} bytes do not fill the file")
    raw = np.frombuffer(data, dtype=np.uint8, count=record * n, offset=offset).reshape(n, record)
    zone = np.repeat(np.arange(zones), sizes)
    if kind == 0:
        hip = raw[:, 0].astype(np.int64) | (raw[:, 1].astype(np.int64) << 8) | (raw[:, 2].astype(np.int64) << 16)
        x0 = raw[:, 4:8].copy().view("<i4")[:, 0].astype(np.float64)
        x1 = raw[:, 8:12].copy().view("<i4")[:, 0].astype(np.float64)
        bv_index = raw[:, 12].astype(np.int64)
        mag_index = raw[:, 13].astype(np.int64)
        dx0 = raw[:, 16:20].copy().view("<i4")[:, 0].astype(np.float64)
        dx1 = raw[:, 20:24].copy().view("<i4")[:, 0].astype(np.float64)
        plx = raw[:, 24:28].copy().view("<i4")[:, 0].astype(np.float64) * 0.01
        max_position = 0x7FFFFFFF
    else:
        lo = raw[:, :8].copy().view("<u8")[:, 0]
        hi = raw[:, 8:10].copy().view("<u2")[:, 0].astype(np.uint64)
        x0 = _bits(lo, hi, 0, 20, True).astype(np.float64)
        x1 = _bits(lo, hi, 20, 20, True).astype(np.float64)
        dx0 = _bits(lo, hi, 40, 14, True).astype(np.float64)
        dx1 = _bits(lo, hi, 54, 14, True).astype(np.float64)
        bv_index = _bits(lo, hi, 68, 7, False)
        mag_index = _bits(lo, hi, 75, 5, False)
        hip = np.zeros(n, dtype=np.int64)
        plx = np.zeros(n)
        max_position = (1 << 19) - 1
    centre, axis0, axis1, scale = zone_frames(level, max_position)
    p = centre[zone] + (x0 * scale)[:, None] * axis0[zone] + (x1 * scale)[:, None] * axis1[zone]
    p /= np.linalg.norm(p, axis=1)[:, None]
    return dict(p=p, v=(mag_min + mag_index * mag_range / mag_steps) / 1000.0, bv=bv_index * 4.0 / 127.0 - 0.5,
                pm_ra=dx0 * 0.1, pm_dec=dx1 * 0.1, plx=plx, hip=hip, source=path)


# ---- sky cells -----------------------------------------------------------------------------------

def band_cells():
    """Cells per 1-degree declination band, south to north."""
    mids = -90.0 + BAND_DEG * (np.arange(int(180 / BAND_DEG)) + 0.5)
    return np.maximum(1, np.rint(360.0 * np.cos(np.radians(mids)))).astype(np.int64)


def cell_of(ra_rad, dec_rad, cells):
    first = np.concatenate([[0], np.cumsum(cells)[:-1]])
    band = np.clip(np.floor((np.degrees(dec_rad) + 90.0) / BAND_DEG).astype(np.int64), 0, len(cells) - 1)
    n = cells[band]
    k = np.minimum(np.floor(np.degrees(ra_rad) / 360.0 * n).astype(np.int64), n - 1)
    return first[band] + k


# ---- the catalogue -------------------------------------------------------------------------------

def unit_vectors(ra, dec):
    return np.stack([np.cos(dec) * np.cos(ra), np.cos(dec) * np.sin(ra), np.sin(dec)], 1)


def near_any(p, q, radius_arcsec):
    """For each row of p, whether some row of q lies within radius (sorted declination sweep)."""
    w = math.radians(radius_arcsec / 3600.0)
    cos_r = math.cos(w)
    qdec = np.arcsin(np.clip(q[:, 2], -1, 1))
    order = np.argsort(qdec)
    sorted_dec = qdec[order]
    pdec = np.arcsin(np.clip(p[:, 2], -1, 1))
    lo = np.searchsorted(sorted_dec, pdec - w)
    hi = np.searchsorted(sorted_dec, pdec + w)
    out = np.zeros(len(p), dtype=bool)
    for i in np.nonzero(hi > lo)[0]:
        out[i] = bool(np.any(q[order[lo[i]:hi[i]]] @ p[i] >= cos_r))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kstars")
    ap.add_argument("stellarium_dir")
    ap.add_argument("output")
    a = ap.parse_args()

    kstars = convert_kstars.parse(a.kstars)
    k_ra = np.array([s["ra"] for s in kstars])
    k_dec = np.array([s["dec"] for s in kstars])
    k_p = unit_vectors(k_ra, k_dec)
    faintest_kstars = max(s["v"] for s in kstars)

    files = sorted(f for f in os.listdir(a.stellarium_dir) if f.startswith("stars_") and f.endswith(".cat")
                   and f.split("_")[2][0] in "01")  # type 0 and 1 catalogues (not the hip_* tables)
    if not files:
        sys.exit(f"{a.stellarium_dir}: no stars_*.cat")
    digest = hashlib.sha256()
    with open(a.kstars, "rb") as f:
        digest.update(f.read())
    extra = []
    for name in files:
        path = os.path.join(a.stellarium_dir, name)
        with open(path, "rb") as f:
            digest.update(f.read())
        d = read_stellarium(path)
        # (quantised to 0.05: 9.00 is the first step past 8.99; the catalogue stops at 10.5, Tycho-2's
        # completeness, also for the few fainter Hipparcos stars of stars_2)
        keep = (d["v"] > faintest_kstars) & (d["v"] <= V_LIMIT + 1e-6)
        for key in ("p", "v", "bv", "pm_ra", "pm_dec", "plx", "hip"):
            d[key] = d[key][keep]
        d["keep"] = ~near_any(d["p"], k_p, KSTARS_MATCH_ARCSEC)
        extra.append(d)

    ra = [k_ra]
    dec = [k_dec]
    cols = {key: [np.array([s[src] for s in kstars], dtype=np.float64)] for key, src in
            (("pm_ra", "pm_ra"), ("pm_dec", "pm_dec"), ("plx", "plx"), ("v", "v"), ("bv", "bv"))}
    sp = [np.array([s["sp"][:2].ljust(2, b"?") for s in kstars], dtype="S2")]
    flags = [np.array([(FLAG_MULTIPLE if s["mult"] else 0) | (FLAG_VARIABLE if s["var"] else 0) for s in kstars],
                      dtype=np.uint8)]
    hip = [np.zeros(len(kstars), dtype=np.int64)]
    names = [s["names"] for s in kstars]
    for d in extra:
        k = d["keep"]
        p = d["p"][k]
        ra.append(np.mod(np.arctan2(p[:, 1], p[:, 0]), 2 * math.pi))
        dec.append(np.arcsin(np.clip(p[:, 2], -1, 1)))
        for key in cols:
            cols[key].append(d[key][k].astype(np.float64))
        sp.append(np.full(k.sum(), b"??", dtype="S2"))
        flags.append(np.where(d["hip"][k] > 0, FLAG_HIPPARCOS, 0).astype(np.uint8))
        hip.append(d["hip"][k])
        names += [""] * int(k.sum())
    ra = np.concatenate(ra)
    dec = np.concatenate(dec)
    for key in cols:
        cols[key] = np.concatenate(cols[key])
    sp = np.concatenate(sp)
    flags = np.concatenate(flags)
    hip = np.concatenate(hip)
    n = len(ra)

    # Ranks in V (ids HT<rank>), then the order of the file: by cell, V within a cell.
    rank = np.empty(n, dtype=np.int64)
    rank[np.argsort(cols["v"], kind="stable")] = np.arange(1, n + 1)
    cells = band_cells()
    cell = cell_of(ra, dec, cells)
    order = np.lexsort((cols["v"], cell))
    cell_count = int(cells.sum())
    starts = np.searchsorted(cell[order], np.arange(cell_count + 1)).astype("<u4")

    names_blob = bytearray()
    name_offset = np.full(n, NO_NAME, dtype=np.uint32)
    for i in order:
        if names[i]:
            name_offset[i] = len(names_blob)
            names_blob += names[i].encode("utf-8") + b"\0"

    records = np.zeros(n, dtype=RECORD)
    records["ra"], records["dec"] = ra[order], dec[order]
    records["pm_ra"], records["pm_dec"] = cols["pm_ra"][order], cols["pm_dec"][order]
    records["plx"], records["v"], records["bv"] = cols["plx"][order], cols["v"][order], cols["bv"][order]
    records["sp"], records["flags"] = sp[order], flags[order]
    records["number"] = np.where(hip[order] > 0, hip[order], rank[order]).astype("<u4")
    records["name"] = name_offset[order]

    # Integrated starlight of the catalogue: V = 0 equivalent stars brighter than m (sum of 10^(-0.4 V)).
    v32 = records["v"].astype(np.float64)
    limits = FLUX_FIRST_MAG + FLUX_STEP_MAG * np.arange(FLUX_STEPS)
    flux = 10.0 ** (-0.4 * np.sort(v32))
    cumulative = np.concatenate([[0.0], np.cumsum(flux)])[np.searchsorted(np.sort(v32), limits + 1e-6, side="right")]

    kstars_version = package_version("kstars-data")
    stellarium_version = package_version("stellarium-data")
    kept = sum(int(d["keep"].sum()) for d in extra)
    source = (f"Debian packages kstars-data {kstars_version} ({a.kstars}: {len(kstars)} Hipparcos/Tycho stars to "
              f"V = {faintest_kstars:.2f}; ESA 1997 via KStars, (C) Jason Harris 2003, GPL) and stellarium-data "
              f"{stellarium_version} ({a.stellarium_dir}/{', '.join(files)}: {kept} further Hipparcos and Tycho-2 "
              f"stars of V 9.0-10.5, Hog et al. 2000 via Stellarium, GPL; V quantised to 0.05 mag); sha256 of the "
              f"inputs {digest.hexdigest()}. Built by data/stars/build_catalogue.py. Positions ICRS at epoch "
              f"J2000.0; proper motion mu_alpha* and mu_delta in mas/yr; parallax in mas; Johnson V and B-V in "
              f"mag. Ordered by sky cell (1-degree declination bands) and V.").encode("utf-8")
    header_bytes = FIXED_HEADER.size + len(source)
    header_bytes = (header_bytes + 7) // 8 * 8
    tables = starts.tobytes() + cumulative.astype("<f8").tobytes()
    tables += b"\0" * ((-len(tables)) % 8)
    max_pm = float(np.max(np.hypot(records["pm_ra"].astype(np.float64), records["pm_dec"].astype(np.float64))))
    header = FIXED_HEADER.pack(MAGIC, FORMAT_VERSION, header_bytes, n, RECORD.itemsize, EPOCH_JULIAN_YEAR,
                               float(v32.min()), float(v32.max()), len(source), len(names_blob), cell_count,
                               FLUX_STEPS, BAND_DEG, max_pm, len(tables))
    header += source
    header += b"\0" * (header_bytes - len(header))
    tmp = a.output + ".tmp"
    with open(tmp, "wb") as f:
        f.write(header)
        f.write(tables)
        f.write(records.tobytes())
        f.write(names_blob)
    os.replace(tmp, a.output)
    print(f"{a.output}: {n} stars ({len(kstars)} KStars, {kept} Stellarium), V {v32.min():.2f} .. {v32.max():.2f}, "
          f"{cell_count} cells; V = 0 equivalent flux to V = 10.5: {cumulative[int(round((10.5 - FLUX_FIRST_MAG) / FLUX_STEP_MAG))]:.1f}")


if __name__ == "__main__":
    main()
