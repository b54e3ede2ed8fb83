#!/usr/bin/env python3
"""The missile demo (issue 22 item 5) in its quick mode: 48 x 48 frames at
T-10 s (on the pad), T+30 s (stage 1 burning), T+100 s (stage 2 burning) and
T+190 s (both burnt out) of scenarios/demo/missile_demo.py.

usage: check_missile_demo.py DEMO_SCRIPT OUT_DIR [EOIR_EXE]

- the script exits 0 and writes its scenario, frames, CSV and plot; the PNGs
  open and are not blank;
- the plumes show at their times (spec 4.3.6, stage timing): the irradiance
  while a plume burns is over 100 times the hardbody's alone before the
  launch and after the burnout;
- while a plume burns the irradiance is at most what the plume's gray body
  (emittance 0.99, band radiance by Simpson over eq. 5) gives with its
  largest projected area (side-on: r sqrt(h^2 - r^2) + r^2 (pi -
  arccos(r/h)), h = length - r) plus every stage's hardbody as a 290 K black
  body seen side-on, over the range squared; and at least the plume's
  radiance over a fifth of its end-on disc (the plume's silhouette holds
  that disc from any side; the stage's, of width 2R = r, covers at most a
  strip of that width across it: 61 % of it);
- the scenario passes `eoir validate` (when EOIR_EXE is given).
"""
import csv
import math
import os
import subprocess
import sys

import numpy as np

failures = []


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what)
    if not cond:
        failures.append(what)


def planck_band(T, lo=3.0, hi=5.0, n=4000):
    """Band radiance W/(cm^2 sr) of a black body, Simpson over eq. 5."""
    c1 = 2 * 6.62607015e-34 * 299792458.0 ** 2 * 1e20  # W um^4 / (cm^2 sr)
    c2 = 6.62607015e-34 * 299792458.0 / 1.380649e-23 * 1e6  # um K
    lam = np.linspace(lo, hi, n + 1)
    B = c1 / lam ** 5 / np.expm1(c2 / (lam * T))
    w = np.ones(n + 1)
    w[1:-1:2], w[2:-1:2] = 4, 2
    return float(np.sum(w * B) * (hi - lo) / n / 3)


def side_area(r, length):
    h = length - r
    return r * math.sqrt(h * h - r * r) + r * r * (math.pi - math.acos(r / h))


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    script, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    r = subprocess.run([sys.executable, script, "--quick", "--out", out], capture_output=True, text=True)
    print(r.stdout[-4000:], r.stderr[-3000:])
    check(r.returncode == 0, "the demo script exits 0")
    if r.returncode != 0:
        return 1
    for name in ("missile_boost.json", "missile_boost_frames.png", "missile_boost_irradiance.csv",
                 "missile_boost_irradiance.png", "missile_boost_frame_00.png", "missile_boost_frame_03.png"):
        check(os.path.getsize(os.path.join(out, name)) > 0, f"{name} written")
    from PIL import Image
    for name in ("missile_boost_frames.png", "missile_boost_irradiance.png"):
        a = np.asarray(Image.open(os.path.join(out, name)).convert("L"), dtype=float)
        check(a.std() > 1.0, f"{name} is not blank")
    with open(os.path.join(out, "missile_boost_irradiance.csv"), encoding="utf-8") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    E = {round(float(x["since_launch_s"])): float(x["effective_irradiance_W_cm2"]) for x in rows}
    R = {round(float(x["since_launch_s"])): float(x["range_m"] or "nan") for x in rows}
    check(sorted(E) == [-10, 30, 100, 190], f"frames at T-10, 30, 100, 190 s: {sorted(E)}")
    if sorted(E) != [-10, 30, 100, 190]:
        return 1
    print("E:", E)
    check(all(x["pixel_x"] != "" for x in rows), "the missile is in the field (truth) in every frame")
    check(all(math.isfinite(v) and v >= 0 for v in E.values()), "finite, non-negative irradiances")
    check(E[30] > 100 * E[-10], "stage 1's plume shows after the launch (x100 over the pad)")
    check(E[100] > 100 * E[190], "stage 2's plume goes off at its burnout (x100)")
    # Bounds while burning: (plume T, r, length) of each stage (missile_demo.py's STAGE1, STAGE2).
    hard = planck_band(290.0) * (14.0 * 1.8 + 7.0 * 1.2 + math.pi * 0.9 ** 2)  # both stages side-on, 290 K black
    for t, (T, R_stage, length) in ((30, (1800.0, 0.9, 3 * 14.0)), (100, (1500.0, 0.6, 4 * 7.0))):
        rr = 2 * R_stage
        L = 0.99 * planck_band(T)
        upper = (L * side_area(rr, length) + hard) / R[t] ** 2
        lower = L * 0.2 * math.pi * rr * rr / R[t] ** 2
        check(lower <= E[t] <= upper, f"T+{t} s: {lower:.4g} <= E = {E[t]:.4g} <= {upper:.4g} W/cm^2")
    if len(sys.argv) == 4:
        v = subprocess.run([sys.argv[3], "validate", os.path.join(out, "missile_boost.json")], capture_output=True,
                           text=True)
        check(v.returncode == 0, "eoir validate missile_boost.json: " + (v.stdout + v.stderr)[-300:])
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
