#!/usr/bin/env python3
"""`eoir access` (spec 7.8 SNR access constraint) against `eoir report`.

usage: check_access.py EOIR_EXE SCENARIO ACCESS_SCHEMA

Runs `eoir access --min-snr 6` and the 60 s Sensor-to-Target report of the
same day, and checks that
  - the JSON validates against schemas/access.schema.json, and the CSV
    output lists the same intervals;
  - every report row inside an interval has SNR >= 6 and every row outside
    has SNR < 6;
  - each boundary lies strictly between the two report steps that bracket
    the crossing (clipped boundaries excepted);
  - reports at the boundary and +-2 ms (three rows, --step 0.002) give
    SNR >= 6 at the boundary and just inside, SNR < 6 just outside.
"""
import csv
import datetime as dt
import io
import json
import subprocess
import sys

import jsonschema

MIN_SNR = 6.0
START, STOP = "2010-12-08T22:00:00Z", "2010-12-09T22:00:00Z"
GROUP = "EOIR Sensor-to-Target Metrics"
SNR = "Signal to Noise Ratio"


def parse(iso):
    return dt.datetime.strptime(iso.replace("Z", "+0000"),
                                "%Y-%m-%dT%H:%M:%S.%f%z" if "." in iso else "%Y-%m-%dT%H:%M:%S%z")


def iso_ms(t):
    return t.astimezone(dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%S.%f")[:-3] + "Z"


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAILED: {' '.join(cmd)}: exit {r.returncode}\n{r.stderr}")
    return r


def main():
    exe, scenario, schema_file = sys.argv[1:4]
    base = [exe, "access", scenario, "--sensor", "Sensor1", "--target", "Satellite2", "--min-snr", "6",
            "--start", START, "--stop", STOP, "--step", "60"]
    r = run(base + ["--format", "json"])
    doc = json.loads(r.stdout)
    print(r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "(no stderr)")
    with open(schema_file) as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.validate(doc, schema, cls=jsonschema.Draft202012Validator)
    assert doc["min_snr"] == MIN_SNR and doc["step_s"] == 60 and doc["tolerance_s"] <= 0.001, doc
    assert doc["sensor"] == "Sensor1" and doc["target"] == "Satellite2"
    intervals = [(parse(i["start"]), parse(i["stop"])) for i in doc["intervals"]]
    if not intervals:
        sys.exit("FAILED: no access interval (spec 7.8 expects SNR >= 6 while the target is seen against space)")
    for (a, b), i in zip(intervals, doc["intervals"]):
        assert a <= b, i
        assert abs((b - a).total_seconds() - i["duration_s"]) < 1e-6, i
    for (a0, b0), (a1, b1) in zip(intervals, intervals[1:]):
        assert b0 < a1, "intervals overlap or are out of order"
    assert doc["evaluations"] >= 1441, doc["evaluations"]

    # CSV: the same intervals.
    r = run(base + ["--format", "csv", "--quiet"])
    rows = list(csv.DictReader(io.StringIO(r.stdout)))
    assert list(rows[0].keys()) == ["start", "stop", "duration_s"], rows[0].keys()
    assert [(x["start"], x["stop"]) for x in rows] == [(i["start"], i["stop"]) for i in doc["intervals"]]
    assert r.stderr == "", r.stderr  # --quiet

    # The 60 s report: inside <=> SNR >= 6.
    r = run([exe, "report", scenario, "--provider", GROUP, "--sensor", "Sensor1", "--target", "Satellite2",
             "--start", START, "--stop", STOP, "--step", "60", "--format", "json", "--quiet"])
    report = [(parse(row["time"]), row["values"][SNR]["value"]) for row in json.loads(r.stdout)["rows"]]
    assert len(report) == 1441, len(report)

    def inside(t):
        return any(a <= t <= b for a, b in intervals)

    bad = [(iso_ms(t), v) for t, v in report if inside(t) != (v >= MIN_SNR)]
    if bad:
        sys.exit(f"FAILED: report rows on the wrong side of the access intervals: {bad[:10]}")
    t_first, t_last = report[0][0], report[-1][0]
    # Each boundary between the two report steps that bracket its crossing.
    checked = 0
    for a, b in intervals:
        for when, entering in ((a, True), (b, False)):
            if when in (t_first, t_last):
                continue  # clipped at start or stop
            before = max(t for t, _ in report if t <= when)
            after = min(t for t, _ in report if t > when)
            snr_before = dict(report)[before]
            snr_after = dict(report)[after]
            if entering:
                ok = snr_before < MIN_SNR <= snr_after and before < when
            else:
                ok = snr_before >= MIN_SNR > snr_after
            if not ok:
                sys.exit(f"FAILED: boundary {iso_ms(when)} not bracketed by report steps "
                         f"{iso_ms(before)} (SNR {snr_before}) and {iso_ms(after)} (SNR {snr_after})")
            # +-2 ms around the boundary, evaluated by `eoir report`.
            lo = when - dt.timedelta(milliseconds=2)
            r = run([exe, "report", scenario, "--provider", GROUP, "--sensor", "Sensor1", "--target", "Satellite2",
                     "--start", iso_ms(lo), "--stop", iso_ms(when + dt.timedelta(milliseconds=2)), "--step",
                     "0.002", "--format", "json", "--quiet"])
            three = [row["values"][SNR]["value"] for row in json.loads(r.stdout)["rows"]]
            assert len(three) == 3, three
            minus, at, plus = three
            inner, outer = (plus, minus) if entering else (minus, plus)
            if not (at >= MIN_SNR and inner >= MIN_SNR and outer < MIN_SNR):
                sys.exit(f"FAILED: around {'start' if entering else 'stop'} {iso_ms(when)}: SNR -2 ms {minus}, "
                         f"at {at}, +2 ms {plus}")
            checked += 1
    print(f"{len(intervals)} intervals, {checked} boundaries checked against the report, "
          f"{doc['evaluations']} SNR evaluations")
    for i in doc["intervals"]:
        print(f"  {i['start']} .. {i['stop']}  {i['duration_s']:.3f} s")


if __name__ == "__main__":
    main()
