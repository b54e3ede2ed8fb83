#!/usr/bin/env python3
"""`eoir pick`: eq. 9 term by term (spec 4.1.5.3; issue 20 item 5).

Over the subsolar point (tests/cli/data/pick_earth.json, a visible and an
8-12 um sensor looking at the nadir from 700 km):
  - vacuum (the scenario as it is): transmittance 1, path terms 0,
    at_sensor = surface, no DownWelling;
  - atmosphere (a copy with the Earth's `atmosphere` = simple, DownWelling
    on by default): every interval obeys eq. 9, at_sensor = surface x
    transmittance + path_thermal + path_scatter (1e-12 relative: the engine
    sums the same doubles); 0 < T < 1; sunlight scattered in the visible,
    the air's emission in 8-12 um, DownWelling part of what leaves the
    surface; less light through the air than in vacuum in the visible;
  - CSV and JSON (schemas/pick.schema.json) carry the same numbers, --out
    writes the file and nothing to stdout, --time moves the frame (local
    midnight: no sunlight, no scatter);
  - bad input: exit status 1 and a message naming the option (unknown
    sensor, x or y outside the frame, bad space, format, index or time), 2
    for a missing scenario file.

usage: check_pick.py EOIR_EXE SCENARIO PICK_SCHEMA WORK_DIR
"""
import csv
import io
import json
import os
import re
import subprocess
import sys

import jsonschema

TERMS = ("surface", "downwelling", "transmittance", "path_thermal", "path_scatter", "at_sensor")


def run(cmd, status=0):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != status:
        sys.exit(f"FAILED: {' '.join(cmd)} -> exit {r.returncode} (expected {status})\n{r.stdout}\n{r.stderr}")
    return r


def pick_json(exe, scenario, schema, *args):
    doc = json.loads(run([exe, "pick", scenario, "--format", "json", *args]).stdout)
    jsonschema.validate(doc, schema)
    n = len(doc["columns"]["wavelength_um"])
    assert all(len(doc["columns"][t]) == n for t in TERMS), {t: len(doc["columns"][t]) for t in TERMS}
    return doc


def check_vacuum(doc):
    c = doc["columns"]
    assert doc["hit"] and doc["object"] == "Earth", (doc["hit"], doc["object"])
    assert abs(doc["latitude_deg"] - 5.379281) < 0.05 and abs(doc["longitude_deg"]) < 0.05, doc
    for i, _ in enumerate(c["wavelength_um"]):
        assert c["transmittance"][i] == 1.0 and c["path_thermal"][i] == 0.0 and c["path_scatter"][i] == 0.0, i
        assert c["downwelling"][i] == 0.0 and c["at_sensor"][i] == c["surface"][i], i
    assert max(c["surface"]) > 0


def check_identity(doc):
    """eq. 9 per interval; returns the columns."""
    c = doc["columns"]
    for i, wl in enumerate(c["wavelength_um"]):
        s, t, th, sc, at = (c[k][i] for k in ("surface", "transmittance", "path_thermal", "path_scatter", "at_sensor"))
        assert abs(at - (s * t + th + sc)) <= 1e-12 * max(abs(at), 1e-300), (wl, at, s * t + th + sc)
        assert 0.0 < t < 1.0, (wl, t)
        assert th >= 0.0 and sc >= 0.0 and 0.0 <= c["downwelling"][i] <= s, (wl, th, sc, c["downwelling"][i], s)
    return c


def main():
    exe, scenario, schema_file, work = sys.argv[1:5]
    schema = json.load(open(schema_file))
    os.makedirs(work, exist_ok=True)
    centre = ["--x", "2", "--y", "2", "--space", "pixel"]

    vacuum = {s: pick_json(exe, scenario, schema, "--sensor", s, *centre) for s in ("Vis", "LWIR")}
    for doc in vacuum.values():
        check_vacuum(doc)

    doc = json.load(open(scenario))
    doc["central_bodies"][0]["properties"]["atmosphere"] = "simple"
    air_scenario = os.path.join(work, "pick_earth_atmosphere.json")
    with open(air_scenario, "w") as f:
        json.dump(doc, f, indent=2)
    air = {s: pick_json(exe, air_scenario, schema, "--sensor", s, *centre) for s in ("Vis", "LWIR")}
    vis, lwir = check_identity(air["Vis"]), check_identity(air["LWIR"])
    assert min(vis["path_scatter"]) > 0 and min(vis["downwelling"]) > 0, (vis["path_scatter"], vis["downwelling"])
    assert min(lwir["path_thermal"]) > 0, lwir["path_thermal"]
    # Rayleigh scatter falls with wavelength: more at 0.425 um than at 0.875 um.
    assert vis["path_scatter"][0] > vis["path_scatter"][-1], vis["path_scatter"]
    assert air["Vis"]["effective_radiance_W_cm2_sr"] != vacuum["Vis"]["effective_radiance_W_cm2_sr"]
    assert sum(vis["surface"][i] * vis["transmittance"][i] for i in range(10)) < sum(vacuum["Vis"]["columns"]["surface"])

    # CSV: the header names what was hit; the rows are the JSON's numbers.
    text = run([exe, "pick", air_scenario, "--sensor", "Vis", *centre]).stdout
    header = [line for line in text.splitlines() if line.startswith("#")]
    assert any(re.match(r"# hit: Earth \(patch -?\d+\), range 7\d{5}\.\d{3} m", h) for h in header), header
    assert any(h.startswith("# latitude 5.3") for h in header) and any("effective radiance" in h for h in header), header
    rows = list(csv.reader(io.StringIO("\n".join(line for line in text.splitlines() if not line.startswith("#")))))
    assert rows[0] == ["wavelength_um", *TERMS], rows[0]
    assert len(rows) == 11, len(rows)
    for i, row in enumerate(rows[1:]):
        assert float(row[0]) == vis["wavelength_um"][i], row
        assert [float(v) for v in row[1:]] == [vis[t][i] for t in TERMS], row

    # --out writes the file atomically and nothing to stdout.
    out = os.path.join(work, "pick_vis.json")
    r = run([exe, "pick", air_scenario, "--sensor", "Vis", *centre, "--format", "json", "--out", out])
    assert r.stdout == "" and json.load(open(out)) == air["Vis"], r.stdout

    # --time: at local midnight over the same point no sunlight reaches it.
    night = pick_json(exe, air_scenario, schema, "--sensor", "Vis", *centre, "--time", "2010-04-03T00:03:19Z")
    assert night["time"] == "2010-04-03T00:03:19Z", night["time"]
    assert max(night["columns"]["path_scatter"]) == 0.0, night["columns"]["path_scatter"]
    assert max(night["columns"]["at_sensor"]) < 1e-6 * min(vis["at_sensor"]), night["columns"]["at_sensor"]

    # Bad input: status 1 and the option named; 2 for an unreadable scenario.
    base = [exe, "pick", scenario]
    bad = [
        (base + ["--sensor", "Vsi", *centre], 1, r"--sensor: unknown sensor 'Vsi' in .*pick_earth\.json \(did you mean 'Vis'\?\); sensors: 'Vis', 'LWIR'"),
        (base + ["--sensor", "Vis", "--x", "5", "--y", "2", "--space", "pixel"], 1,
         r"--x: 5 is outside the frame of sensor 'Vis' \(5 pixels across: 0-4\)"),
        (base + ["--sensor", "Vis", "--x", "0", "--y", "20"], 1,
         r"--y: 20 is outside the frame of sensor 'Vis' \(20 scene samples down: 0-19\)"),
        (base + ["--sensor", "Vis", "--x", "-1", "--y", "0"], 1, r"--x: '-1' is not a non-negative integer"),
        (base + ["--sensor", "Vis", "--x", "1.5", "--y", "0"], 1, r"--x: '1\.5' is not a non-negative integer"),
        (base + ["--sensor", "Vis", "--x", "0", "--y", "0", "--space", "voxel"], 1, r"--space: 'voxel' is not sample or pixel"),
        (base + ["--sensor", "Vis", "--x", "0", "--y", "0", "--format", "xml"], 1, r"--format: 'xml' is not csv or json"),
        (base + ["--sensor", "Vis", "--x", "0", "--y", "0", "--time", "noon"], 1, r"--time: 'noon' is not an ISO-8601"),
        (base + ["--sensor", "Vis", "--y", "0"], 1, r"pick: missing --x N"),
        (base + ["--x", "0", "--y", "0"], 1, r"pick: missing --sensor NAME"),
        ([exe, "pick", os.path.join(work, "no_such.json"), "--sensor", "Vis", "--x", "0", "--y", "0"], 2,
         r"no_such\.json: cannot open"),
    ]
    for cmd, status, pattern in bad:
        r = run(cmd, status)
        assert re.search(pattern, r.stderr), f"{' '.join(cmd)}: stderr does not match /{pattern}/:\n{r.stderr}"
        assert r.stdout == "", r.stdout
    print("vacuum and atmosphere picks: eq. 9 holds in %d + %d intervals; Vis at_sensor/vacuum %.3f" % (
        len(vis["at_sensor"]), len(lwir["at_sensor"]),
        air["Vis"]["effective_radiance_W_cm2_sr"] / vacuum["Vis"]["effective_radiance_W_cm2_sr"]))
    print("passed")


if __name__ == "__main__":
    main()
