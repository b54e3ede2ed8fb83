#!/usr/bin/env python3
"""Scenario numbers the messages used to mislead about (issue 25 item 11):
- a semi-major axis of 1e308 km was told "must be positive": it is refused
  for its apogee beyond the engine's 1e14 m, quoting the value;
- a time step of 1e-300 s passed `validate` and failed `report`: both refuse
  it alike (below the 1 ms resolution of times), as they refuse a step count
  beyond the report's limit, and --step likewise;
- a field of view of 179.9999 deg is quoted as such (it was "got 180"
  against the 179.9 limit).

usage: check_scenario_numbers.py EOIR_EXE BASE_SCENARIO WORK_DIR
"""
import copy
import json
import os
import shutil
import subprocess
import sys

from cli_checks import check, failures, run


def main():
    exe, base_path, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    base = json.load(open(base_path))
    kepler = next(i for i, o in enumerate(base["objects"]) if o["motion"]["type"] == "kepler")
    sensor = base["sensors"][0]["name"]

    def write(name, change):
        doc = copy.deepcopy(base)
        change(doc)
        path = os.path.join(work, name + ".json")
        with open(path, "w") as f:
            json.dump(doc, f)
        return path

    def report(path, *extra):
        return run(exe, "report", path, "--provider", "EOIR Sensor Optics", "--sensor", sensor, "--quiet", *extra)

    path = write("huge_orbit", lambda d: d["objects"][kepler]["motion"].update(semi_major_axis_km=1e308))
    code, out = run(exe, "validate", path)
    want = f"objects[{kepler}].motion.semi_major_axis_km: 1e+308 km puts the apogee beyond 1e11 km"
    check(code == 2 and want in out and "must be positive" not in out, f"1e308 km: {out.strip()[-160:]}")

    path = write("tiny_step", lambda d: d.update(step_s=1e-300))
    want = "step_s: 1e-300 s is below the 1 ms resolution of times"
    for name, (code, out) in {"validate": run(exe, "validate", path), "report": report(path)}.items():
        check(code == 2 and want in out, f"{name} refuses step_s 1e-300: {out.strip()[-160:]}")
    code, out = report(base_path, "--step", "1e-300")
    check(code == 1 and "--step: 1e-300 s is below the 1 ms resolution of times" in out, "--step 1e-300 refused")

    path = write("many_steps", lambda d: d.update(start="2010-01-01T00:00:00Z", stop="2010-12-31T00:00:00Z",
                                                  step_s=0.001))
    for name, (code, out) in {"validate": run(exe, "validate", path), "report": report(path)}.items():
        check(code != 0 and "more than 10000000 time steps" in out, f"{name} refuses 3e10 steps: {out.strip()[-120:]}")

    path = write("fov", lambda d: d["sensors"][0].setdefault("parameters", {}).update(horizontal_fov_deg=179.9999))
    code, out = run(exe, "validate", path)
    check(code == 2 and "got 179.9999" in out, f"179.9999 deg quoted: {out.strip()[-160:]}")

    if failures:
        sys.exit(f"FAILED: {len(failures)} checks: " + "; ".join(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
