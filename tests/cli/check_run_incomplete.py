#!/usr/bin/env python3
"""A run that fails half-way is told from a complete one (issue 25 item 12;
plugin_host/cli/run.hpp): INCOMPLETE is written before the first frame and
an earlier summary.json removed; a failure leaves INCOMPLETE with the reason
and no summary.json beside the frames it wrote; a complete run into the same
folder writes summary.json ("complete": true) last and removes INCOMPLETE.

The scenario's ephemeris ends at 18:10; rendering on to 18:12 fails there.

usage: check_run_incomplete.py EOIR_EXE SCENARIO WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

from cli_checks import check, failures, run


def main():
    exe, scenario, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    stale = os.path.join(work, "summary.json")
    with open(stale, "w") as f:
        json.dump({"format": "eoir-run-summary", "complete": True, "frames": []}, f)  # an earlier run's
    args = [exe, "run", scenario, "--out", work, "--sensor", "Sensor1", "--quiet", "--step", "120"]

    code, out = run(*args, "--start", "2010-08-25T18:08:00Z", "--stop", "2010-08-25T18:12:00Z")
    files = sorted(os.listdir(work))
    check(code == 2 and "outside the ephemeris" in out, "the run fails at 18:12")
    check(any(f.startswith("Sensor1_0000_") for f in files) and any(f.startswith("Sensor1_0001_") for f in files),
          "frames 0 and 1 were written")
    check("summary.json" not in files, "no summary.json (the earlier run's is gone)")
    check("INCOMPLETE" in files, "INCOMPLETE marks the folder")
    if "INCOMPLETE" in files:
        text = open(os.path.join(work, "INCOMPLETE")).read()
        check("failed:" in text and "outside the ephemeris" in text, f"INCOMPLETE says why: {text.strip()}")

    code, out = run(*args, "--start", "2010-08-25T18:08:00Z", "--stop", "2010-08-25T18:10:00Z")
    files = sorted(os.listdir(work))
    check(code == 0, "a complete run into the same folder")
    check("INCOMPLETE" not in files, "INCOMPLETE removed")
    check("summary.json" in files, "summary.json written")
    if "summary.json" in files:
        summary = json.load(open(os.path.join(work, "summary.json")))
        check(summary.get("complete") is True and len(summary["frames"]) == 2, "summary: complete, 2 frames")

    if failures:
        sys.exit(f"FAILED: {len(failures)} checks: " + "; ".join(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
