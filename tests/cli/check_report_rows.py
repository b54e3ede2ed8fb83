#!/usr/bin/env python3
"""Reports over time: `--start/--stop/--step` give every step with the stop
included, JSON (to --out) and CSV agree, curves carry x and x_unit.

usage: check_report_rows.py EOIR_EXE SCENARIO REPORT_SCHEMA
"""
import csv
import io
import json
import os
import subprocess
import sys
import tempfile

import jsonschema


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAILED: {' '.join(cmd)} -> exit {r.returncode}\n{r.stderr}")
    return r


def main():
    exe, scenario, schema_file = sys.argv[1:4]
    schema = json.load(open(schema_file))
    base = [exe, "report", scenario, "--sensor", "Sensor1", "--start", "2010-08-25T18:00:00Z",
            "--stop", "2010-08-25T18:09:00Z", "--step", "120", "--quiet"]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "optics.json")
        r = run(base + ["--provider", "EOIR Sensor Optics", "--format", "json", "--out", out])
        assert r.stdout == "", "with --out nothing goes to stdout"
        doc = json.load(open(out))
    jsonschema.validate(doc, schema)
    times = [row["time"] for row in doc["rows"]]
    want = ["2010-08-25T18:00:00Z", "2010-08-25T18:02:00Z", "2010-08-25T18:04:00Z", "2010-08-25T18:06:00Z",
            "2010-08-25T18:08:00Z", "2010-08-25T18:09:00Z"]
    assert times == want, times
    otf = doc["rows"][0]["values"]["Diffraction OTF"]
    assert otf["x_unit"] == "cycles/mrad" and len(otf["x"]) == len(otf["value"]) > 1, otf.keys()
    assert abs(otf["value"][0] - 1.0) < 1e-9, otf["value"][0]

    r = run(base + ["--provider", "EOIR Radiometric Performance", "--format", "csv"])
    rows = list(csv.reader(io.StringIO(r.stdout)))
    assert rows[0][0] == "time" and "Dark NEI [W/cm^2]" in rows[0], rows[0]
    assert [row[0] for row in rows[1:]] == want, rows
    nei = rows[0].index("Dark NEI [W/cm^2]")
    assert all(abs(float(row[nei]) - 1e-18) < 1e-21 for row in rows[1:])
    r = run(base + ["--provider", "EOIR Sensor Optics", "--format", "csv"])
    assert "curve elements are not written to CSV" in r.stderr, r.stderr
    print("passed")


if __name__ == "__main__":
    main()
