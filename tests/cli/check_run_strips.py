#!/usr/bin/env python3
"""`eoir run` of frames made in strips (issue 23 item 2): with the sensor's
scene_memory_max_mib at 0 every frame is made in strips; the run says so
once, writes no scene radiance FITS and no scene PNG (summary.json lists
neither), and its electrons and mean electrons equal the whole-frame run's
to 1e-9 relative (noise off).

usage: check_run_strips.py EOIR_EXE SCENARIO WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np
from astropy.io import fits

from cli_checks import check, failures


def run_scenario(exe, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    r = subprocess.run([exe, "run", scenario, "--out", out], capture_output=True, text=True, timeout=600)
    check(r.returncode == 0, f"eoir run {os.path.basename(scenario)} succeeds ({(r.stdout + r.stderr).strip()[-300:]})")
    return r.stderr, json.load(open(os.path.join(out, "summary.json")))


def main(exe, scenario, work):
    os.makedirs(work, exist_ok=True)
    _, whole = run_scenario(exe, scenario, os.path.join(work, "whole"))
    doc = json.load(open(scenario))
    for s in doc["sensors"]:
        s["parameters"]["scene_memory_max_mib"] = 0
    doc.pop("$schema", None)
    strips_scenario = os.path.join(work, "strips.json")
    json.dump(doc, open(strips_scenario, "w"))
    said, strips = run_scenario(exe, strips_scenario, os.path.join(work, "strips"))
    check(said.count("made in strips") == len(doc["sensors"]), "the run says once per sensor that it makes strips")
    check(len(strips["frames"]) == len(whole["frames"]) > 0, f"{len(strips['frames'])} frames")
    for a, b in zip(whole["frames"], strips["frames"]):
        check("radiance" not in b["files"] and "scene_png" not in b["files"], "no scene radiance or PNG listed")
        check(not os.path.exists(os.path.join(work, "strips", a["files"]["radiance"])), "no scene radiance file")
        for key in ("electrons", "mean_electrons"):
            x = fits.getdata(os.path.join(work, "whole", a["files"][key])).astype(float)
            y = fits.getdata(os.path.join(work, "strips", b["files"][key])).astype(float)
            scale = np.maximum(np.abs(x), 1e-6 * np.abs(x).max())
            worst = float(np.max(np.abs(x - y) / scale))
            check(np.abs(x).max() > 0 and worst <= 1e-6,
                  f"{key} of frame {a['index']}: largest relative difference {worst:.2g} (float32 files)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
