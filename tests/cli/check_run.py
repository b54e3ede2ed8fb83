#!/usr/bin/env python3
"""`eoir run`: files, FITS headers and pixels (read back with cfitsio through
fits_dump), PNG sizes and orientation, summary.json against its schema, the
FITS WCS against the Moon's true direction, --sensor selection, progress.

usage: check_run.py EOIR FITS_DUMP RUN_SUMMARY_SCHEMA

Needs the Python bindings on PYTHONPATH (for the Moon's position) and
EOIR_LIBRARY pointing at the engine.
"""
import json
import math
import os
import re
import struct
import subprocess
import sys
import tempfile
import zlib

import jsonschema
import numpy as np

import eoir

START, STOP = "2010-08-25T18:00:00Z", "2010-08-25T18:01:00Z"
GEO_A_KM = 42164.17
SAMPLES = {"Cam": 4, "Wide": 2}  # scene samples per pixel (fidelity knob samples_per_pixel)
TRUE_ANOMALY = 100.0  # the Moon (RA 343 deg) is far from the Earth seen from here
CAM = {"w": 64, "h": 48, "hfov": 6.0, "vfov": 4.5}
LWIR = {
    "band_low_um": 8.0, "band_high_um": 12.0, "f_number": 2.0, "focal_length_cm": 5.0,
    "defocus_mm": 0.0, "image_quality": "diffraction_limited", "diffraction_wavelength_um": 10.0,
    "integration_time_ms": 1.0, "sensitivity_quantity": "radiance", "sensitivity_pairs": [[10.0, 1e-7]],
    "saturation_quantity": "radiance", "saturation_pairs": [[10.0, 1e-2]], "jitter_mrad": 0.0,
}

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL", what)


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def radec(v):
    v = unit(v)
    return math.degrees(math.atan2(v[1], v[0])) % 360.0, math.degrees(math.asin(v[2]))


def vec(ra, dec):
    ra, dec = math.radians(ra), math.radians(dec)
    return np.array([math.cos(dec) * math.cos(ra), math.cos(dec) * math.sin(ra), math.sin(dec)])


def quat_from_axes(x, y, z):
    """Quaternion (w, x, y, z) of the rotation whose matrix has columns x, y, z."""
    m = np.column_stack([x, y, z])
    w = math.sqrt(max(0.0, 1.0 + m[0, 0] + m[1, 1] + m[2, 2])) / 2.0
    return [w, (m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w), (m[1, 0] - m[0, 1]) / (4 * w)]


def moon_j2000_m(iso):
    with eoir.Engine(threads=1) as e:
        e.add_object("central_body", "Moon")
        e.set_time(iso)
        return e.get_state("Moon")["position"]


def sat_j2000_m(true_anomaly_deg):
    nu = math.radians(true_anomaly_deg)
    return GEO_A_KM * 1e3 * np.array([math.cos(nu), math.sin(nu), 0.0])


def scenario(cam_quat):
    return {
        "format": "eoir-scenario", "version": 1, "name": "run test: Moon off-centre",
        "start": START, "stop": STOP, "step_s": 60,
        "central_bodies": [{"name": "Earth", "properties": {"temperature_K": 288.0}},
                           {"name": "Moon", "properties": {"temperature_K": 250.0}}],
        "objects": [{
            "name": "Sat", "kind": "satellite",
            "motion": {"type": "kepler", "central_body": "Earth", "semi_major_axis_km": GEO_A_KM,
                       "eccentricity": 0.0, "inclination_deg": 0.0, "raan_deg": 0.0, "arg_perigee_deg": 0.0,
                       "true_anomaly_deg": TRUE_ANOMALY, "epoch": START},
            "attitude": {"type": "nadir"}}],
        "sensors": [
            {"name": "Cam", "parent": "Sat", "pointing": {"type": "fixed_inertial", "quaternion": cam_quat},
             "parameters": dict(LWIR, horizontal_pixels=CAM["w"], vertical_pixels=CAM["h"],
                                horizontal_fov_deg=CAM["hfov"], vertical_fov_deg=CAM["vfov"])},
            {"name": "Wide", "parent": "Sat", "pointing": {"type": "nadir"},
             "parameters": dict(LWIR, horizontal_pixels=32, vertical_pixels=32,
                                horizontal_fov_deg=20.0, vertical_fov_deg=20.0, samples_per_pixel=2)},
        ],
    }


def fits(dump, path, tmp):
    raw = os.path.join(tmp, "pixels.raw")
    r = subprocess.run([dump, path, raw], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"FAILED: cfitsio cannot read {path}: {r.stderr}")
    cards, size, chk = {}, None, None
    for line in r.stdout.splitlines():
        if line.startswith("card "):
            k, _, v = line[5:].partition("\t")
            cards.setdefault(k, v.strip())
        elif line.startswith("size "):
            size = tuple(int(x) for x in line.split()[1:])
        elif line.startswith("checksum "):
            chk = tuple(int(x) for x in line.split()[1:])
    w, h = size[0], size[1]
    data = np.fromfile(raw, dtype=np.float64).reshape(h, w)  # FITS order: row 0 = bottom
    return cards, size, chk, data


def png(path):
    """Decodes an 8-bit grayscale, non-interlaced PNG (all the writer makes)."""
    with open(path, "rb") as f:
        b = f.read()
    assert b[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, ihdr = 8, b"", None
    while pos < len(b):
        n, kind = struct.unpack(">I4s", b[pos:pos + 8])
        body = b[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    w, h, depth, ctype, _, _, interlace = ihdr
    assert depth == 8 and ctype == 0 and interlace == 0, ihdr
    raw = zlib.decompress(idat)
    out = np.zeros((h, w), dtype=np.int32)
    prev = np.zeros(w, dtype=np.int32)
    for r in range(h):
        ftype = raw[r * (w + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=w, offset=r * (w + 1) + 1).astype(np.int32)
        cur = np.zeros(w, dtype=np.int32)
        for c in range(w):
            a = cur[c - 1] if c else 0
            up = prev[c]
            ul = prev[c - 1] if c else 0
            if ftype == 0:
                p = 0
            elif ftype == 1:
                p = a
            elif ftype == 2:
                p = up
            elif ftype == 3:
                p = (a + up) // 2
            else:
                pa, pb, pc = abs(up - ul), abs(a - ul), abs(a + up - 2 * ul)
                p = a if pa <= pb and pa <= pc else (up if pb <= pc else ul)
            cur[c] = (line[c] + p) & 255
        out[r] = cur
        prev = cur
    return out


def wcs_direction(cards, px, py):
    """Direction (unit J2000 vector) of FITS pixel (px, py) (1-based) by the
    header's TAN WCS (CD matrix)."""
    g = lambda k: float(cards[k])
    xi = g("CD1_1") * (px - g("CRPIX1")) + g("CD1_2") * (py - g("CRPIX2"))
    eta = g("CD2_1") * (px - g("CRPIX1")) + g("CD2_2") * (py - g("CRPIX2"))
    ra0, dec0 = math.radians(g("CRVAL1")), math.radians(g("CRVAL2"))
    r = vec(g("CRVAL1"), g("CRVAL2"))
    east = np.array([-math.sin(ra0), math.cos(ra0), 0.0])
    north = np.array([-math.sin(dec0) * math.cos(ra0), -math.sin(dec0) * math.sin(ra0), math.cos(dec0)])
    return unit(r + math.radians(xi) * east + math.radians(eta) * north)


def angle_deg(a, b):
    return math.degrees(math.acos(max(-1.0, min(1.0, float(unit(a) @ unit(b))))))


def centroid(mask):
    rows, cols = np.nonzero(mask)
    return cols.mean(), rows.mean()


def main():
    eoir_exe, dump, schema_file = sys.argv[1:4]
    with open(schema_file) as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)

    # Camera: boresight 1.5 deg and 1.0 deg away from the Moon along two
    # axes, image up 30 deg from north, so that a flip or a mirror in the
    # files or in the WCS moves the Moon far from where the WCS puts it.
    moon0 = moon_j2000_m(START)
    sat0 = sat_j2000_m(TRUE_ANOMALY)
    d = unit(moon0 - sat0)
    east = unit(np.cross([0, 0, 1], d))
    north = np.cross(d, east)
    z = unit(d + math.tan(math.radians(1.5)) * east + math.tan(math.radians(1.0)) * north)
    y = unit(math.cos(math.radians(30)) * north + math.sin(math.radians(30)) * east)
    y = unit(y - (y @ z) * z)
    x = np.cross(y, z)
    quat = quat_from_axes(x, y, z)

    with tempfile.TemporaryDirectory() as tmp:
        scen = os.path.join(tmp, "run_test.json")
        with open(scen, "w") as f:
            json.dump(scenario(quat), f, indent=2)
        out = os.path.join(tmp, "out", "nested")  # created with its parents
        r = subprocess.run([eoir_exe, "run", scen, "--out", out, "--quiet"], capture_output=True, text=True)
        print(f"$ eoir run {scen} --out {out} --quiet\nexit {r.returncode}\n{r.stdout}{r.stderr}")
        if r.returncode != 0:
            raise SystemExit("FAILED: eoir run exited non-zero")
        check("frame" not in r.stderr, "--quiet prints no progress")

        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        errs = list(jsonschema.Draft202012Validator(schema).iter_errors(summary))
        for e in errs:
            print("schema:", "/".join(map(str, e.path)), e.message)
        check(not errs, "summary.json validates against run_summary.schema.json")
        check(summary["time_steps"] == 2 and len(summary["frames"]) == 4, "2 time steps x 2 sensors")
        check(summary["scenario"] == "run test: Moon off-centre", "summary scenario name")
        # Fidelity echoed per sensor (issue 7 item 3): the knobs as set.
        fid = {x["name"]: x["fidelity"] for x in summary["sensors"]}
        check(fid["Wide"].get("samples_per_pixel") == 2 and fid["Cam"].get("samples_per_pixel") == 4,
              f"summary fidelity samples_per_pixel {fid}")
        check(fid["Cam"].get("scene_mode") == "coarse" and fid["Cam"].get("band_integration") == "grid"
              and fid["Cam"].get("psf_grid_size") == 512, "summary fidelity: scene_mode, band_integration, psf_grid_size")

        expected = {"summary.json"}
        for i in range(2):
            for s in ("Cam", "Wide"):
                for suffix in ("radiance.fits", "electrons.fits", "mean_electrons.fits", "scene.png", "sensor.png",
                               "truth.json", "truth.reg"):
                    expected.add(f"{s}_{i:04d}_{suffix}")
        present = set(os.listdir(out))
        check(present == expected, f"files written: extra {sorted(present - expected)}, "
                                   f"missing {sorted(expected - present)}")

        for fr in summary["frames"]:
            tag = f"{fr['sensor']} frame {fr['index']}"
            sw, sh = fr["sensor_size"]["width"], fr["sensor_size"]["height"]
            cw, ch = fr["scene_size"]["width"], fr["scene_size"]["height"]
            n = SAMPLES[fr["sensor"]]
            check((cw, ch) == (n * sw, n * sh), f"{tag}: scene is {n}x{n} samples per pixel")
            if fr["sensor"] == "Cam":
                check((sw, sh) == (CAM["w"], CAM["h"]), f"{tag}: sensor size {sw}x{sh}")
            images = {}
            for key, bunit, (w, h), kind in (("radiance", "W cm-2 sr-1", (cw, ch), "scene_radiance"),
                                             ("electrons", "electron", (sw, sh), "sensor_electrons"),
                                             ("mean_electrons", "electron", (sw, sh), "sensor_mean")):
                cards, size, chk, data = fits(dump, os.path.join(out, fr["files"][key]), tmp)
                images[key] = (cards, data)
                check(chk == (1, 1), f"{tag} {key}: CHECKSUM/DATASUM verify ({chk})")
                check(size[:2] == (w, h), f"{tag} {key}: NAXIS1/2 {size[:2]} != {(w, h)}")
                check(cards.get("BUNIT") == bunit, f"{tag} {key}: BUNIT {cards.get('BUNIT')!r}")
                # FITS dates have no 'Z' (the time scale is TIMESYS = 'UTC');
                # DATE-OBS is the start of the integration, DATE-AVG the frame time
                check(cards.get("DATE-OBS") + "Z" == fr["start_time"] and cards.get("TIMESYS") == "UTC",
                      f"{tag} {key}: DATE-OBS {cards.get('DATE-OBS')}")
                check(cards.get("DATE-AVG") + "Z" == fr["time"], f"{tag} {key}: DATE-AVG {cards.get('DATE-AVG')}")
                check(cards.get("SENSOR") == fr["sensor"] and cards.get("INSTRUME") == fr["sensor"],
                      f"{tag} {key}: SENSOR/INSTRUME")
                check(cards.get("SCENARIO") == summary["scenario"], f"{tag} {key}: SCENARIO")
                check(int(cards.get("FRAME", -1)) == fr["index"], f"{tag} {key}: FRAME")
                check(cards.get("IMAGTYPE") == kind, f"{tag} {key}: IMAGTYPE")
                check(int(cards.get("SAMPPIX", -1)) == (SAMPLES[fr["sensor"]] if key == "radiance" else 1),
                      f"{tag} {key}: SAMPPIX {cards.get('SAMPPIX')}")
                for name, v in fid[fr["sensor"]].items():
                    card = cards.get("FID " + name.upper())
                    same = card is not None and (card.strip("'").strip() == v if isinstance(v, str)
                                                 else abs(float(card) - v) <= 1e-12 * abs(v))
                    check(same, f"{tag} {key}: HIERARCH FID {name.upper()} = {card!r}, summary {v!r}")
                for k, sk in (("BORE_RA", "boresight_ra_deg"), ("BORE_DEC", "boresight_dec_deg"),
                              ("UP_RA", "up_ra_deg"), ("UP_DEC", "up_dec_deg")):
                    check(abs(float(cards[k]) - fr[sk]) < 1e-9, f"{tag} {key}: {k}")
                st = fr[key]
                fin = data[np.isfinite(data)]
                for stat, v in (("min", fin.min()), ("max", fin.max()), ("mean", fin.mean())):
                    check(abs(v - st[stat]) <= 1e-6 * max(abs(st[stat]), 1e-30) + 1e-30,
                          f"{tag} {key}: {stat} {v} vs summary {st[stat]}")

            # PNGs: sizes, and the same orientation as the FITS (rows flipped back).
            scene_png = png(os.path.join(out, fr["files"]["scene_png"]))
            sensor_png = png(os.path.join(out, fr["files"]["sensor_png"]))
            check(scene_png.shape == (ch, cw), f"{tag}: scene PNG shape {scene_png.shape}")
            check(sensor_png.shape == (sh, sw), f"{tag}: sensor PNG shape {sensor_png.shape}")

            if fr["sensor"] != "Cam":
                continue
            # Where the Moon is, seen from the satellite at the frame time.
            wide = next(g for g in summary["frames"] if g["sensor"] == "Wide" and g["index"] == fr["index"])
            sat = -GEO_A_KM * 1e3 * vec(wide["boresight_ra_deg"], wide["boresight_dec_deg"])
            moon_dir = unit(moon_j2000_m(fr["time"]) - sat)
            cards, rad = images["radiance"]
            moon = rad > 0  # the sky is 0, only the Moon is in this field
            check(moon.sum() > 20, f"{tag}: the Moon is in the radiance image ({moon.sum()} samples)")
            cx, cy = centroid(moon)  # 0-based, FITS order
            off_centre = math.hypot(cx - (cw - 1) / 2, cy - (ch - 1) / 2)
            check(off_centre > 40, f"{tag}: the Moon is off-centre ({off_centre:.1f} samples)")
            err = angle_deg(wcs_direction(cards, cx + 1, cy + 1), moon_dir)
            print(f"{tag}: Moon at FITS sample ({cx + 1:.1f}, {cy + 1:.1f}); WCS error {err:.4f} deg")
            check(err < 0.05, f"{tag}: WCS puts the Moon {err:.3f} deg from its true direction")
            # The PNG shows the Moon at the same place, rows top-down.
            px, py = centroid(scene_png > scene_png.min() + 0.5 * (scene_png.max() - scene_png.min()))
            check(abs(px - cx) < 2 and abs(py - (ch - 1 - cy)) < 2,
                  f"{tag}: scene PNG Moon at ({px:.1f}, {py:.1f}) vs FITS ({cx:.1f}, {ch - 1 - cy:.1f}) flipped")
            # The sensor image (blurred, electrons): same place by its own WCS.
            cards_m, mean = images["mean_electrons"]
            bright = mean > mean.min() + 0.5 * (mean.max() - mean.min())
            mx, my = centroid(bright)
            err = angle_deg(wcs_direction(cards_m, mx + 1, my + 1), moon_dir)
            check(err < 0.1, f"{tag}: mean-electron WCS puts the Moon {err:.3f} deg off")

        # Progress on stderr without --quiet; --sensor selects.
        out2 = os.path.join(tmp, "out2")
        r = subprocess.run([eoir_exe, "run", scen, "--out", out2, "--sensor", "Cam", "--stop", START],
                           capture_output=True, text=True)
        print(f"$ eoir run ... --sensor Cam --stop {START}\nexit {r.returncode}\n{r.stderr}")
        check(r.returncode == 0, "single-frame run exits 0")
        check(re.search(r"frame 1 of 1 .*elapsed .*ETA", r.stderr) is not None, "progress line on stderr")
        check(sorted(os.listdir(out2)) == sorted(["summary.json"] + [
            f"Cam_0000_{s}" for s in ("radiance.fits", "electrons.fits", "mean_electrons.fits", "scene.png",
                                      "sensor.png", "truth.json", "truth.reg")]), f"--sensor Cam writes Cam only: {sorted(os.listdir(out2))}")

        r = subprocess.run([eoir_exe, "run", scen, "--out", out2, "--sensor", "Nope"], capture_output=True,
                           text=True)
        check(r.returncode != 0 and "unknown sensor 'Nope'" in r.stderr, f"unknown --sensor fails: {r.stderr}")

    if failures:
        raise SystemExit(f"FAILED: {len(failures)} check(s)")
    print("passed")


if __name__ == "__main__":
    main()
