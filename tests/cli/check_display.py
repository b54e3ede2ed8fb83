#!/usr/bin/env python3
"""Pictures people can read (issue 21 item 6): `eoir run`'s sensor PNGs
under each display stretch against astropy.visualization applied here to
the electrons FITS of the same frame, saturation shown white, and the
warnings about empty and saturated frames.

- --stretch zscale: the bytes are round(255 u) with u linear between
  astropy's ZScaleInterval() limits (IRAF's zscale); --stretch log and
  asinh: u between the frame's least and greatest electrons (AGC) through
  LogStretch() and AsinhStretch() (a = 1000, 0.1); a pixel at SATURATE is
  255. At most 1 byte apart (the FITS holds float32, the engine doubles) and
  99 % equal.
- The sensor parameter display_stretch chooses the same per sensor (here
  asinh), without --stretch; an unknown --stretch is refused naming
  display_stretch.
- A frame saturated all over is white (it was uniform grey 128) and warned
  about on stderr and in summary.json ("warnings", "saturated_fraction");
  a frame with nothing in the field (no star field, no object in view) is
  warned about; the star-field demo's frame has no warning.

usage: check_display.py EOIR_EXE STAR_FIELD_SCENARIO OUT_DIR
"""
import copy
import json
import os
import shutil
import subprocess
import sys

import matplotlib.image
import numpy as np
from astropy.io import fits
from astropy.visualization import AsinhStretch, LogStretch, MinMaxInterval, ZScaleInterval

from cli_checks import check, failures


def run(exe, scenario, out, *extra, ok=True):
    shutil.rmtree(out, ignore_errors=True)
    start = json.load(open(scenario))["start"]
    r = subprocess.run([exe, "run", scenario, "--out", out, "--stop", start, "--quiet", *extra],
                       capture_output=True, text=True)
    if ok and r.returncode != 0:
        sys.exit(f"eoir run {scenario} {extra} failed ({r.returncode}): {r.stderr}")
    summary = json.load(open(os.path.join(out, "summary.json"))) if r.returncode == 0 else None
    return r, summary


def frame_images(out, frame):
    """Electrons as the PNG's rows (top-down), the PNG bytes, the header."""
    with fits.open(os.path.join(out, frame["files"]["electrons"])) as hdul:
        electrons = np.flipud(hdul[0].data.astype(float))
        header = hdul[0].header
    png = matplotlib.image.imread(os.path.join(out, frame["files"]["sensor_png"]))
    png = np.rint((png[..., 0] if png.ndim == 3 else png) * 255).astype(int)
    return electrons, png, header


def expected_bytes(electrons, header, stretch):
    if stretch == "zscale":
        lo, hi = ZScaleInterval().get_limits(electrons)
        u = np.clip((electrons - lo) / (hi - lo), 0, 1)
    else:
        u = MinMaxInterval()(electrons)
        u = {"log": LogStretch(), "asinh": AsinhStretch(), "linear": lambda x: x}[stretch](u)
    b = np.rint(255 * u).astype(int)
    if "SATURATE" in header:
        b[electrons >= header["SATURATE"] * (1 - 1e-7)] = 255  # float32 of the level
    return b


def compare(tag, png, expected):
    diff = np.abs(png - expected)
    equal = float(np.mean(diff == 0))
    check(diff.max() <= 1 and equal >= 0.99,
          f"{tag}: PNG vs astropy: largest difference {diff.max()} byte, {100 * equal:.2f} % equal")


def main():
    exe, star_field, out = sys.argv[1:4]
    base = json.load(open(star_field))
    sensor = base["sensors"][0]["name"]

    # Each stretch from the command line.
    for stretch in ("zscale", "log", "asinh", "linear"):
        where = os.path.join(out, stretch)
        r, summary = run(exe, star_field, where, "--stretch", stretch)
        frame = summary["frames"][0]
        electrons, png, header = frame_images(where, frame)
        compare(f"--stretch {stretch}", png, expected_bytes(electrons, header, stretch))
        if stretch == "zscale":
            check(frame["warnings"] == [] and "warning" not in r.stderr,
                  f"the star-field demo's frame has no warning ({frame['warnings']})")

    # Per sensor: display_stretch among the sensor's parameters.
    per_sensor = copy.deepcopy(base)
    per_sensor["sensors"][0]["parameters"]["display_stretch"] = "asinh"
    path = os.path.join(out, "per_sensor.json")
    os.makedirs(out, exist_ok=True)
    json.dump(per_sensor, open(path, "w"), indent=1)
    where = os.path.join(out, "per_sensor")
    r, summary = run(exe, path, where)
    electrons, png, header = frame_images(where, summary["frames"][0])
    compare("display_stretch asinh (scenario)", png, expected_bytes(electrons, header, "asinh"))

    r, _ = run(exe, star_field, os.path.join(out, "bad"), "--stretch", "sqrt", ok=False)
    check(r.returncode != 0 and "--stretch sqrt" in r.stderr and "display_stretch" in r.stderr and
          "linear, log, asinh, zscale" in r.stderr, f"--stretch sqrt refused: {r.stderr.strip()}")

    # Saturated all over: white, and warned about.
    saturated = copy.deepcopy(base)
    saturated["sensors"][0]["parameters"]["saturation_pairs"] = [1000.0, 1e-30]
    saturated["sensors"][0]["parameters"]["noise_enabled"] = False  # the background light fills every pixel
    path = os.path.join(out, "saturated.json")
    json.dump(saturated, open(path, "w"), indent=1)
    where = os.path.join(out, "saturated")
    r, summary = run(exe, path, where)
    frame = summary["frames"][0]
    electrons, png, header = frame_images(where, frame)
    check(frame["saturated_fraction"] > 0.5 and np.mean(electrons >= header["SATURATE"] * (1 - 1e-7)) > 0.5,
          f"saturated frame: {100 * frame['saturated_fraction']:.1f} % of the pixels at SATURATE")
    check(np.all(png[electrons >= header["SATURATE"] * (1 - 1e-7)] == 255), "saturated pixels are white")
    check(frame["saturated_fraction"] == 1.0 and np.all(png == 255),
          "a frame saturated all over is white (it was uniform grey 128)")
    check(len(frame["warnings"]) == 1 and "saturated" in frame["warnings"][0],
          f"summary warns: {frame['warnings']}")
    check("warning" in r.stderr and "pixels are saturated" in r.stderr and sensor in r.stderr,
          f"stderr warns (with --quiet): {r.stderr.strip()}")

    # Nothing in the field: no star field, the camera on the target's side
    # away from everything (the target behind it).
    empty = copy.deepcopy(base)
    empty.pop("stars", None)
    empty["objects"] = [o for o in empty["objects"] if o["name"] == empty["sensors"][0]["parent"]]
    empty["central_bodies"] = []
    empty["sensors"][0]["pointing"] = {"type": "fixed_inertial", "quaternion": [1, 0, 0, 0]}
    path = os.path.join(out, "empty.json")
    json.dump(empty, open(path, "w"), indent=1)
    where = os.path.join(out, "empty")
    r, summary = run(exe, path, where)
    frame = summary["frames"][0]
    check(len(frame["warnings"]) == 1 and frame["warnings"][0].startswith("nothing in the field"),
          f"empty frame: summary warns {frame['warnings']}")
    check("nothing in the field" in r.stderr, f"empty frame: stderr warns: {r.stderr.strip()}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
