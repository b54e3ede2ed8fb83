#!/usr/bin/env python3
"""scenario.schema.json types what the engine takes: sensor parameters
through sensor.schema.json (a typo such as horizontal_fov_dge, or a string
for f_number, is refused) with the reference pairs flat or nested; object
properties through object_properties.schema.json; the "tle" motion. Every
schema carries the one $id host https://eoir.invalid/schemas/. Cases the
schema accepts are accepted by `eoir validate` too.

usage: check_scenario_schema.py SCHEMA_DIR SCENARIO EOIR_EXE WORK_DIR
"""
import copy
import glob
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(__file__))
from validate_json import validator_for  # noqa: E402

TLE = {"type": "tle",
       "line1": "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927",
       "line2": "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537"}


def main():
    schema_dir, scenario, exe, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    hosts = {json.load(open(p))["$id"].rsplit("/", 1)[0] for p in glob.glob(os.path.join(schema_dir, "*.json"))}
    failures = 0
    if hosts != {"https://eoir.invalid/schemas"}:
        print(f"FAIL $id hosts {hosts}")
        failures += 1
    v = validator_for(os.path.join(schema_dir, "scenario.schema.json"))
    base = json.load(open(scenario))

    def case(name, edit, valid, cli=None):
        nonlocal failures
        doc = copy.deepcopy(base)
        edit(doc)
        errors = list(v.iter_errors(doc))
        ok = (not errors) == valid
        msg = errors[0].message[:120] if errors else "accepted"
        if ok and cli is not None:
            path = os.path.join(work, name + ".json")
            json.dump(doc, open(path, "w"), indent=1)
            r = subprocess.run([exe, "validate", path], capture_output=True, text=True, timeout=120)
            ok = (r.returncode == 0) == cli
            msg += f"; eoir validate exit {r.returncode} {r.stderr.strip()[:160]}"
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {msg}")
        failures += not ok

    sensor = lambda d: d["sensors"][0]["parameters"]  # noqa: E731
    obj = lambda d: d["objects"][0].setdefault("properties", {})  # noqa: E731
    case("as_is", lambda d: None, True, cli=True)
    case("sensor_typo", lambda d: sensor(d).update(horizontal_fov_dge=2.0), False, cli=False)
    case("sensor_type", lambda d: sensor(d).update(f_number="fast"), False, cli=False)
    case("sensor_enum", lambda d: sensor(d).update(image_quality="superb"), False, cli=False)
    case("pairs_nested", lambda d: sensor(d).update(sensitivity_pairs=[[10.0, 1e-18], [20.0, 5e-19]]), True,
         cli=True)
    case("pairs_flat", lambda d: sensor(d).update(sensitivity_pairs=[10.0, 1e-18, 20.0, 5e-19]), True, cli=True)
    case("pairs_odd", lambda d: sensor(d).update(sensitivity_pairs=[[10.0, 1e-18, 3.0]]), False)
    case("object_typo", lambda d: obj(d).update(temprature_K=300), False, cli=False)
    case("object_type", lambda d: obj(d).update(temperature_K="hot"), False, cli=False)
    case("object_material", lambda d: obj(d).update(material="gold"), True, cli=True)
    case("object_bad_material", lambda d: obj(d).update(material="wood"), False, cli=False)
    case("body_property", lambda d: d["central_bodies"].__setitem__(
        0, {"name": "Earth", "properties": {"temperature_K": 288.0}}), True, cli=True)
    case("tle", lambda d: d["objects"][0].__setitem__("motion", dict(TLE)), True, cli=True)
    case("tle_missing_line", lambda d: d["objects"][0].__setitem__("motion", {"type": "tle", "line1": TLE["line1"]}),
         False, cli=False)
    # Missiles (issue 22): the ballistic motion, the velocity attitude, stages and launch time.
    ballistic = {"type": "ballistic", "launch_lat_deg": 5.0, "launch_lon_deg": -30.0, "impact_lat_deg": 30.0,
                 "impact_lon_deg": -15.0, "launch_time": base["start"], "burn_s": 120.0}

    def missile(d, **motion):
        d["objects"][0].update(kind="missile", motion=dict(ballistic, **motion), attitude={"type": "velocity"})
        d["objects"][0]["properties"] = {"missile_stages": '[{"length_m": 10, "radius_m": 1}]',
                                         "launch_time_utc": base["start"]}
    case("ballistic", missile, True, cli=True)
    case("ballistic_lofted", lambda d: missile(d, apogee_height_m=1500e3), True, cli=True)
    case("ballistic_negative_burn", lambda d: missile(d, burn_s=-1.0), False, cli=False)
    case("ballistic_typo", lambda d: missile(d, burn_time_s=10.0), False, cli=False)
    case("ballistic_burn_too_long", lambda d: missile(d, burn_s=1e6), True, cli=False)  # (the engine's check)
    case("ballistic_antipodal", lambda d: missile(d, impact_lat_deg=-5.0, impact_lon_deg=150.0), True, cli=False)
    print(f"{failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
