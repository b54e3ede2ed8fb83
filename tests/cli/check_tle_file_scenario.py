#!/usr/bin/env python3
"""A scenario whose satellites come from a file of two-line element sets
(issue 23 item 3): `eoir validate` and `eoir run` on a generated belt.

usage: check_tle_file_scenario.py EOIR_EXE SCHEMA_DIR OUT_DIR

The file holds 20 sets, "GEO 00" to "GEO 19" (title lines in the three-line
form "0 NAME" for half of them): the elements of SGP4-VER.TLE's near-
geostationary 14128 with their own satellite numbers and mean anomalies
0.1 deg apart (checksums recomputed). The scenario raises max_satellites to
20 (`limits`); a camera on GEO 00 tracks GEO 19, 1.9 deg of arc ahead, with
a 10 deg field: every other satellite lies within 1 deg of its line of sight.

- the scenario validates against schemas/scenario.schema.json; `validate`
  and `run` succeed; the truth of each frame lists GEO 01 to GEO 19, each
  once (its own parent is never imaged), and validates against
  schemas/truth.schema.json;
- without `limits` the 17th satellite is refused naming max_satellites;
- a corrupt set (inclination 181 in the 8th set's line 2, line 24 of the
  file) is refused naming tle_file and the line; a tle_file outside the
  scenario's folder is refused naming the field.
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from validate_json import validator_for  # noqa: E402

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    print(f"$ {' '.join(cmd)}\nexit {r.returncode}\n{r.stdout[-1500:]}{r.stderr[-1500:]}")
    if r.returncode < 0:
        sys.exit(f"FAILED: killed by signal {-r.returncode}")
    return r


def checksum(first_68):
    return first_68 + str(sum(int(c) if c.isdigit() else (1 if c == "-" else 0) for c in first_68) % 10)


L1 = "1 14128U 83058A   06176.02844893 -.00000158  00000-0  10000-3 0  9627"
L2 = "2 14128  11.4384  35.2134 0011562  26.4582 333.5652  0.98870114 46093"


def tle_set(k, inclination=None):
    num = f"{20000 + k:05d}"
    l1 = checksum(L1[:2] + num + L1[7:68])
    l2 = L2[:2] + num + L2[7:43] + f"{(333.5652 + 0.1 * k) % 360:8.4f}" + L2[51:68]
    if inclination is not None:
        l2 = l2[:8] + inclination + l2[16:]
    title = f"0 GEO {k:02d}" if k % 2 else f"GEO {k:02d}"
    return [title, l1, checksum(l2)]


def scenario(tle_file, limits=True):
    sc = {
        "format": "eoir-scenario", "version": 1, "name": "belt from a TLE file",
        "start": "2006-06-25T12:00:00Z", "stop": "2006-06-25T12:10:00Z", "step_s": 600,
        "central_bodies": ["Earth"],
        "objects": [{"tle_file": tle_file, "kind": "satellite",
                     "properties": {"shape": "sphere", "dimensions_m": [2.0]}}],
        "sensors": [{"name": "Cam", "parent": "GEO 00", "pointing": {"type": "target", "target": "GEO 19"},
                     "parameters": {"horizontal_pixels": 64, "vertical_pixels": 64,
                                    "horizontal_fov_deg": 10.0, "vertical_fov_deg": 10.0}}],
    }
    if limits:
        sc["limits"] = {"max_satellites": 20}
    return sc


def main():
    exe, schema_dir, out = sys.argv[1:4]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    lines = [line for k in range(20) for line in tle_set(k)]
    with open(os.path.join(out, "belt.tle"), "w") as f:
        f.write("\n".join(lines) + "\n")
    bad = [line for k in range(20) for line in tle_set(k, "181.0000" if k == 7 else None)]
    with open(os.path.join(out, "bad.tle"), "w") as f:
        f.write("\n".join(bad) + "\n")
    paths = {}
    for name, doc in [("belt", scenario("belt.tle")), ("no_limits", scenario("belt.tle", False)),
                      ("bad", scenario("bad.tle")), ("outside", scenario("../belt.tle"))]:
        paths[name] = os.path.join(out, name + ".json")
        with open(paths[name], "w") as f:
            json.dump(doc, f, indent=1)

    errors = list(validator_for(os.path.join(schema_dir, "scenario.schema.json")).iter_errors(scenario("belt.tle")))
    check(not errors, f"the scenario validates against its schema: {[e.message for e in errors]}")

    check(run([exe, "validate", paths["belt"]]).returncode == 0, "validate accepts the TLE-file scenario")
    frames = os.path.join(out, "run")
    r = run([exe, "run", paths["belt"], "--out", frames, "--quiet"])
    check(r.returncode == 0, "run succeeds")
    truth_v = validator_for(os.path.join(schema_dir, "truth.schema.json"))
    with open(os.path.join(frames, "summary.json")) as f:
        summary = json.load(f)
    check(len(summary["frames"]) == 2, f"two frames, got {len(summary['frames'])}")
    expected = sorted(f"GEO {k:02d}" for k in range(1, 20))
    for fr in summary["frames"]:
        with open(os.path.join(frames, fr["files"]["truth"])) as f:
            truth = json.load(f)
        errors = list(truth_v.iter_errors(truth))
        check(not errors, f"{fr['files']['truth']} validates: {[e.message for e in errors[:3]]}")
        names = sorted(t["object"] for t in truth if t["kind"] == "object")
        check(names == expected, f"{fr['files']['truth']} lists GEO 01 to GEO 19 once each: {names}")

    r = run([exe, "validate", paths["no_limits"]])
    check(r.returncode != 0 and "max_satellites" in r.stdout + r.stderr,
          "without limits the 17th satellite is refused naming max_satellites")
    r = run([exe, "validate", paths["bad"]])
    text = r.stdout + r.stderr
    check(r.returncode != 0 and "objects[0].tle_file" in text and "line 24" in text and "inclination" in text,
          "a corrupt set is refused naming tle_file, line 24 and the field")
    r = run([exe, "validate", paths["outside"]])
    check(r.returncode != 0 and "objects[0].tle_file" in r.stdout + r.stderr and "outside" in r.stdout + r.stderr,
          "a tle_file outside the scenario's folder is refused")

    if failures:
        sys.exit(f"FAILED: {len(failures)} checks")
    print("OK")


if __name__ == "__main__":
    main()
