#!/usr/bin/env python3
"""The vehicle demo (issue 22 item 5) in its quick mode: a small frame of
scenarios/demo/vehicle_demos.py, which must complete and write its
picture, table and scenario.

usage: check_vehicle_demos.py DEMO_SCRIPT OUT_DIR [EOIR_EXE]

- the script exits 0;
- aircraft_leo.png opens (PIL) and is not blank;
- aircraft_leo.csv: the aircraft is in the frame (samples brighter than
  the ground without it) and so is its shadow (samples darker than half the
  bare ground's), shadowed ground at most 1/3 of the mean ground (the
  desert's skylight-free shadow in vacuum holds no direct sunlight);
- aircraft_leo.json passes the scenario schema and `eoir validate` (when
  EOIR_EXE is given).
"""
import csv
import json
import os
import subprocess
import sys
import time

failures = []
OUTPUTS = ("aircraft_leo.png", "aircraft_leo.csv", "aircraft_leo.json")


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    script, out = sys.argv[1], sys.argv[2]
    eoir_exe = sys.argv[3] if len(sys.argv) == 4 else None
    os.makedirs(out, exist_ok=True)
    for name in OUTPUTS:
        if os.path.exists(os.path.join(out, name)):
            os.unlink(os.path.join(out, name))
    t0 = time.time()
    r = subprocess.run([sys.executable, script, "--quick", "--out", out], capture_output=True, text=True)
    print(r.stdout[-4000:], r.stderr[-3000:])
    print(f"exit {r.returncode} after {time.time() - t0:.1f} s")
    check(r.returncode == 0, "the demo script exits 0")
    for name in OUTPUTS:
        check(os.path.exists(os.path.join(out, name)), f"{name} written")
    if failures:
        sys.exit(f"FAILED: {len(failures)} checks")

    from PIL import Image
    with Image.open(os.path.join(out, "aircraft_leo.png")) as im:
        lo, hi = im.convert("L").getextrema()
        check(hi > lo, "aircraft_leo.png is not blank")

    with open(os.path.join(out, "aircraft_leo.csv"), encoding="utf-8") as f:
        rows = {r["quantity"]: float(r["value"]) for r in csv.DictReader(line for line in f if not line.startswith("#"))}
    check(rows["ground_mean"] > 0, f"the ground is lit ({rows['ground_mean']})")
    check(rows["aircraft_samples"] > 0, "the aircraft is in the frame")
    check(rows["shadow_samples"] > 0, "its shadow is in the frame")
    if rows["shadow_samples"] > 0:
        check(rows["shadow_mean"] <= rows["ground_mean"] / 3,
              f"shadowed ground {rows['shadow_mean']} against {rows['ground_mean']}")

    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(script))))
    sys.path.insert(0, os.path.join(repo, "tests", "cli"))
    from validate_json import validator_for
    validator = validator_for(os.path.join(repo, "schemas", "scenario.schema.json"))
    with open(os.path.join(out, "aircraft_leo.json"), encoding="utf-8") as f:
        errors = [f"{'/'.join(map(str, e.path))}: {e.message[:200]}" for e in validator.iter_errors(json.load(f))]
    check(not errors, f"aircraft_leo.json against the scenario schema: {errors[:3]}")
    if eoir_exe:
        r = subprocess.run([eoir_exe, "validate", os.path.join(out, "aircraft_leo.json")], capture_output=True,
                           text=True)
        print(r.stdout.strip(), r.stderr.strip())
        check(r.returncode == 0, "eoir validate aircraft_leo.json")

    if failures:
        sys.exit(f"FAILED: {len(failures)} checks")
    print("OK")


if __name__ == "__main__":
    main()
