#!/usr/bin/env python3
"""A ground site tracking the ISS (issue 20 item 6): `eoir validate` and
`eoir run` on tests/cli/data/site_tracks_iss.json.

usage: check_site_scenario.py EOIR_EXE SCENARIO SCHEMA_DIR OUT_DIR

- validate and run succeed; summary.json and every truth file validate
  against their schemas;
- every frame of the tracking camera lists the ISS alone, at the centre
  pixel (0.05 px), without a streak over its 100 ms integration (0.05 px:
  the tracking rates); its truth azimuth and elevation (the site is on the
  ground) agree with astropy within 0.005 deg: the ISS's J2000 (GCRS) state
  from the scenario's own SGP4 (eoir.tle_state), taken to ITRS by astropy
  with UT1 = UTC as the engine takes it, seen from the site's WGS84
  position along its geodetic east, north and up; the rest is the polar
  motion astropy applies and the engine does not (about 8 m on the ground,
  0.001 deg at the ISS 430-1500 km away);
- the pass rises, culminates and sets (elevation up, then down);
- bad site scenarios are refused by validate and by the schema, naming the
  field: elevation 95, a site moving on a TLE, a site with an attitude, a
  latitude of 91.
"""
import copy
import json
import math
import re
import os
import shutil
import subprocess
import sys
import tempfile
import warnings

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from validate_json import validator_for  # noqa: E402

import eoir  # noqa: E402

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(cmd, ok=True):
    r = subprocess.run(cmd, capture_output=True, text=True)
    print(f"$ {' '.join(cmd)}\nexit {r.returncode}\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
    if r.returncode < 0:
        sys.exit(f"FAILED: killed by signal {-r.returncode}")
    if ok and r.returncode != 0:
        sys.exit(f"FAILED: {' '.join(cmd)}")
    return r


def astropy_azel(site_geodetic, position_gcrs_m, iso):
    """Topocentric azimuth and elevation (deg) of a GCRS position."""
    from astropy import units as u
    from astropy.coordinates import GCRS, ITRS, CartesianRepresentation, EarthLocation, SkyCoord
    from astropy.time import Time
    from astropy.utils import iers
    iers.conf.auto_download = False
    lat, lon, h = site_geodetic
    t = Time(iso.rstrip("Z"), scale="utc")
    t.delta_ut1_utc = 0.0
    site = EarthLocation.from_geodetic(lon * u.deg, lat * u.deg, h * u.m)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # IERS tables beyond their range
        c = SkyCoord(CartesianRepresentation(*(np.asarray(position_gcrs_m) * u.m)), frame=GCRS(obstime=t))
        d = (c.transform_to(ITRS(obstime=t)).cartesian.xyz.to(u.m).value -
             site.get_itrs(t).cartesian.xyz.to(u.m).value)
    p, l = math.radians(lat), math.radians(lon)
    east = np.array([-math.sin(l), math.cos(l), 0.0])
    north = np.array([-math.sin(p) * math.cos(l), -math.sin(p) * math.sin(l), math.cos(p)])
    up = np.array([math.cos(p) * math.cos(l), math.cos(p) * math.sin(l), math.sin(p)])
    az = math.degrees(math.atan2(d @ east, d @ north)) % 360.0
    el = math.degrees(math.atan2(d @ up, math.hypot(d @ east, d @ north)))
    return az, el


def main():
    exe, scenario_path, schemas, out = sys.argv[1:5]
    with open(scenario_path) as f:
        scenario = json.load(f)
    site = next(o for o in scenario["objects"] if o["kind"] == "site")
    m = site["motion"]
    site_geodetic = (m["lat_deg"], m["lon_deg"], m.get("alt_m", 0.0))
    iss = next(o for o in scenario["objects"] if o["name"] == "ISS")["motion"]
    tracker = next(s for s in scenario["sensors"] if s["pointing"]["type"] == "target")
    pixels = tracker["parameters"]["horizontal_pixels"]
    centre = (pixels - 1) / 2.0

    run([exe, "validate", scenario_path])
    shutil.rmtree(out, ignore_errors=True)
    run([exe, "run", scenario_path, "--out", out, "--quiet"])
    summary_v = validator_for(os.path.join(schemas, "run_summary.schema.json"))
    truth_v = validator_for(os.path.join(schemas, "truth.schema.json"))
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    summary_v.validate(summary)
    elevations = []
    for fr in summary["frames"]:
        with open(os.path.join(out, fr["files"]["truth"])) as f:
            truth = json.load(f)
        truth_v.validate(truth)
        for row in truth:
            check("azimuth_deg" in row and "elevation_deg" in row, f"{fr['files']['truth']}: no azimuth/elevation")
        if fr["sensor"] != tracker["name"]:
            continue
        where = f"{fr['sensor']} frame {fr['index']} ({fr['time']})"
        check([r["object"] for r in truth] == ["ISS"], f"{where}: truth lists {[r['object'] for r in truth]}")
        if not truth:
            continue
        r = truth[0]
        check(abs(r["pixel_x"] - centre) <= 0.05 and abs(r["pixel_y"] - centre) <= 0.05,
              f"{where}: ISS at ({r['pixel_x']}, {r['pixel_y']}), not the centre {centre}")
        streak = math.hypot(r["end_fits"][0] - r["start_fits"][0], r["end_fits"][1] - r["start_fits"][1])
        check(streak <= 0.05, f"{where}: the tracked ISS streaks by {streak} px")
        state = eoir.tle_state(iss["line1"], iss["line2"], fr["time"])
        az, el = astropy_azel(site_geodetic, state["position_m"], fr["time"])
        daz = (r["azimuth_deg"] - az + 180.0) % 360.0 - 180.0
        print(f"{where}: az {r['azimuth_deg']:.6f} (astropy {az:.6f}), el {r['elevation_deg']:.6f} "
              f"(astropy {el:.6f}), range {r['range_m'] / 1e3:.1f} km")
        check(abs(daz) * math.cos(math.radians(el)) <= 0.005 and abs(r["elevation_deg"] - el) <= 0.005,
              f"{where}: azimuth/elevation {r['azimuth_deg']}, {r['elevation_deg']} vs astropy {az}, {el}")
        elevations.append(r["elevation_deg"])
    check(len(elevations) == 7, f"{len(elevations)} tracking frames, expected 7")
    top = int(np.argmax(elevations)) if elevations else 0
    check(0 < top < len(elevations) - 1 and all(e > 0 for e in elevations) and
          elevations == sorted(elevations[:top + 1]) + sorted(elevations[top + 1:], reverse=True),
          f"the pass does not rise and set: {elevations}")

    # Bad sites: validate names the field, and the schema refuses the file.
    scenario_v = validator_for(os.path.join(schemas, "scenario.schema.json"))
    site_index = scenario["objects"].index(site)
    stare_index = next(i for i, s in enumerate(scenario["sensors"]) if s["pointing"]["type"] == "azel")
    cases = []
    bad = copy.deepcopy(scenario)
    bad["sensors"][stare_index]["pointing"]["elevation_deg"] = 95.0
    cases.append((bad, rf"sensors\[{stare_index}\]\.pointing\.elevation_deg: must be in \[-90, 90\]"))
    bad = copy.deepcopy(scenario)
    bad["objects"][site_index]["motion"] = dict(iss)
    cases.append((bad, rf"objects\[{site_index}\]\.motion\.type: a site is fixed on the Earth"))
    bad = copy.deepcopy(scenario)
    bad["objects"][site_index]["attitude"] = {"type": "nadir"}
    cases.append((bad, rf"objects\[{site_index}\]\.attitude: a site's attitude is its local horizon"))
    bad = copy.deepcopy(scenario)
    bad["objects"][site_index]["motion"]["lat_deg"] = 91.0
    cases.append((bad, rf"objects\[{site_index}\]\.motion\.lat_deg: must be in \[-90, 90\]"))

    with tempfile.TemporaryDirectory() as tmp:
        for k, (doc, pattern) in enumerate(cases):
            path = os.path.join(tmp, f"bad_{k}.json")
            with open(path, "w") as f:
                json.dump(doc, f)
            r = run([exe, "validate", path], ok=False)
            check(r.returncode != 0 and re.search(pattern, r.stderr), f"bad case {k}: expected /{pattern}/")
            check(any(True for _ in scenario_v.iter_errors(doc)), f"bad case {k}: the schema accepts it")
    check(not list(scenario_v.iter_errors(scenario)), "the scenario does not validate against the schema")

    # `eoir properties site` lists the site's place.
    r = run([exe, "properties", "site", "--format", "json"])
    names = [p["name"] for p in json.loads(r.stdout)["properties"]]
    check(names == ["latitude_deg", "longitude_deg", "height_m"], f"eoir properties site: {names}")

    if failures:
        sys.exit(f"FAILED: {len(failures)} checks")
    print("all checks passed")


if __name__ == "__main__":
    main()
