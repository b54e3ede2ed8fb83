#!/usr/bin/env python3
"""Files a scenario names (issue 25 item 10; README "Bounds"): relative to
the scenario's folder and inside it (star catalogues; mesh files, as an
object's mesh_file and in a composite's parts, issue 22 item 4). A path leading out of it (`..`, an
absolute path, a symbolic link) is refused naming the field, with the same
message whether the file exists or not, before it is opened;
--allow-paths-outside lets every scenario command read it. Paths inside
(relative, in a subfolder, absolute) are read as before.

usage: check_scenario_paths.py EOIR_EXE WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

from cli_checks import check, failures, run

CATALOGUE = ("id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\n"
             "vega,279.234735,38.783689,200.94,286.23,130.23,0.03,0.00\n")
FIELD = "stars.properties.catalog_file"
OUTSIDE = "lies outside the scenario's folder"


def scenario(folder, name, catalog_file):
    """A scenario with the star field naming catalog_file, and a sensor."""
    doc = {"format": "eoir-scenario", "version": 1, "name": name, "start": "2010-08-25T18:00:00Z",
           "stars": {"properties": {"catalog_file": catalog_file}},
           "objects": [{"name": "Sat", "kind": "satellite",
                        "motion": {"type": "kepler", "semi_major_axis_km": 42164, "epoch": "2010-08-25T18:00:00Z"}}],
           "sensors": [{"name": "Cam", "parent": "Sat",
                        "parameters": {"horizontal_pixels": 8, "vertical_pixels": 8}}]}
    path = os.path.join(folder, name + ".json")
    with open(path, "w") as f:
        json.dump(doc, f)
    return path


CUBE = ("v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
        "f 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\nf 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n")


def mesh_scenario(folder, name, properties):
    """A scenario whose target has `properties` (shape mesh or composite)."""
    doc = {"format": "eoir-scenario", "version": 1, "name": name, "start": "2010-08-25T18:00:00Z",
           "objects": [{"name": "Sat", "kind": "satellite",
                        "motion": {"type": "kepler", "semi_major_axis_km": 42164, "epoch": "2010-08-25T18:00:00Z"}},
                       {"name": "Target", "kind": "satellite", "properties": properties,
                        "motion": {"type": "kepler", "semi_major_axis_km": 42164.1,
                                   "epoch": "2010-08-25T18:00:00Z"}}],
           "sensors": [{"name": "Cam", "parent": "Sat", "pointing": {"type": "target", "target": "Target"},
                        "parameters": {"horizontal_pixels": 8, "vertical_pixels": 8}}]}
    path = os.path.join(folder, name + ".json")
    with open(path, "w") as f:
        json.dump(doc, f)
    return path


def check_mesh_files(exe, folder):
    """mesh_file of an object and of a composite's (nested) part: relative
    to the scenario's folder, refused outside it naming the JSON path."""
    with open(os.path.join(folder, "sub", "cube.obj"), "w") as f:
        f.write(CUBE)
    as_shape = {"shape": "mesh", "mesh_file": "sub/cube.obj", "dimensions_m": [2.0]}
    code, out = run(exe, "validate", mesh_scenario(folder, "mesh_shape", as_shape))
    check(code == 0 and "valid" in out, f"mesh_file relative to the scenario: valid ({out.strip()[-200:]})")
    part = json.dumps([{"parts": [{"shape": "mesh", "mesh_file": "sub/cube.obj", "dimensions_m": [2.0]}]}])
    code, out = run(exe, "validate", mesh_scenario(folder, "mesh_part", {"shape": "composite", "composite": part}))
    check(code == 0 and "valid" in out, f"a composite part's mesh_file relative to the scenario: valid ({out.strip()[-200:]})")
    outside = json.dumps([{"parts": [{"shape": "mesh", "mesh_file": "../outside.obj"}]}])
    code, out = run(exe, "validate", mesh_scenario(folder, "mesh_out", {"shape": "composite", "composite": outside}))
    check(code == 2 and "objects[1].properties.composite[0].parts[0].mesh_file: '../outside.obj' " + OUTSIDE in out,
          f"a composite part's mesh_file outside: refused naming its path ({out.strip()[-200:]})")
    bad = dict(as_shape, mesh_file="sub/missing.obj")
    code, out = run(exe, "validate", mesh_scenario(folder, "mesh_missing", bad))
    check(code != 0 and "missing.obj" in out and "mesh_file" in out, f"a missing mesh file: reported ({out.strip()[-200:]})")


def main():
    exe, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    folder = os.path.join(work, "scenarios")
    os.makedirs(os.path.join(folder, "sub"))
    for p in (os.path.join(folder, "stars.csv"), os.path.join(folder, "sub", "stars.csv"),
              os.path.join(work, "outside.csv")):
        with open(p, "w") as f:
            f.write(CATALOGUE)
    os.symlink(os.path.join(work, "outside.csv"), os.path.join(folder, "link.csv"))

    inside = {"same folder": "stars.csv", "subfolder": "sub/stars.csv", "through ..": "sub/../stars.csv",
              "absolute inside": os.path.join(folder, "stars.csv")}
    for what, named in inside.items():
        code, out = run(exe, "validate", scenario(folder, "inside", named))
        check(code == 0 and "valid" in out, f"{what} ({named}): valid")

    outside = {"..": "../outside.csv", "missing ..": "../missing.csv", "sub/../..": "sub/../../outside.csv",
               "absolute": os.path.join(work, "outside.csv"), "missing absolute": "/nonexistent/dir/x.csv",
               "system file": "/etc/passwd", "symbolic link": "link.csv"}
    messages = set()
    for what, named in outside.items():
        code, out = run(exe, "validate", scenario(folder, "outside", named))
        check(code == 2 and f"{FIELD}: '{named}' {OUTSIDE}" in out, f"{what} ({named}): refused naming the field")
        check("cannot open" not in out and "No such file" not in out, f"{what}: nothing read or probed")
        messages.add(out.replace(named, "NAMED"))
    check(len(messages) == 1, "one message whether the file exists or not")

    # Every scenario command refuses it, and takes --allow-paths-outside.
    path = scenario(folder, "outside", "../outside.csv")
    out_dir = os.path.join(work, "run")
    commands = {
        "validate": ["validate", path],
        "report": ["report", path, "--provider", "EOIR Sensor Optics", "--sensor", "Cam", "--quiet"],
        "run": ["run", path, "--out", out_dir, "--quiet"],
        "save-state": ["save-state", path, "--out", os.path.join(work, "state.scd")],
    }
    for name, args in commands.items():
        code, out = run(exe, *args)
        check(code == 2 and OUTSIDE in out, f"{name}: refused")
        code, out = run(exe, *args, "--allow-paths-outside")
        check(code == 0, f"{name} --allow-paths-outside: accepted ({out.strip()[-200:]})")
        code, out = run(exe, name, "--help")
        check("--allow-paths-outside" in out, f"{name} --help lists --allow-paths-outside")
    code, out = run(exe, "access", path, "--sensor", "Cam", "--target", "Sat", "--min-snr", "6")
    check(code == 2 and OUTSIDE in out, "access: refused")
    # Allowed, a missing file outside is an error of its own.
    code, out = run(exe, "validate", scenario(folder, "missing", "../missing.csv"), "--allow-paths-outside")
    check(code == 2 and "missing.csv" in out and OUTSIDE not in out, "allowed: a missing file is reported")

    check_mesh_files(exe, folder)

    if failures:
        sys.exit(f"FAILED: {len(failures)} checks: " + "; ".join(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
