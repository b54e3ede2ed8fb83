#!/usr/bin/env python3
"""The atmosphere demos (issue 20 item 10) in their quick mode: tiny frames
and 3 steps of scenarios/demo/atmosphere_demos.py, which must complete and
write every picture, table and scenario it makes for the README.

usage: check_atmosphere_demos.py DEMO_SCRIPT OUT_DIR [EOIR_EXE]

- the script exits 0 within its budget;
- the three PNGs open (PIL) and are not blank;
- geo_disc_profile.csv: finite radiances; the atmosphere adds light where
  the vacuum frame is black (limb haze and twilight past the terminator);
  the mean ratio on/off in its header is finite and positive;
- geo_belt_night.csv: the five GEO satellites in the field, each with a
  positive SNR, near 52.8 deg elevation and an air mass near 0.97 (2096 m);
- iss_twilight_snr.csv: 3 steps in twilight (Sun 4-12 deg down), the ISS
  above 5 deg, an air mass that grows as the elevation falls, and at every
  step an SNR lower with the atmosphere than without it;
- the scenarios it wrote pass the scenario schema and `eoir validate` (when
  EOIR_EXE is given).
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import time

failures = []
OUTPUTS = ("geo_disc_atmosphere.png", "geo_disc_profile.csv", "geo_belt_night.png", "geo_belt_night.csv",
           "geo_belt_night.json", "iss_twilight_snr.png", "iss_twilight_snr.csv", "iss_twilight_pass.json")


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def rows_of(path):
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    script, out = sys.argv[1], sys.argv[2]
    eoir_exe = sys.argv[3] if len(sys.argv) == 4 else None
    os.makedirs(out, exist_ok=True)
    for name in OUTPUTS:  # an earlier run's files must not pass for this one's
        if os.path.exists(os.path.join(out, name)):
            os.unlink(os.path.join(out, name))
    t0 = time.time()
    r = subprocess.run([sys.executable, script, "--quick", "--out", out], capture_output=True, text=True)
    print(r.stdout[-6000:], r.stderr[-3000:])
    print(f"exit {r.returncode} after {time.time() - t0:.1f} s")
    if r.returncode != 0:
        sys.exit("FAILED: the demo script failed")

    from PIL import Image
    import numpy as np
    for name in OUTPUTS:
        check(os.path.isfile(os.path.join(out, name)), f"{name} written")
    for png in ("geo_disc_atmosphere.png", "geo_belt_night.png", "iss_twilight_snr.png"):
        path = os.path.join(out, png)
        if os.path.isfile(path):
            with Image.open(path) as im:
                a = np.asarray(im.convert("L"), dtype=float)
            check(a.shape[0] > 200 and a.shape[1] > 200, f"{png}: {a.shape}")
            check(a.std() > 5, f"{png} is not blank (std {a.std():.1f})")

    # 1. The GEO disc.
    path = os.path.join(out, "geo_disc_profile.csv")
    with open(path, encoding="utf-8") as f:
        header = f.read()
    m = re.search(r"mean ratio on/off: frame ([0-9.eE+-]+), disc ([0-9.eE+-]+)", header)
    check(m is not None, "geo_disc_profile.csv names the mean ratio")
    if m:
        frame, disc = float(m.group(1)), float(m.group(2))
        print(f"GEO disc: mean ratio on/off {frame} (disc {disc})")
        check(math.isfinite(frame) and frame > 0 and math.isfinite(disc) and disc > 0, "ratios positive")
    rows = rows_of(path)
    off = np.array([float(x["radiance_off_W_cm2_sr"]) for x in rows])
    on = np.array([float(x["radiance_on_W_cm2_sr"]) for x in rows])
    check(len(rows) >= 100 and np.all(np.isfinite(off)) and np.all(np.isfinite(on)), "profile finite")
    check(np.all(off >= 0) and np.all(on >= 0), "profile non-negative")
    check(np.any((off == 0) & (on > 0)), "the atmosphere lights samples the vacuum leaves black")

    # 2. The GEO belt.
    sats = rows_of(os.path.join(out, "geo_belt_night.csv"))
    check(len(sats) == 5, f"5 GEO satellites in the field ({len(sats)})")
    for s in sats:
        snr, el, am = float(s["snr"]), float(s["elevation_deg"]), float(s["air_mass"])
        check(snr > 0, f"{s['object']}: SNR {snr} > 0")
        check(abs(el - 52.8) < 0.1, f"{s['object']}: elevation {el} near 52.8")
        check(0.9 < am < 1.05, f"{s['object']}: air mass {am} near 0.97")

    # 3. The ISS pass.
    steps = rows_of(os.path.join(out, "iss_twilight_snr.csv"))
    check(len(steps) == 3, f"3 steps ({len(steps)})")
    for s in steps:
        sun, el = float(s["sun_elevation_deg"]), float(s["elevation_deg"])
        on, off = float(s["snr_on"]), float(s["snr_off"])
        check(-12 <= sun <= -4, f"{s['time_utc']}: Sun at {sun} deg, in twilight")
        check(el >= 5, f"{s['time_utc']}: ISS at {el} deg")
        check(0 < on < off, f"{s['time_utc']}: SNR {on} with the atmosphere below {off} without")
    if len(steps) == 3:
        ordered = sorted(steps, key=lambda s: float(s["elevation_deg"]))
        check(float(ordered[0]["air_mass"]) > float(ordered[-1]["air_mass"]) > 0,
              "air mass larger at the lower elevation")

    # The scenarios against the scenario schema (tests/cli/validate_json.py's resolver).
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(script))))
    sys.path.insert(0, os.path.join(repo, "tests", "cli"))
    from validate_json import validator_for
    validator = validator_for(os.path.join(repo, "schemas", "scenario.schema.json"))
    for scenario in ("geo_belt_night.json", "iss_twilight_pass.json"):
        with open(os.path.join(out, scenario), encoding="utf-8") as f:
            errors = [f"{'/'.join(map(str, e.path))}: {e.message[:200]}" for e in validator.iter_errors(json.load(f))]
        check(not errors, f"{scenario} against the scenario schema: {errors[:3]}")

    if eoir_exe:
        for scenario in ("geo_belt_night.json", "iss_twilight_pass.json"):
            r = subprocess.run([eoir_exe, "validate", os.path.join(out, scenario)], capture_output=True, text=True)
            print(r.stdout.strip(), r.stderr.strip())
            check(r.returncode == 0, f"eoir validate {scenario}")

    if failures:
        sys.exit(f"FAILED: {len(failures)} checks")
    print("OK")


if __name__ == "__main__":
    main()
