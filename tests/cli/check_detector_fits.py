#!/usr/bin/env python3
"""The detector stage in `eoir run`'s FITS (issue 23 item 4; README
"Detector model"): with the sensor's detector_model on each frame has an
`_adu.fits` of unsigned integers, BITPIX 16 with BZERO 32768 for a 14-bit
ADC (BITPIX 32 with BZERO 2^31 for a 20-bit one), equal pixel for pixel to
clip(floor(e / GAIN + BIASLEV + 1/2), 0, 2^bits - 1) of the frame's
electrons FITS (read noise 0, so the electrons are whole numbers, exact in
float32), header cards GAIN, SATURATE (the ADU of a full well), DATAMAX,
BIASLEV; the electrons FITS' SATURATE is the full well; summary.json lists
the file (schemas/run_summary.schema.json). With the stage off there is no
ADU file.

usage: check_detector_fits.py EOIR_EXE STAR_FIELD_SCENARIO OUT_DIR
"""
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np
from astropy.io import fits

from cli_checks import check, failures, first_frame


def main():
    exe, scenario, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    sc = json.load(open(scenario))
    params = sc["sensors"][0]["parameters"]
    params.update(horizontal_pixels=128, vertical_pixels=128, horizontal_fov_deg=0.75, vertical_fov_deg=0.75)

    # Off: the spec's model, no ADU file.
    path = os.path.join(out, "off.json")
    json.dump(sc, open(path, "w"))
    summary = first_frame(exe, path, os.path.join(out, "off"))
    check("adu" not in summary["frames"][0]["files"], "detector_model off: no ADU file")

    for bits, bitpix, bzero in ((14, 16, 32768), (20, 32, 2147483648)):
        gain, bias, well = 0.75, 120.0, 3.0e4
        params.update(detector_model=True, noise_enabled=True, gain_e_per_adu=gain, bias_adu=bias, read_noise_e=0.0, full_well_e=well,
                      adc_bits=bits, dark_current_e_s=30.0, dsnu_e_s=3.0, prnu_fraction=0.01,
                      hot_pixel_fraction=0.001, dead_pixel_fraction=0.001)
        path = os.path.join(out, f"on_{bits}.json")
        json.dump(sc, open(path, "w"))
        run_dir = os.path.join(out, f"on_{bits}")
        frame = first_frame(exe, path, run_dir)["frames"][0]
        check("adu" in frame["files"], f"{bits} bits: summary.json lists the ADU file")
        with fits.open(os.path.join(run_dir, frame["files"]["adu"]), do_not_scale_image_data=True) as hdul:
            h = hdul[0].header
            check(h["BITPIX"] == bitpix and h["BZERO"] == bzero,
                  f"{bits} bits: BITPIX {h['BITPIX']} BZERO {h['BZERO']} (expected {bitpix}, {bzero})")
        with fits.open(os.path.join(run_dir, frame["files"]["adu"])) as hdul:
            adu = hdul[0].data.astype(np.int64)
            h = hdul[0].header
        with fits.open(os.path.join(run_dir, frame["files"]["electrons"])) as hdul:
            e = hdul[0].data.astype(np.float64)
            he = hdul[0].header
        top = 2 ** bits - 1
        expected = np.clip(np.floor(e / gain + bias + 0.5), 0, top).astype(np.int64)
        check(np.array_equal(adu, expected), f"{bits} bits: ADU = clip(floor(e / gain + bias + 1/2), 0, 2^bits - 1)"
              f" ({int(np.sum(adu != expected))} of {adu.size} differ)")
        check(np.all(e == np.floor(e)) and float(e.max()) <= well, f"{bits} bits: whole electrons within the full well")
        check(h["BUNIT"] == "adu" and h["GAIN"] == gain and h["BIASLEV"] == bias and h["DATAMAX"] == top,
              f"{bits} bits: BUNIT, GAIN, BIASLEV, DATAMAX cards")
        check(h["SATURATE"] == min(top, math.floor(well / gain + bias + 0.5)), f"{bits} bits: SATURATE (ADU)")
        check(he["SATURATE"] == well, f"{bits} bits: electrons SATURATE is the full well")
        check("RDNOISE" not in h, f"{bits} bits: no RDNOISE with read noise 0")

    if failures:
        sys.exit(f"{len(failures)} check(s) failed")


main()
