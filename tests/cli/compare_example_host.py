#!/usr/bin/env python3
"""The C example host and the eoir CLI print the same static metrics.

usage: compare_example_host.py EXAMPLE_HOST EOIR_EXE SCENARIO
The example host prints "Group | Element | value | unit" (%.6g); the CLI's
JSON report of the same group must agree to the printed 6 digits.
"""
import json
import subprocess
import sys


def main():
    host, exe, scenario = sys.argv[1:4]
    run = subprocess.run([host], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"FAILED: example host exit {run.returncode}\n{run.stderr}")
    by_group = {}
    for line in run.stdout.splitlines():
        parts = [p.strip() for p in line.split("|")]
        if len(parts) != 4:
            continue
        group, element, value, unit = parts
        by_group.setdefault(group, []).append((element, value, unit))
    if len(by_group) < 4:
        sys.exit(f"FAILED: expected the four static groups, got {sorted(by_group)}\n{run.stdout}")
    compared = failures = 0
    for group, rows in by_group.items():
        cli = subprocess.run([exe, "report", scenario, "--provider", group, "--sensor", "Sensor1", "--format", "json"],
                             capture_output=True, text=True)
        if cli.returncode != 0:
            sys.exit(f"FAILED: eoir report --provider '{group}': {cli.stderr}")
        values = json.loads(cli.stdout)["rows"][0]["values"]
        for element, value, unit in rows:
            if element not in values:
                print(f"FAIL {group} / {element}: not in the CLI report")
                failures += 1
                continue
            v = values[element]
            if unit != v["unit"]:
                print(f"FAIL {group} / {element}: unit '{unit}' vs CLI '{v['unit']}'")
                failures += 1
            if value.startswith("curve("):
                n = int(value[len("curve("):].split()[0])
                ok = isinstance(v["value"], list) and len(v["value"]) == n
            else:
                cli_value = float(v["value"])
                ok = ("%.6g" % cli_value) == value
            compared += 1
            print(f"{'ok  ' if ok else 'FAIL'} {group} / {element}: host {value} CLI {v['value'] if not isinstance(v['value'], list) else 'curve'}")
            failures += not ok
    print(f"{compared} elements compared, {failures} differences")
    sys.exit(1 if failures or compared == 0 else 0)


if __name__ == "__main__":
    main()
