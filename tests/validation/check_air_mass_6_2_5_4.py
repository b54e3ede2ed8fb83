#!/usr/bin/python3
"""Spec 6.2.5.4's air-mass charts (issue 20 item 9), made by
scenarios/validation/tools/air_mass_6_2_5_4.py --quick into OUT_DIR, checked:

- from the ground straight up: 1 (the unit), within 1e-3;
- from 10 km straight up: the share of the column above 10 km, US76's
  p(10 km) / p0 = 26436.27 / 101325 Pa (NOAA-S/T 76-1562, table I) over the
  ratio of gravity there (g falls 0.31 % by 10 km), within 1 %;
- from space down the same line: the same air within 1 % up to LZA 75 deg
  (the ray from the ground is refracted, the ray from space is taken
  straight: they part near the horizon);
- the spec's remark "at altitude the horizon recedes, so it is possible to
  look through a greater amount of atmosphere": from 10 km the horizontal
  line crosses more zenith columns of its own height than the ground's
  horizontal line does (it dips below the sensor);
- finite and rising with LZA at 0 and 10 km.

usage: check_air_mass_6_2_5_4.py OUT_DIR
"""
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))


def main():
    out = sys.argv[1]
    subprocess.run([sys.executable, os.path.join(ROOT, "scenarios", "validation", "tools", "air_mass_6_2_5_4.py"),
                    "--quick", "--out-dir", out], check=True)
    rows = {}
    with open(os.path.join(out, "air_mass_6_2_5_4.csv")) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            rows[(float(r["altitude_km"]), float(r["lza_deg"]))] = (
                float(r["ground_to_space"]), float(r["space_to_ground"]) if r["space_to_ground"] else None)
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    up0 = rows[(0, 0)][0]
    check(abs(up0 - 1.0) < 1e-3, f"ground, zenith: {up0:.5f} (1)")
    g_ratio = (6356766.0 / (6356766.0 + 10e3)) ** 2  # US76 geopotential radius
    expected = 26436.27 / 101325.0 / g_ratio
    up10 = rows[(10, 0)][0]
    check(abs(up10 / expected - 1) < 0.01, f"10 km, zenith: {up10:.5f} (p(10 km)/p0/g ratio {expected:.5f})")
    for (h, z), (up, down) in sorted(rows.items()):
        if down is not None and z <= 75:
            check(abs(down / up - 1) < 0.01, f"{h:g} km, LZA {z:g}: space to ground {down:.4f}, ground to space {up:.4f}")
    h0, h10 = rows[(0, 90)][0], rows[(10, 90)][0]
    check(h10 / up10 > h0, f"horizontal from 10 km {h10:.2f} = {h10 / up10:.1f} zenith columns there, "
          f"more than the ground's {h0:.2f}")
    for h in (0, 10):
        series = [rows[(h, z)][0] for z in (0, 30, 60, 75, 85, 89, 90)]
        check(all(b > a for a, b in zip(series, series[1:])) and all(x == x and x < 1e3 for x in series),
              f"{h} km: finite and rising with LZA {['%.3f' % x for x in series]}")
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
