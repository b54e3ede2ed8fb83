#!/usr/bin/env python3
"""An aircraft seen from a LEO imager (issue 22 item 5), made with the eoir
Python package (the library in build/lib, or EOIR_LIBRARY):

aircraft_leo.png: a 40 m airliner (cylinder fuselage, plate wings,
tailplane and fin; white, reflectance 0.8) flying north-east at 230 m/s,
10 km above the Libyan desert (25 N, 17 E) on the June solstice at 09:00
UTC (the Sun ~63 deg high), placed by an Earth-fixed ephemeris with a
heading_pitch_roll attitude; a LEO imager 490 km away at the Sun's
elevation, 4 deg of azimuth beside it, looks at it, so that its shadow on
the ground (~5 km down-Sun of the point below it) lies a few hundred metres
beside it in the picture
(0.45-0.75 um, bitmap mode: the land cover around). Left: the scene's
radiance; right: the same with the aircraft removed subtracted (the
aircraft bright, its shadow dark). aircraft_leo.csv: the ground's, the
shadow's and the aircraft's radiance; aircraft_leo.json: the scenario
(`eoir run` takes it).

The shadow is the geometric one of the aircraft's parts (no penumbra:
README "Aircraft and ground vehicles"); at 10 km the real Sun's 0.53 deg
disc would blur it over ~90 m, wider than the aircraft.

    /usr/bin/python3 scenarios/demo/vehicle_demos.py                  # scenarios/demo/results
    /usr/bin/python3 scenarios/demo/vehicle_demos.py --quick --out /tmp/demos   # small frame
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from demo_support import WGS84_A, WGS84_E2, ecef, enu_axes, import_eoir, write_json  # noqa: E402

eoir = import_eoir()


TIME = "2010-06-21T09:00:00Z"
BESIDE_DEG = 4.0  # the imager's azimuth from the Sun's, seen from the aircraft
PLACE = (25.0, 17.0, 10000.0)  # lat, lon deg, height m
HEADING_DEG = 45.0
SPEED_M_S = 230.0


def geodetic(r):
    """Earth-fixed metres to lat, lon (deg), height (m) (fixed-point iteration)."""
    x, y, z = r
    lon = math.atan2(y, x)
    p = math.hypot(x, y)
    lat = math.atan2(z, p * (1.0 - WGS84_E2))
    for _ in range(10):
        n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
        h = p / math.cos(lat) - n
        lat = math.atan2(z, p * (1.0 - WGS84_E2 * n / (n + h)))
    n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
    return math.degrees(lat), math.degrees(lon), p / math.cos(lat) - n


def airliner_parts():
    """A 40 m airliner of primitives in the aircraft's body axes (x forward,
    y right, z down; metres)."""
    c45 = math.sqrt(0.5)
    return [
        {"shape": "cylinder", "dimensions_m": [2.0, 40.0], "orientation_wxyz": [c45, 0.0, c45, 0.0]},  # z -> x
        {"shape": "plate", "dimensions_m": [6.0, 36.0], "offset_m": [2.0, 0.0, 0.5]},       # wings
        {"shape": "plate", "dimensions_m": [3.0, 12.0], "offset_m": [-17.5, 0.0, -1.0]},    # tailplane
        {"shape": "plate", "dimensions_m": [4.0, 7.0], "offset_m": [-17.0, 0.0, -5.0],     # fin (plate y -> up)
         "orientation_wxyz": [c45, -c45, 0.0, 0.0]},
    ]


def sun_direction_enu(lat, lon, h):
    """The Sun's direction from the place (east, north, up), from the engine's Sun."""
    with eoir.Engine(threads=1) as e:
        e.set_time(TIME)
        sun = e.get_state("Sun", "earth_fixed")["position"]
    d = sun - ecef(lat, lon, h)
    d /= np.linalg.norm(d)
    east, north, up = enu_axes(lat, lon)
    return np.array([d @ east, d @ north, d @ up])


def scenario(quick: bool):
    lat, lon, h = PLACE
    east, north, up = enu_axes(lat, lon)
    r0 = ecef(lat, lon, h)
    hdg = math.radians(HEADING_DEG)
    v = SPEED_M_S * (math.cos(hdg) * north + math.sin(hdg) * east)
    # Ephemeris: straight and level (Earth-fixed) 30 s either side of TIME.
    t0 = np.datetime64(TIME.rstrip("Z"))
    points = []
    for dt in (-30, 30):
        t = str(t0 + np.timedelta64(dt, "s")) + "Z"
        points.append({"time": t, "position_m": list(map(float, r0 + dt * v)), "velocity_m_s": list(map(float, v))})
    # The imager: 490 km from the aircraft at the Sun's elevation, BESIDE_DEG
    # of azimuth beside it.
    s = sun_direction_enu(lat, lon, h)
    el = math.asin(s[2])
    az = math.atan2(s[0], s[1]) + math.radians(BESIDE_DEG)
    look = math.cos(el) * (math.sin(az) * east + math.cos(az) * north) + math.sin(el) * up
    ilat, ilon, ih = geodetic(r0 + 490e3 * look)
    pixels = 64 if quick else 256
    return {
        "$schema": "../../../schemas/scenario.schema.json",
        "format": "eoir-scenario",
        "version": 1,
        "name": "Aircraft from LEO",
        "description": "Issue 22 item 5: a 40 m airliner of primitives at 10 km over the Libyan desert, heading "
                       "45 deg at 230 m/s (Earth-fixed ephemeris, heading_pitch_roll attitude), seen from a LEO "
                       "imager ~490 km away beside the Sun's direction with its shadow on the ground (bitmap mode, "
                       "0.45-0.75 um). Made by scenarios/demo/vehicle_demos.py.",
        "start": TIME,
        "stop": TIME,
        "step_s": 60,
        "central_bodies": [{"name": "Earth"}],
        "objects": [
            {"name": "Imager", "kind": "satellite",
             "motion": {"type": "fixed_geodetic", "lat_deg": ilat, "lon_deg": ilon, "alt_m": ih},
             "properties": {"shape": "none"}},
            {"name": "Airliner", "kind": "aircraft",
             "motion": {"type": "ephemeris", "frame": "earth_fixed", "points": points},
             "attitude": {"type": "heading_pitch_roll", "heading_deg": HEADING_DEG, "pitch_deg": 2.0,
                          "roll_deg": 0.0},
             "properties": {"shape": "composite", "composite": json.dumps(airliner_parts()),
                            "material": "gray_body", "reflectance": 0.8}},
        ],
        "sensors": [
            {"name": "Camera", "parent": "Imager",
             "pointing": {"type": "target", "target": "Airliner"},
             "parameters": {"horizontal_pixels": pixels, "vertical_pixels": pixels,
                            "horizontal_fov_deg": 0.12, "vertical_fov_deg": 0.12,
                            "band_low_um": 0.45, "band_high_um": 0.75, "spectral_intervals": 6,
                            "focal_length_cm": 250.0, "f_number": 5.0, "diffraction_wavelength_um": 0.6,
                            "noise_enabled": False, "scene_mode": "bitmap"}},
        ],
    }, (math.degrees(el), math.degrees(az) - BESIDE_DEG)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=str(HERE / "results"))
    ap.add_argument("--quick", action="store_true", help="a 64 x 64 pixel frame")
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    doc, (sun_el, sun_az) = scenario(args.quick)
    path = out / "aircraft_leo.json"
    write_json(path, doc)
    t0 = time.time()
    with eoir.Scenario.load(path, threads=args.threads) as sc:
        e = sc.engine
        sc.set_time(sc.start)
        e.render("Camera")
        scene = e.image("Camera", "scene_radiance")
        plane = e.pick("Camera", scene.shape[1] // 2, scene.shape[0] // 2)
        e.set("Airliner", "shape", "none")
        e.render("Camera")
        bare = e.image("Camera", "scene_radiance")
    print(f"  {scene.shape[1]}x{scene.shape[0]} samples, twice, in {time.time() - t0:.1f} s; "
          f"Sun {sun_el:.1f} deg high at azimuth {sun_az:.1f} deg; centre sample: {plane['object']}")
    diff = scene - bare
    shadow = scene < 0.5 * bare
    aircraft = diff > 0.05 * bare.mean()
    ground = bare.mean()
    rows = [("ground_mean", float(ground)),
            ("shadow_samples", int(np.count_nonzero(shadow))),
            ("shadow_mean", float(scene[shadow].mean()) if shadow.any() else 0.0),
            ("aircraft_samples", int(np.count_nonzero(aircraft))),
            ("aircraft_max", float(scene.max())),
            ("sun_elevation_deg", sun_el)]
    with open(out / "aircraft_leo.csv", "w", newline="", encoding="utf-8") as f:
        f.write("# radiances W/(cm^2 sr), 0.45-0.75 um; samples are scene samples (4 x 4 per pixel)\n")
        w = csv.writer(f)
        w.writerow(["quantity", "value"])
        for k, v in rows:
            w.writerow([k, f"{v:.6g}" if isinstance(v, float) else v])
    for k, v in rows:
        print(f"  {k}: {v}")

    # The square about the aircraft and its shadow, with a margin.
    rows_, cols_ = np.nonzero(shadow | aircraft)
    if rows_.size:
        half = max(rows_.ptp(), cols_.ptp()) // 2 + max(8, scene.shape[0] // 16)
        cy, cx = (rows_.min() + rows_.max()) // 2, (cols_.min() + cols_.max()) // 2
        y0, x0 = max(0, cy - half), max(0, cx - half)
        crop = (slice(y0, min(scene.shape[0], cy + half)), slice(x0, min(scene.shape[1], cx + half)))
    else:
        crop = (slice(None), slice(None))
    metres = 2 * 490e3 * math.tan(math.radians(0.06)) / scene.shape[1]  # per sample at the aircraft
    fig, ax = plt.subplots(1, 2, figsize=(11, 5.6))
    ax[0].imshow(scene[crop], cmap="gray", vmin=0, vmax=scene.max())
    ax[0].set_title(f"scene radiance (bitmap mode, 0.45-0.75 um), {metres:.1f} m samples", fontsize=9)
    lim = max(abs(diff).max(), 1e-30)
    ax[1].imshow(diff[crop], cmap="RdBu_r", vmin=-lim, vmax=lim)
    ax[1].set_title("minus the same without the aircraft: aircraft red, shadow blue", fontsize=9)
    for a in ax:
        a.set_xticks([])
        a.set_yticks([])
    fig.suptitle(f"40 m airliner at 10 km seen from LEO 490 km away, {TIME}: the aircraft and its "
                 f"shadow on the desert", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "aircraft_leo.png", dpi=90)
    plt.close(fig)
    print(f"  wrote {out / 'aircraft_leo.png'}, aircraft_leo.csv, aircraft_leo.json")
    return 0


if __name__ == "__main__":
    sys.exit(main())
