#!/usr/bin/env python3
"""Spec 7.6 (Valid_Sens_StaticMetrics): every static metric of the four static
groups, reported by `eoir report ... --format json`, matches Table 3 within
0.1 % (ensquared energy 0.9683 +- 0.0005, spec 7.6 step 4 and 7.5.5), and the
JSON validates against schemas/report.schema.json.

usage: check_static_metrics.py EOIR_EXE SCENARIO REPORT_SCHEMA
"""
import json
import subprocess
import sys

import jsonschema

# Spec 7.6 Table 3, by data-provider group and element.
TABLE3 = {
    "EOIR Sensor Spatial Performance": {
        "Number of Horizontal Pixels": 128,
        "Number of Vertical Pixels": 128,
        "FOV Solid Angle": 7.6154e-5,          # sr
        "Horizontal FOV": 0.5,                 # deg
        "Vertical FOV": 0.5,                   # deg
        "IFOV Solid Angle": 4.648e-9,          # sr
        "Horizontal IFOV": 6.818e-2,           # mrad
        "Vertical IFOV": 6.818e-2,             # mrad
        "Effective FOV Solid Angle": 7.865e-5, # sr
        "Effective Horizontal FOV": 0.5081,    # deg
        "Effective Vertical FOV": 0.5081,      # deg
        "Effective IFOV Solid Angle": 4.80e-9, # sr
        "Effective Horizontal IFOV": 6.928e-2, # mrad
        "Effective Vertical IFOV": 6.928e-2,   # mrad
    },
    "EOIR Sensor Spectral Performance": {
        "Low Band Edge Wavelength": 1.0,       # um
        "High Band Edge Wavelength": 4.0,      # um
    },
    "EOIR Radiometric Performance": {
        "Peak Irradiance Responsivity": 5.295e19,  # e-/(W/cm^2)
        "Dark NEI": 1.0e-18,                       # W/cm^2
        "SEI": 1.0e-15,                            # W/cm^2
        "Peak Radiance Responsivity": 2.542e11,    # e-/(W/(cm^2 sr))
        "Dark NER": 2.083e-10,                     # W/(cm^2 sr)
        "SER": 2.083e-7,                           # W/(cm^2 sr)
    },
    "EOIR Sensor Optics": {
        "Effective Focal Length": 147.0,       # cm
        "F-number": 3.5,
        "Diffraction Wavelength": 2.5,         # um
        "Airy Disk Diameter": 1.452e-2,        # mrad
        "Rayleigh Resolution": 7.262e-3,       # mrad
        "Sparrow Resolution": 5.952e-3,        # mrad
    },
}
ENSQUARED = ("EOIR Sensor Optics", "Ensquared Energy", 0.9683, 0.0005)
REL_TOL = 1e-3


def report(exe, scenario, group):
    cmd = [exe, "report", scenario, "--provider", group, "--sensor", "Sensor1", "--format", "json"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"FAILED: {' '.join(cmd)} -> exit {run.returncode}\n{run.stderr}")
    return json.loads(run.stdout)


def main():
    exe, scenario, schema_file = sys.argv[1:4]
    with open(schema_file) as f:
        schema = json.load(f)
    failures = 0
    for group, expected in TABLE3.items():
        doc = report(exe, scenario, group)
        jsonschema.validate(doc, schema)
        assert doc["provider"] == group and doc["sensor"] == "Sensor1" and doc["target"] is None
        # The scenario's start..stop (18:00..18:05 every 60 s); static metrics
        # do not change with time: the last row is checked like the first.
        assert len(doc["rows"]) == 6, f"6 rows (scenario start..stop) expected, got {len(doc['rows'])}"
        assert doc["rows"][-1]["values"] == doc["rows"][0]["values"]
        values = doc["rows"][0]["values"]
        checks = [(name, value, REL_TOL * abs(value)) for name, value in expected.items()]
        if group == ENSQUARED[0]:
            checks.append((ENSQUARED[1], ENSQUARED[2], ENSQUARED[3]))
        for name, want, tol in checks:
            if name not in values:
                print(f"FAIL {group} / {name}: missing (elements: {sorted(values)})")
                failures += 1
                continue
            got = values[name]["value"]
            ok = isinstance(got, (int, float)) and not isinstance(got, bool) and abs(got - want) <= tol
            print(f"{'ok  ' if ok else 'FAIL'} {group} / {name}: {got!r} [{values[name]['unit']}]"
                  f" vs Table 3 {want!r}")
            failures += not ok
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
