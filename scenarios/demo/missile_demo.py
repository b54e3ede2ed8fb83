#!/usr/bin/env python3
"""A two-stage missile boosting and separating, seen by a GEO staring sensor
in the MWIR (issue 22 item 5), made with the eoir Python package (the library
in build/lib, or EOIR_LIBRARY):

- missile_boost.json: the scenario (`eoir run` takes it): a geostationary
  satellite over 25 deg W carries Stare, a 3-5 um camera (1 deg field,
  256 x 256) held on a point of the Atlantic near the launch site at local
  midnight; Missile1 flies a ballistic motion (README "Missiles": the
  minimum-energy Keplerian arc from 5 N 30 W to 30 N 15 W, 170 s powered)
  nose first (attitude velocity), with two stages (missile_stages): the first
  (14 m x 0.9 m) burns with a 1800 K plume for 90 s and separates, then falls
  back from the stack for 30 s; the second (7 m x 0.6 m) lights its 1500 K
  plume 3 s after the separation and burns to 80 s of its own time.
- missile_boost_frames.png: the image sequence (sensor electrons, a frame
  every 10 s from 10 s before the launch; asinh stretch, the missile's truth
  pixel circled), and each frame alone as missile_boost_frame_NN.png.
- missile_boost_irradiance.csv / .png: the missile's effective irradiance at
  the sensor (truth: the detailed point-source sum over its visible patches)
  against time, with the stage events marked.

    /usr/bin/python3 scenarios/demo/missile_demo.py                 # scenarios/demo/results
    /usr/bin/python3 scenarios/demo/missile_demo.py --quick --out /tmp/m   # 48 x 48, 4 frames

The Earth is the climatology's night-time surface in smooth mode, without
its atmosphere (vacuum): the plume's light reaches GEO undimmed.
"""

from __future__ import annotations

import argparse
import csv
import datetime as dt
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


def import_eoir():
    import importlib
    import importlib.util
    if importlib.util.find_spec("eoir") is None:
        sys.path.insert(0, str(REPO / "bindings" / "python"))
    return importlib.import_module("eoir")


START = dt.datetime(2010, 8, 25, 2, 0, 0, tzinfo=dt.timezone.utc)  # local midnight at 30 W
LAUNCH_DELAY_S = 10.0
LAUNCH = (5.0, -30.0)
IMPACT = (30.0, -15.0)
BURN_S = 170.0  # the motion's powered flight: both stages' burns
# (The spent stage recedes 150 m at most: the missile stays smaller than a
# sample, a point source; README "Missiles".)
STAGE1 = {"length_m": 14.0, "radius_m": 0.9, "separation_s": 90.0, "drawn_after_separation_s": 30.0,
          "separation_speed_m_s": 5.0,
          "plume": {"temperature_K": 1800.0, "length_scale": 3.0, "width_scale": 2.0}}
STAGE2 = {"length_m": 7.0, "radius_m": 0.6,
          "parts": [{"shape": "cylinder", "dimensions_m": [0.6, 5.0], "offset_m": [0, 0, 2.5]},
                    {"shape": "cone", "dimensions_m": [0.6, 2.0], "offset_m": [0, 0, 6.0]}],
          "plume": {"temperature_K": 1500.0, "length_scale": 4.0, "width_scale": 2.0, "on_s": 3.0, "off_s": 80.0}}
BAND_UM = (3.0, 5.0)


def iso(t: dt.datetime) -> str:
    return t.strftime("%Y-%m-%dT%H:%M:%S") + (f".{t.microsecond // 1000:03d}" if t.microsecond else "") + "Z"


def scenario(quick: bool) -> dict:
    launch_time = START + dt.timedelta(seconds=LAUNCH_DELAY_S)
    # The sensor stares at a point 5 % of the way from the launch to the impact (the boost in the field).
    aim = (LAUNCH[0] + 0.05 * (IMPACT[0] - LAUNCH[0]), LAUNCH[1] + 0.05 * (IMPACT[1] - LAUNCH[1]))
    n = 48 if quick else 256
    # GEO over 25 W at the start: the true anomaly from the Greenwich sidereal angle.
    jd = 2440587.5 + START.timestamp() / 86400.0
    gmst_deg = (280.46061837 + 360.98564736629 * (jd - 2451545.0)) % 360.0
    return {
        "format": "eoir-scenario",
        "version": 1,
        "name": "EOIR demo: a two-stage missile boosts and separates, seen from GEO in the MWIR",
        "description": "scenarios/demo/missile_demo.py (issue 22 item 5): a GEO staring 3-5 um camera over 25 W "
                       "watches a two-stage missile (missile_stages, ballistic motion, attitude velocity) launched "
                       "from 5 N 30 W at local midnight.",
        "start": iso(START),
        "stop": iso(START + dt.timedelta(seconds=220)),
        "step_s": 10,
        "central_bodies": ["Earth"],
        "stars": False,
        "objects": [
            {"name": "Geo1", "kind": "satellite",
             "motion": {"type": "kepler", "central_body": "Earth", "semi_major_axis_km": 42164.17,
                        "eccentricity": 0.0, "inclination_deg": 0.0, "raan_deg": 0.0, "arg_perigee_deg": 0.0,
                        "true_anomaly_deg": (gmst_deg - 25.0) % 360.0, "epoch": iso(START)},
             "attitude": {"type": "nadir"}, "properties": {"shape": "none"}},
            {"name": "AimPoint", "kind": "site", "motion": {"type": "fixed_geodetic", "lat_deg": aim[0],
                                                           "lon_deg": aim[1], "alt_m": 0.0}},
            {"name": "Missile1", "kind": "missile",
             "motion": {"type": "ballistic", "launch_lat_deg": LAUNCH[0], "launch_lon_deg": LAUNCH[1],
                        "impact_lat_deg": IMPACT[0], "impact_lon_deg": IMPACT[1], "launch_time": iso(launch_time),
                        "burn_s": BURN_S},
             "attitude": {"type": "velocity"},
             "properties": {"material": "gray_body", "reflectance": 0.3, "temperature_K": 290.0,
                            "missile_stages": json.dumps([STAGE1, STAGE2]), "launch_time_utc": iso(launch_time)}},
        ],
        "sensors": [
            {"name": "Stare", "parent": "Geo1", "pointing": {"type": "target", "target": "AimPoint"},
             "parameters": {"horizontal_pixels": n, "vertical_pixels": n, "horizontal_fov_deg": 1.0,
                            "vertical_fov_deg": 1.0, "band_low_um": BAND_UM[0], "band_high_um": BAND_UM[1],
                            "f_number": 2.0, "focal_length_cm": 60.0, "image_quality": "diffraction_limited",
                            "diffraction_wavelength_um": 4.0, "integration_time_ms": 10.0,
                            "sensitivity_quantity": "radiance", "sensitivity_pairs": [[4.0, 1e-8]],
                            "saturation_quantity": "radiance", "saturation_pairs": [[4.0, 1e-3]],
                            "jitter_mrad": 0.0, "scene_mode": "smooth"}},
        ],
    }


def events():
    """Seconds after the scenario's start of the stage events."""
    sep = LAUNCH_DELAY_S + STAGE1["separation_s"]
    return {"launch": LAUNCH_DELAY_S, "stage 1 separates": sep,
            "stage 2 lights": sep + STAGE2["plume"]["on_s"], "stage 2 burns out": sep + STAGE2["plume"]["off_s"],
            "spent stage 1 gone": sep + STAGE1["drawn_after_separation_s"]}


def asinh_stretch(x, soft, top):
    return np.clip(np.arcsinh(np.maximum(x, 0) / soft) / np.arcsinh(top / soft), 0, 1)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=str(HERE / "results"))
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    eoir = import_eoir()
    path = out / "missile_boost.json"
    with open(path, "w", encoding="utf-8") as f:
        json.dump(scenario(args.quick), f, indent=2)
        f.write("\n")
    times_s = [0.0, 40.0, 110.0, 200.0] if args.quick else [10.0 * k for k in range(22)]
    frames, rows = [], []
    with eoir.Scenario.load(path, threads=args.threads) as sc:
        e = sc.engine
        for t in times_s:
            sc.set_time(iso(START + dt.timedelta(seconds=t)))
            t0 = time.time()
            e.render("Stare")
            img = e.image("Stare", "sensor_electrons")
            truth = [r for r in sc.truth("Stare") if r.get("object") == "Missile1"]
            m = truth[0] if truth else {}
            E = float(m.get("effective_irradiance") or 0.0)
            rows.append((t, t - LAUNCH_DELAY_S, E, m.get("pixel_x"), m.get("pixel_y"), m.get("range_m")))
            frames.append((t, img, m))
            print(f"  t = {t:5.0f} s: E = {E:.4g} W/cm^2, pixel ({m.get('pixel_x')}, {m.get('pixel_y')}), "
                  f"{time.time() - t0:.1f} s", flush=True)
    with open(out / "missile_boost_irradiance.csv", "w", encoding="utf-8", newline="") as f:
        f.write(f"# missile_boost.json: Missile1's effective irradiance at Stare ({BAND_UM[0]}-{BAND_UM[1]} um), "
                "truth of each frame; pixels 0-based, rows from the top\n")
        for name, t in events().items():
            f.write(f"# {name}: {t:.1f} s after the start\n")
        w = csv.writer(f)
        w.writerow(["time_s", "since_launch_s", "effective_irradiance_W_cm2", "pixel_x", "pixel_y", "range_m"])
        for r in rows:
            w.writerow(["" if v is None else v for v in r])

    # The image sequence: each frame less its median (the Earth's night-time
    # background), one asinh stretch for all, its knee at the background's
    # spread; the montage shows a 48-pixel crop around the missile.
    diffs = [img - np.median(img) for _, img, _ in frames]
    spread = max(float(np.median([np.percentile(np.abs(d), 90) for d in diffs])), 1e-12)
    top = max(float(max(d.max() for d in diffs)), 10 * spread)
    soft = max(spread, 1e-3 * top)
    for k, d in enumerate(diffs):
        plt.imsave(out / f"missile_boost_frame_{k:02d}.png", asinh_stretch(d, soft, top), cmap="inferno", vmin=0,
                   vmax=1)
    cols = 4 if args.quick else 6
    shown = list(range(len(frames))) if args.quick else list(range(0, len(frames), 2))[:12]
    nrows = math.ceil(len(shown) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(2.6 * cols, 2.8 * nrows), dpi=110, squeeze=False)
    for ax in axes.flat:
        ax.set_axis_off()
    half = min(24, frames[0][1].shape[0] // 2)
    last = (frames[0][1].shape[1] / 2, frames[0][1].shape[0] / 2)
    for ax, k in zip(axes.flat, shown):
        t, img, m = frames[k]
        if m.get("pixel_x") is not None:
            last = (m["pixel_x"], m["pixel_y"])
        h, w = img.shape
        x0 = int(np.clip(round(last[0]) - half, 0, w - 2 * half))
        y0 = int(np.clip(round(last[1]) - half, 0, h - 2 * half))
        ax.imshow(asinh_stretch(diffs[k][y0:y0 + 2 * half, x0:x0 + 2 * half], soft, top), cmap="inferno", vmin=0,
                  vmax=1, interpolation="nearest", extent=(x0 - 0.5, x0 + 2 * half - 0.5, y0 + 2 * half - 0.5,
                                                           y0 - 0.5))
        if m.get("pixel_x") is not None:
            ax.add_patch(plt.Circle((m["pixel_x"], m["pixel_y"]), 3, fill=False, color="cyan", lw=0.6))
        ax.set_title(f"T{t - LAUNCH_DELAY_S:+.0f} s", fontsize=9)
    fig.suptitle("GEO staring sensor, 3-5 um, 1 deg field (crops of 48 pixels around the missile): a two-stage "
                 f"missile boosts,\nstage 1 separates at T+{STAGE1['separation_s']:.0f} s, stage 2 lights 3 s later "
                 "and burns out at T+170 s (sensor electrons less the background, asinh)", fontsize=10)
    fig.savefig(out / "missile_boost_frames.png", bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 4.2), dpi=110)
    t_arr = np.array([r[0] for r in rows])
    E_arr = np.array([r[2] for r in rows])
    ax.semilogy(t_arr - LAUNCH_DELAY_S, np.maximum(E_arr, 1e-22), "o-", color="tab:red", ms=3)
    for name, t in events().items():
        ax.axvline(t - LAUNCH_DELAY_S, color="gray", lw=0.7, ls="--")
        ax.text(t - LAUNCH_DELAY_S, ax.get_ylim()[1] * 0.98, name, rotation=90, fontsize=7, va="top", ha="right")
    ax.set_xlabel("time since launch (s)")
    ax.set_ylabel("effective irradiance at the sensor (W cm$^{-2}$)")
    ax.set_title("Missile1 seen from GEO, 3-5 um (detailed point source: visible plume and hardbody patches)",
                 fontsize=9)
    ax.grid(alpha=0.3)
    fig.savefig(out / "missile_boost_irradiance.png", bbox_inches="tight")
    plt.close(fig)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
