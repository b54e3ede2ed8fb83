#!/usr/bin/env python3
"""The eoir command line (issue 11 item 3):
- `--name=value` gives the same output as `--name value`;
- `report` without --start/--stop covers the scenario's start..stop like
  `run` and `access` (6 rows for 18:00..18:05 every 60 s, not one);
- `--seed` reaches the engine (saved in the state) and `--threads` is taken;
- `save-state` / `load-state` round-trip a scenario through a .scd file that
  validates against scd.schema.json, at the time asked;
- `properties sensor` lists every sensor property with type, unit and the
  spec 7.6 Table 3 defaults (128 x 128 pixels, 0.5 deg, 1-4 um, F/3.5, 147 cm).

usage: check_command_line.py EOIR_EXE SOURCE_DIR WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

import jsonschema


def run(cmd, ok=True):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if ok and r.returncode != 0:
        sys.exit(f"FAILED: {' '.join(cmd)} -> exit {r.returncode}\n{r.stderr}")
    return r


def main():
    exe, src, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    static = os.path.join(src, "scenarios/validation/valid_sens_static_metrics.json")

    # --name=value and --name value agree.
    a = run([exe, "report", static, "--provider", "EOIR Sensor Optics", "--sensor", "Sensor1", "--format", "csv",
             "--quiet"])
    b = run([exe, "report", static, "--provider=EOIR Sensor Optics", "--sensor=Sensor1", "--format=csv", "--quiet"])
    assert a.stdout == b.stdout and a.stdout, (a.stdout, b.stdout)

    # report covers the scenario's start..stop.
    doc = json.loads(run([exe, "report", static, "--provider", "EOIR Sensor Spatial Performance",
                          "--sensor", "Sensor1", "--quiet"]).stdout)
    times = [r["time"] for r in doc["rows"]]
    assert times == [f"2010-08-25T18:0{m}:00Z" for m in range(6)], times
    print(f"report: {len(times)} rows {times[0]} .. {times[-1]}")

    # --seed reaches the engine; --threads is accepted.
    scd_schema = json.load(open(os.path.join(src, "schemas/scd.schema.json")))
    for seed in ("7", "12345678901234567890"):
        out = os.path.join(work, f"seed{seed}.scd")
        run([exe, "save-state", static, "--out", out, f"--seed={seed}", "--threads", "1"])
        state = json.load(open(out))
        jsonschema.validate(state, scd_schema)
        assert state["engine"]["seed"] == int(seed), state["engine"]
    out = os.path.join(work, "global.scd")
    run([exe, "--seed", "9", "save-state", static, "--out", out])
    assert json.load(open(out))["engine"]["seed"] == 9

    # save-state at a time, load-state restores it.
    out = os.path.join(work, "at1802.scd")
    r = run([exe, "save-state", static, "--out", out, "--time", "2010-08-25T18:02:00Z"])
    assert "wrote" in r.stdout, r.stdout
    state = json.load(open(out))
    jsonschema.validate(state, scd_schema)
    assert state["time"]["utc"].startswith("2010-08-25T18:02:00"), state["time"]
    r = run([exe, "load-state", out])
    assert "time: 2010-08-25T18:02:00" in r.stdout, r.stdout
    assert "Sensor1 (sensor)" in r.stdout and "Satellite1 (satellite)" in r.stdout, r.stdout
    ee = [line for line in r.stdout.splitlines() if line.strip().startswith("Ensquared Energy")]
    assert ee and abs(float(ee[0].split()[2]) - 0.9683) < 5e-4, ee
    bad = run([exe, "load-state", os.path.join(src, "tests/cli/data/malformed.json")], ok=False)
    assert bad.returncode == 2 and "EOIR_ERR_CORRUPT_FILE" in bad.stderr, bad.stderr

    # properties sensor: every property, Table 3 defaults.
    props = json.loads(run([exe, "properties", "sensor", "--format", "json"]).stdout)["properties"]
    by = {p["name"]: p for p in props}
    want = {"horizontal_pixels": ("integer", 128), "vertical_pixels": ("integer", 128),
            "horizontal_fov_deg": ("number", 0.5), "band_low_um": ("number", 1.0),
            "band_high_um": ("number", 4.0), "f_number": ("number", 3.5), "focal_length_cm": ("number", 147.0)}
    for name, (typ, default) in want.items():
        assert by[name]["type"] == typ and by[name]["default"] == default, by[name]
    assert by["horizontal_fov_deg"]["unit"] == "deg" and by["band_low_um"]["unit"] == "um"
    assert len(props) >= 25 and all(p["description"] for p in props), len(props)
    table = run([exe, "properties", "satellite"]).stdout
    assert "temperature_K" in table and "material" in table, table
    bad = run([exe, "properties", "satelite"], ok=False)
    assert bad.returncode == 1 and "did you mean 'satellite'" in bad.stderr, bad.stderr
    print(f"properties: {len(props)} sensor properties")
    print("passed")


if __name__ == "__main__":
    main()
