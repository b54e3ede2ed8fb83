#!/usr/bin/python3
"""Spec 6.2.5.4's air-mass charts (issue 20 item 9): the air a line of sight
crosses, in sea-level vertical columns (straight up from the ground is 1),
against the local zenith angle (LZA), from the engine's "Air Mass" data
provider (group "EOIR Sensor-to-Target Metrics"; US Standard 1976, the
refracted ray from a sensor inside the atmosphere).

1. A ground sensor at 0, 2, 4, 6, 8 and 10 km looks at a satellite 2,000 km
   away at LZA 0-90 deg (the spec's first chart): at altitude the horizon
   recedes and the line can cross more air than from the ground.
2. The converse: a sensor on a satellite 1,000 km up looks at a ground
   target (at 0-10 km) seen from the target at LZA 0-89 deg (the second
   chart).

usage: air_mass_6_2_5_4.py [--out-dir DIR] [--quick]
Writes DIR/air_mass_6_2_5_4.csv (altitude_km, lza_deg, ground_to_space,
space_to_ground) and DIR/air_mass_6_2_5_4.png, and prints the checks that
tests/validation/check_air_mass_6_2_5_4.py makes of the CSV.
"""
import argparse
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
GROUP = "EOIR Sensor-to-Target Metrics"
A = 6378137.0  # the site at 0 N 0 E: up is +x, north +z (Earth-fixed)


def import_eoir():
    import importlib.util
    if importlib.util.find_spec("eoir") is None:
        sys.path.insert(0, os.path.join(ROOT, "bindings", "python"))
    import eoir
    return eoir


def point(height_m, lza_deg, range_m):
    """Earth-fixed position `range_m` from the point `height_m` above 0 N 0 E
    along the direction at zenith angle lza_deg, azimuth north."""
    z = math.radians(lza_deg)
    return (A + height_m + range_m * math.cos(z), 0.0, range_m * math.sin(z))


def engine_with(eoir):
    e = eoir.Engine()
    e.set_time("2010-03-21T12:00:00Z")
    e.add_object("central_body", "Earth")
    e.set("Earth", "atmosphere", "simple")
    e.set("Earth", "aerosol_model", "none")
    return e


def ground_to_space(eoir, heights_km, lzas):
    """The ground sensor's air mass toward a satellite 2,000 km away."""
    e = engine_with(eoir)
    e.add_object("satellite", "Ground")
    e.add_sensor("Cam", "Ground")
    e.add_object("satellite", "Sat")
    out = {}
    for h in heights_km:
        e.set_state("Ground", (A + 1e3 * h, 0.0, 0.0), frame="earth_fixed")
        for z in lzas:
            e.set_state("Sat", point(1e3 * h, z, 2.0e6), frame="earth_fixed")
            out[(h, z)] = e.provider(GROUP, "Air Mass", "Cam", "Sat")
    e.close()
    return out


def space_to_ground(eoir, heights_km, lzas):
    """A sensor 1,000 km up looking at a ground target that sees it at LZA z:
    the same line of sight walked the other way."""
    e = engine_with(eoir)
    e.add_object("satellite", "Orbiter")
    e.add_sensor("Cam", "Orbiter")
    e.add_object("satellite", "Target")
    out = {}
    for h in heights_km:
        e.set_state("Target", (A + 1e3 * h, 0.0, 0.0), frame="earth_fixed")
        r = A + 1e3 * h
        for z in lzas:
            # range to a point 1,000 km up along LZA z from the target
            c = math.cos(math.radians(z))
            top = A + 1.0e6
            s = -r * c + math.sqrt((r * c) ** 2 - r * r + top * top)
            e.set_state("Orbiter", point(1e3 * h, z, s), frame="earth_fixed")
            out[(h, z)] = e.provider(GROUP, "Air Mass", "Cam", "Target")
    e.close()
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out-dir", default=os.path.join(ROOT, "scenarios", "validation", "results"))
    ap.add_argument("--quick", action="store_true", help="a coarse grid of zenith angles")
    args = ap.parse_args(argv)
    eoir = import_eoir()
    heights = [0, 2, 4, 6, 8, 10]
    lzas = [0, 30, 60, 75, 85, 89, 90] if args.quick else [0.5 * i for i in range(0, 181)]
    up = ground_to_space(eoir, heights, lzas)
    down = space_to_ground(eoir, heights, [z for z in lzas if z < 90])
    os.makedirs(args.out_dir, exist_ok=True)
    path = os.path.join(args.out_dir, "air_mass_6_2_5_4.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        f.write("# Spec 6.2.5.4 air-mass charts: eoir 'Air Mass' (sea-level vertical columns), US Standard 1976,\n")
        f.write("# no aerosol; ground_to_space: ground sensor at altitude_km toward a satellite 2000 km away at\n")
        f.write("# local zenith angle lza_deg; space_to_ground: a sensor 1000 km up toward a target at altitude_km\n")
        f.write("# that sees it at lza_deg (empty at 90 deg).\n")
        w.writerow(["altitude_km", "lza_deg", "ground_to_space", "space_to_ground"])
        for h in heights:
            for z in lzas:
                d = down.get((h, z))
                w.writerow([h, z, f"{up[(h, z)]:.6f}", "" if d is None else f"{d:.6f}"])
    print(f"wrote {path}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return 0
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for h in heights:
        axes[0].semilogy(lzas, [up[(h, z)] for z in lzas], label=f"{h} km")
        zs = [z for z in lzas if z < 90]
        axes[1].semilogy(zs, [down[(h, z)] for z in zs], label=f"{h} km")
    axes[0].set_title("Ground sensor to a satellite")
    axes[1].set_title("Satellite sensor to a ground target")
    for ax in axes:
        ax.set_xlabel("local zenith angle (deg)")
        ax.set_ylabel("air mass")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(title="altitude")
    fig.suptitle("Spec 6.2.5.4 air mass (US Standard 1976; the ground sensor along the refracted ray)")
    fig.tight_layout()
    png = os.path.join(args.out_dir, "air_mass_6_2_5_4.png")
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
