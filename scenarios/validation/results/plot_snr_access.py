#!/usr/bin/python3
"""Spec 7.8 (SNR access constraint): SNR of Satellite2 seen by Sensor1 over a
day, with the SNR = 6 line and the access intervals (SNR >= 6) shaded.

usage: plot_snr_access.py [EOIR_EXE]   (else $EOIR_EXE, else build/bin/eoir)

Runs the documented commands from the repository root:

  eoir report scenarios/validation/valid_sens_snr_access.json \
       --provider "EOIR Sensor-to-Target Metrics" --sensor Sensor1 --target Satellite2 \
       --start 2010-12-08T22:00:00Z --stop 2010-12-09T22:00:00Z --step 60 --format csv
  eoir access scenarios/validation/valid_sens_snr_access.json \
       --sensor Sensor1 --target Satellite2 --min-snr 6 \
       --start 2010-12-08T22:00:00Z --stop 2010-12-09T22:00:00Z --step 60 --format json|csv

and writes, beside this script, snr_access_7_8.png, access_7_8.json,
access_7_8.csv and snr_report_7_8.csv.
"""
import csv
import datetime as dt
import io
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.dates as mdates  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SCENARIO = os.path.join("scenarios", "validation", "valid_sens_snr_access.json")
START, STOP, STEP, MIN_SNR = "2010-12-08T22:00:00Z", "2010-12-09T22:00:00Z", "60", "6"
SNR = "Signal to Noise Ratio"


def parse(iso):
    iso = iso.rstrip("Z")
    fmt = "%Y-%m-%dT%H:%M:%S.%f" if "." in iso else "%Y-%m-%dT%H:%M:%S"
    return dt.datetime.strptime(iso, fmt)


def run(cmd):
    print("$ " + " ".join(f"'{c}'" if " " in c else c for c in cmd), file=sys.stderr)
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{cmd[1]} failed (exit {r.returncode}):\n{r.stderr}")
    if r.stderr.strip():
        print(r.stderr.strip().splitlines()[-1], file=sys.stderr)
    return r.stdout


def main():
    exe = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("EOIR_EXE", os.path.join(ROOT, "build", "bin", "eoir"))
    report_csv = run([exe, "report", SCENARIO, "--provider", "EOIR Sensor-to-Target Metrics", "--sensor", "Sensor1",
                      "--target", "Satellite2", "--start", START, "--stop", STOP, "--step", STEP, "--format", "csv"])
    access_args = [exe, "access", SCENARIO, "--sensor", "Sensor1", "--target", "Satellite2", "--min-snr", MIN_SNR,
                   "--start", START, "--stop", STOP, "--step", STEP]
    access_json = run(access_args + ["--format", "json"])
    access_csv = run(access_args + ["--format", "csv", "--quiet"])
    for name, text in (("snr_report_7_8.csv", report_csv), ("access_7_8.json", access_json),
                       ("access_7_8.csv", access_csv)):
        with open(os.path.join(HERE, name), "w") as f:
            f.write(text)

    rows = list(csv.DictReader(io.StringIO(report_csv)))
    t = [parse(r["time"]) for r in rows]
    snr = [float(r[SNR]) for r in rows]
    access = json.loads(access_json)
    intervals = [(parse(i["start"]), parse(i["stop"])) for i in access["intervals"]]

    fig, ax = plt.subplots(figsize=(12, 4.5), dpi=110)
    for k, (a, b) in enumerate(intervals):
        ax.axvspan(a, b, color="tab:green", alpha=0.22, lw=0, label="access (SNR >= 6)" if k == 0 else None)
    ax.plot(t, snr, color="tab:blue", lw=0.9, marker=".", ms=2.5, label="SNR (eoir report, 60 s steps)")
    ax.axhline(float(MIN_SNR), color="tab:red", lw=1.0, ls="--", label="SNR = 6")
    ax.set_xlim(parse(START), parse(STOP))
    ax.set_ylim(0, max(snr) * 1.3)
    ax.xaxis.set_major_locator(mdates.HourLocator(interval=2))
    ax.xaxis.set_major_formatter(mdates.DateFormatter("%d %H:%M"))
    ax.set_xlabel("UTC (day hour:minute), 8-9 Dec 2010")
    ax.set_ylabel("SNR (Satellite2 seen by Sensor1)")
    ax.set_title(f"Spec 7.8 SNR access constraint: {len(intervals)} intervals with SNR >= 6 "
                 f"(eoir access, boundaries refined to {access['tolerance_s'] * 1e3:g} ms, "
                 f"{access['evaluations']} SNR evaluations)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper center", ncol=3, fontsize=8, framealpha=0.95)
    fig.tight_layout()
    out = os.path.join(HERE, "snr_access_7_8.png")
    fig.savefig(out)
    print(f"wrote {out}, {len(intervals)} intervals", file=sys.stderr)


if __name__ == "__main__":
    main()
