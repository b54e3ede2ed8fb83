#!/usr/bin/env python3
"""The FITS WCS of `eoir run` against a plate solution by astrometry.net
(issue 21 item 1): solve-field (Debian astrometry.net, Lang et al. 2010,
AJ 139, 1782) with the Tycho-2 index files 4110-4119
(astrometry-data-tycho2-10-19) solves the noise-free electrons of a frame of
the star-field demo, knowing nothing of the engine. The demo's optics image
a star within one pixel (F/2: an Airy disc of 3 um on 31 um pixels), where
any centroid is quantised (0.1-0.25 pixel RMS, so the plate scale of ~25
stars only to 3e-4); here its sensor gets a line-of-sight jitter of
0.1 mrad (eq. 38: one pixel RMS), which samples the stars as an
astronomical camera does (centroids to 0.02 pixel). Its solution (TAN, linear
fit to every matched star: --tweak-order 1, reference pixel at the image
centre) must agree with the frame's own WCS within 0.1 pixel at the centre
and within 1e-4 in scale: the frame's WCS is astrometric (ICRS, the field's
aberration and light deflection absorbed) as a plate solution is. The
apparent boresight (BORE_RA/BORE_DEC: the sensor's axis in J2000, what a WCS
of apparent places would put at the centre) lies about 1 pixel away (the
annual aberration, 20"), so the check tells the two apart. Besides, the
stars astrometry.net matched sit at their Tycho-2 places within 1.5" of the
truth's astrometric places (median; Tycho-2 at epoch J2000.0 against places
moved by proper motion to 2010).

usage: check_astrometry_net.py EOIR_EXE SCENARIO OUT_DIR
"""
import json
import math
import os
import shutil
import subprocess
import sys
import time
import warnings

import numpy as np
from astropy.io import fits
from astropy.wcs import WCS, FITSFixedWarning

from cli_checks import check, failures

JITTER_MRAD = 0.1  # one pixel RMS of the demo's 3 deg / 512 camera


def unit(ra, dec):
    ra, dec = np.radians(ra), np.radians(dec)
    return np.array([np.cos(dec) * np.cos(ra), np.cos(dec) * np.sin(ra), np.sin(dec)])


def arcsec(a, b):
    return math.degrees(math.atan2(np.linalg.norm(np.cross(a, b)), float(a @ b))) * 3600.0


def scale_deg(w):
    cd = w.wcs.cd if w.wcs.has_cd() else w.pixel_scale_matrix
    return math.sqrt(abs(np.linalg.det(cd)))


def main():
    exe, scenario, out = sys.argv[1:4]
    if shutil.which("solve-field") is None:
        sys.exit("solve-field not found: install the Debian packages astrometry.net and "
                 "astrometry-data-tycho2-10-19 (.ci/setup)")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    doc = json.load(open(scenario))
    doc.pop("$schema", None)
    for sensor in doc["sensors"]:
        sensor["parameters"]["jitter_mrad"] = JITTER_MRAD
    scenario = os.path.join(out, "star_field_jitter.json")
    json.dump(doc, open(scenario, "w"), indent=1)
    start = doc["start"]
    r = subprocess.run([exe, "run", scenario, "--out", out, "--stop", start, "--quiet"], capture_output=True,
                       text=True)
    if r.returncode != 0:
        sys.exit(f"eoir run failed ({r.returncode}): {r.stderr}")
    frame = json.load(open(os.path.join(out, "summary.json")))["frames"][0]
    image = os.path.join(out, frame["files"]["mean_electrons"])
    truth = json.load(open(os.path.join(out, frame["files"]["truth"])))
    header = fits.getheader(image)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FITSFixedWarning)  # obsfix filling in OBSGEO-L/B/H (astropy #10365)
        ours = WCS(header)
    width, height = header["NAXIS1"], header["NAXIS2"]
    pixel = scale_deg(ours)

    solve = os.path.join(out, "solve")
    os.makedirs(solve)
    args = ["solve-field", image, "--dir", solve, "--no-plots", "--overwrite", "--new-fits", "none",
            "--scale-units", "arcsecperpix", "--scale-low", f"{pixel * 3600 * 0.95:.4f}",
            "--scale-high", f"{pixel * 3600 * 1.05:.4f}", "--ra", f"{header['CRVAL1']:.6f}",
            "--dec", f"{header['CRVAL2']:.6f}", "--radius", "5", "--cpulimit", "60",
            "--crpix-center", "--tweak-order", "1", "--no-remove-lines", "--uniformize", "0"]
    began = time.monotonic()
    r = subprocess.run(args, capture_output=True, text=True)
    seconds = time.monotonic() - began
    solution = os.path.join(solve, os.path.splitext(os.path.basename(image))[0] + ".wcs")
    if r.returncode != 0 or not os.path.exists(solution):
        print(r.stdout[-3000:], r.stderr[-3000:])
        sys.exit(f"solve-field did not solve the frame ({r.returncode})")
    print(f"solve-field solved {os.path.basename(image)} in {seconds:.1f} s")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FITSFixedWarning)
        theirs = WCS(fits.getheader(solution))

    # The image centre (our reference pixel) through both WCS.
    centre = np.array([[(width + 1) / 2.0, (height + 1) / 2.0]])
    a = unit(*ours.all_pix2world(centre, 1)[0])
    b = unit(*theirs.all_pix2world(centre, 1)[0])
    offset_px = arcsec(a, b) / (pixel * 3600)
    check(offset_px < 0.1, f"centre: the two WCS agree within {offset_px:.3f} pixel ({arcsec(a, b):.2f}\") < 0.1")
    ratio = scale_deg(theirs) / pixel
    check(abs(ratio - 1) < 1e-4, f"scale: astrometry.net / ours - 1 = {ratio - 1:.2e} (limit 1e-4)")
    # Rotation: the direction of north at the centre in each WCS.
    def north_angle(w):
        ra, dec = w.all_pix2world(centre, 1)[0]
        x1 = w.all_world2pix([[ra, dec + 0.01]], 1)[0]
        return math.degrees(math.atan2(x1[1] - centre[0][1], x1[0] - centre[0][0]))
    turn = (north_angle(theirs) - north_angle(ours) + 180) % 360 - 180
    check(abs(turn) * math.radians(1) * width / 2 < 0.1,
          f"rotation: {turn * 3600:.1f}\" ({abs(math.radians(turn)) * width / 2:.3f} pixel at the edge)")
    # The apparent boresight: what a WCS of apparent places would centre on.
    apparent = unit(header["BORE_RA"], header["BORE_DEC"])
    apparent_px = arcsec(apparent, b) / (pixel * 3600)
    check(apparent_px > 0.3, f"the apparent boresight lies {apparent_px:.2f} pixel from the solution "
                             "(the check tells astrometric from apparent)")

    # The stars astrometry.net matched: Tycho-2 places against the truth's.
    corr = os.path.join(solve, os.path.splitext(os.path.basename(image))[0] + ".corr")
    stars = [t for t in truth if t["kind"] == "star"]
    offsets = []
    if os.path.exists(corr):
        c = fits.getdata(corr)
        for fx, fy, ira, idec in zip(c["field_x"], c["field_y"], c["index_ra"], c["index_dec"]):
            near = min(stars, key=lambda t: math.hypot(t["x_fits"] - fx, t["y_fits"] - fy))
            if math.hypot(near["x_fits"] - fx, near["y_fits"] - fy) < 2:
                offsets.append(arcsec(unit(ira, idec), unit(near["ra_deg"], near["dec_deg"])))
    median = float(np.median(offsets)) if offsets else float("inf")
    check(len(offsets) >= 5 and median < 1.5,
          f"{len(offsets)} matched stars: Tycho-2 - truth astrometric place, median {median:.2f}\" < 1.5\"")
    print(json.dumps({"solve_s": round(seconds, 2), "centre_offset_px": round(offset_px, 4),
                      "centre_offset_arcsec": round(arcsec(a, b), 3), "scale_ratio_minus_1": float(ratio - 1),
                      "rotation_arcsec": round(turn * 3600, 2), "apparent_boresight_px": round(apparent_px, 3),
                      "matched_stars": len(offsets), "median_star_offset_arcsec": round(median, 3)}))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
