#!/usr/bin/env python3
"""`eoir run --cube` streams the data cube (issue 23 item 2): the cube is
the file the run wrote before, when it held every frame in memory:

- the primary header is the electrons header of frame 0 with exactly the
  cube's cards added or changed (NAXIS = 3, NAXIS3 = the time steps,
  IMAGTYPE 'sensor_electrons_cube', WCSAXES 3 and the linear TIME axis
  CTYPE3/CUNIT3/CRVAL3/CRPIX3/CD3_3/MJDREF/DATEREF, NFRAMES, two COMMENT
  cards), in the same order, with CHECKSUM/DATASUM that verify;
- plane k equals the electrons file of frame k bit for bit (float32);
- the TIMES table holds each frame's DATE-OBS, DATE-AVG, MJD-OBS, MJD-AVG,
  BORE_RA/DEC and UP_RA/DEC as the frame's own header gives them;
- a run that fails half-way (the ephemeris of ephemeris_too_short.json ends
  at 18:10) leaves no cube and no temporary file in a fresh folder, and an
  earlier run's cube in the same folder as it was.

usage: check_run_cube.py EOIR_EXE WCS_SCENARIO SHORT_SCENARIO WORK_DIR
"""
import os
import shutil
import subprocess
import sys
import json

import numpy as np
from astropy.io import fits

from cli_checks import check, failures, run


CUBE_ONLY = {"NAXIS3", "WCSAXES", "CTYPE3", "CUNIT3", "CRVAL3", "CRPIX3", "CD3_3", "MJDREF", "DATEREF", "NFRAMES"}
CHANGED = {"NAXIS", "IMAGTYPE", "WCSAXES"}
NOT_COMPARED = {"CHECKSUM", "DATASUM", "COMMENT"}


def cards(header):
    return [(c.keyword, c.value) for c in header.cards]


def check_cube(exe, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    code, text = run(exe, "run", scenario, "--out", out, "--cube", "--quiet")
    check(code == 0, f"eoir run --cube succeeds ({text.strip()[-300:]})")
    if code != 0:
        return
    summary = json.load(open(os.path.join(out, "summary.json")))
    frames = [fr for fr in summary["frames"] if fr["sensor"] == "Cam"]
    steps = summary["time_steps"]
    check(len(frames) == steps == 3, f"three frames of Cam ({len(frames)}, {steps} steps)")
    check(not [f for f in os.listdir(out) if ".tmp." in f], "no temporary files left")
    with fits.open(os.path.join(out, summary["cubes"]["Cam"]), checksum=True) as cube_hdul, \
            fits.open(os.path.join(out, frames[0]["files"]["electrons"])) as first:
        cube, times = cube_hdul[0], cube_hdul["TIMES"].data
        check(cube_hdul[0].verify_checksum() == 1 and cube_hdul["TIMES"].verify_checksum() == 1, "checksums verify")
        h0, hc = first[0].header, cube.header
        check(hc["NAXIS"] == 3 and hc["NAXIS3"] == steps and hc["NFRAMES"] == steps, "NAXIS3 = NFRAMES = time steps")
        check(hc["IMAGTYPE"] == "sensor_electrons_cube" and hc["WCSAXES"] == 3, "IMAGTYPE, WCSAXES of a cube")
        # The frame's cards, in order, then the cube's own (as the in-memory writer had them).
        frame_cards = [c for c in cards(h0) if c[0] not in NOT_COMPARED | CHANGED]
        cube_cards = [c for c in cards(hc) if c[0] not in NOT_COMPARED | CHANGED | CUBE_ONLY]
        check(frame_cards == cube_cards,
              "cube header = frame 0's electrons header but for the cube's cards "
              f"(differences: {set(frame_cards) ^ set(cube_cards)})")
        extra = [c.keyword for c in hc.cards if c.keyword in CUBE_ONLY]
        check(extra == ["NAXIS3", "WCSAXES", "CTYPE3", "CUNIT3", "CRVAL3", "CRPIX3", "CD3_3", "MJDREF", "DATEREF",
                        "NFRAMES"], f"the cube's cards, in order: {extra}")
        # cfitsio splits a comment into cards of 72 characters.
        extra_comments = "".join(list(hc["COMMENT"])[len(list(h0["COMMENT"])):])
        check(extra_comments == "Plane k (1-based) is time step k-1 of the run; its time and pointing are in the "
              "TIMES table.The celestial WCS is the first plane's.", f"the cube's comments: {extra_comments!r}")
        check(abs(hc["CD3_3"] - 60.0) == 0 and hc["MJDREF"] == h0["MJD-AVG"] and hc["DATEREF"] == h0["DATE-AVG"],
              "time axis: 60 s steps from frame 0's DATE-AVG")
        for k, fr in enumerate(frames):
            with fits.open(os.path.join(out, fr["files"]["electrons"])) as f:
                plane, hk = f[0].data, f[0].header
                check(cube.data.dtype == plane.dtype and np.array_equal(cube.data[k], plane, equal_nan=True),
                      f"plane {k} = {fr['files']['electrons']} bit for bit")
                row = [times["FRAME"][k], times["DATE-OBS"][k], times["DATE-AVG"][k], times["MJD-OBS"][k],
                       times["MJD-AVG"][k], times["BORE_RA"][k], times["BORE_DEC"][k], times["UP_RA"][k],
                       times["UP_DEC"][k]]
                want = [k, hk["DATE-OBS"], hk["DATE-AVG"], hk["MJD-OBS"], hk["MJD-AVG"], hk["BORE_RA"],
                        hk["BORE_DEC"], hk["UP_RA"], hk["UP_DEC"]]
                check(row == want, f"TIMES row {k} = frame {k}'s header ({row} vs {want})")


def check_failed_run(exe, scenario, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    args = [exe, "run", scenario, "--out", work, "--sensor", "Sensor1", "--quiet", "--step", "120", "--cube",
            "--start", "2010-08-25T18:08:00Z"]
    code, text = run(*args, "--stop", "2010-08-25T18:12:00Z")
    files = sorted(os.listdir(work))
    check(code == 2 and "outside the ephemeris" in text, "the --cube run fails at 18:12")
    check(any(f.startswith("Sensor1_0001_") for f in files), "frames 0 and 1 were written")
    check(not [f for f in files if "cube" in f], f"no cube in a fresh folder ({files})")
    check(not [f for f in files if ".tmp." in f], "no temporary file")
    code, text = run(*args, "--stop", "2010-08-25T18:10:00Z")
    cube = os.path.join(work, "Sensor1_electrons_cube.fits")
    check(code == 0 and os.path.exists(cube), "a complete --cube run writes the cube")
    before = open(cube, "rb").read() if os.path.exists(cube) else b""
    code, text = run(*args, "--stop", "2010-08-25T18:12:00Z")
    check(code == 2, "the failing run again")
    after = open(cube, "rb").read() if os.path.exists(cube) else b""
    check(before and after == before, "the earlier cube is left as it was")
    check(not [f for f in os.listdir(work) if ".tmp." in f], "no temporary file")


def main():
    exe, wcs_scenario, short_scenario, work = sys.argv[1:5]
    check_cube(exe, wcs_scenario, os.path.join(work, "cube"))
    check_failed_run(exe, short_scenario, os.path.join(work, "failed"))
    if failures:
        sys.exit(f"FAILED: {len(failures)} checks: " + "; ".join(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
