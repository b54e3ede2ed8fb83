#!/usr/bin/env python3
"""Per-frame truth of `eoir run`: <sensor>_<NNNN>_truth.json beside each frame.

usage: check_run_truth.py EOIR_EXE SCENARIO_DIR SCHEMA_DIR OUT_DIR

- 7.7.2 (valid_sens_point_src_target.json, 127 x 127 pixels, the sensor
  points at Satellite2): every frame lists Satellite2 alone, at the centre
  pixel (63, 63), as a visible point source with SNR = irradiance / NEI and
  the range and SNR of the Sensor-to-Target report at that time;
- 7.8 (valid_sens_snr_access.json): at 22:20 (inside the first access
  interval) Satellite2 is listed with SNR >= 6, equal to the report's;
- the truth files validate against schemas/truth.schema.json and
  summary.json (which names them) against schemas/run_summary.schema.json.
"""
import json
import os
import shutil
import subprocess
import sys

import jsonschema

GROUP = "EOIR Sensor-to-Target Metrics"


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAILED: {' '.join(cmd)}: exit {r.returncode}\n{r.stdout}\n{r.stderr}")
    return r


def validator(path):
    with open(path) as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def run_and_load(exe, scenario, out, start, stop, step, summary_v, truth_v):
    shutil.rmtree(out, ignore_errors=True)
    run([exe, "run", scenario, "--out", out, "--start", start, "--stop", stop, "--step", step, "--quiet"])
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    summary_v.validate(summary)
    frames = []
    for fr in summary["frames"]:
        name = fr["files"]["truth"]
        assert name == f"{fr['sensor']}_{fr['index']:04d}_truth.json", name
        with open(os.path.join(out, name)) as f:
            truth = json.load(f)
        truth_v.validate(truth)
        frames.append((fr, truth))
    return frames


def report_at(exe, scenario, time):
    r = run([exe, "report", scenario, "--provider", GROUP, "--sensor", "Sensor1", "--target", "Satellite2",
             "--start", time, "--format", "json", "--quiet"])
    return {k: v["value"] for k, v in json.loads(r.stdout)["rows"][0]["values"].items()}


def main():
    exe, scenario_dir, schema_dir, out_dir = sys.argv[1:5]
    summary_v = validator(os.path.join(schema_dir, "run_summary.schema.json"))
    truth_v = validator(os.path.join(schema_dir, "truth.schema.json"))
    failures = 0

    # 7.7.2: the target on the boresight of a 127 x 127 sensor.
    sc = os.path.join(scenario_dir, "validation", "valid_sens_point_src_target.json")
    frames = run_and_load(exe, sc, os.path.join(out_dir, "truth_772"), "2010-08-03T16:00:00Z",
                          "2010-08-03T16:10:00Z", "300", summary_v, truth_v)
    assert len(frames) == 3, len(frames)
    for fr, truth in frames:
        rep = report_at(exe, sc, fr["time"])
        objs = [t["object"] for t in truth]
        ok = objs == ["Satellite2"]
        if ok:
            t = truth[0]
            ok = (abs(t["pixel_x"] - 63.0) < 0.05 and abs(t["pixel_y"] - 63.0) < 0.05 and t["point_source"]
                  and t["visible"] and t["effective_radiance"] == 0.0
                  and close(t["range_m"], rep["Range to Target"] * 1e3, 1e-9)
                  and close(t["snr"], rep["Signal to Noise Ratio"], 1e-9)
                  and close(t["snr"], t["effective_irradiance"] / rep["Total NEI"], 1e-9))
        print(f"{'ok  ' if ok else 'FAIL'} 7.7.2 frame {fr['index']} {fr['time']}: {truth}")
        failures += not ok

    # 7.8: inside the first access interval (SNR >= 6 against space).
    sc = os.path.join(scenario_dir, "validation", "valid_sens_snr_access.json")
    frames = run_and_load(exe, sc, os.path.join(out_dir, "truth_78"), "2010-12-08T22:20:00Z",
                          "2010-12-08T22:20:00Z", "60", summary_v, truth_v)
    fr, truth = frames[0]
    rep = report_at(exe, sc, fr["time"])
    ok = ([t["object"] for t in truth] == ["Satellite2"] and truth[0]["snr"] >= 6.0
          and close(truth[0]["snr"], rep["Signal to Noise Ratio"], 1e-9)
          and 0 <= truth[0]["pixel_x"] <= 255 and 0 <= truth[0]["pixel_y"] <= 255 and truth[0]["visible"])
    print(f"{'ok  ' if ok else 'FAIL'} 7.8 frame {fr['time']}: {truth}")
    failures += not ok
    print(f"{failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
