#!/usr/bin/env python3
"""FITS output of `eoir run` read the way astronomers read it (astropy):

- DATE-OBS parses as a FITS time (no trailing 'Z') and WCS() reads every
  header without a warning; BUNIT parses in FITS unit syntax ('electron',
  'W cm-2 sr-1');
- the WCS maps each truth RA/Dec (astrometric: both the WCS and the truth
  absorb the field's aberration) to the truth pixel (written in the FITS
  convention x_fits, y_fits) within 0.05 pixel;
- FITS rows: the data as astropy reads them (row 0 = FITS row 1 = bottom)
  peak at (y_fits - 1, x_fits - 1), and flipped upside down they peak where
  the PNG (row 0 = top) does: ds9 shows the picture of the PNG;
- the ds9 region file holds a circle at each truth RA/Dec;
- with --cube, <sensor>_electrons_cube.fits holds every frame (plane k =
  the electrons file of frame k), a TIMES table with each plane's DATE-OBS
  (start) and DATE-AVG,
  and the first frame's celestial WCS.

usage: check_fits_astropy.py EOIR_EXE SCENARIO OUT_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys
import warnings

import numpy as np
from astropy import units as u
from astropy.io import fits
from astropy.time import Time
from astropy.utils import iers
from astropy.wcs import WCS, FITSFixedWarning
import matplotlib.image

iers.conf.auto_download = False  # no network; UTC-only arithmetic below needs no tables

failures = 0


def check(ok, what):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += not ok


def allow_obsgeo_fill_in():
    """The one FITSFixedWarning a correct header gets: wcslib fills in
    OBSGEO-L/B/H from OBSGEO-X/Y/Z and says so (astropy issue #10365), though
    FITS 4.0 section 8.4.1 allows only one set of coordinates per HDU."""
    warnings.filterwarnings("ignore", message=r".*'obsfix' made the change 'Set OBSGEO-L",
                            category=FITSFixedWarning)


def main():
    exe, scenario, out = sys.argv[1:4]
    shutil.rmtree(out, ignore_errors=True)
    r = subprocess.run([exe, "run", scenario, "--out", out, "--cube", "--quiet"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"eoir run failed ({r.returncode}): {r.stderr}")
    summary = json.load(open(os.path.join(out, "summary.json")))
    worst = 0.0
    for fr in summary["frames"]:
        tag = f"{fr['sensor']} frame {fr['index']}"
        files = fr["files"]
        truth = json.load(open(os.path.join(out, files["truth"])))
        check(len(truth) == 3, f"{tag}: three targets in the truth")
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # astropy's FITSFixedWarning for 'Z' dates fails here
            allow_obsgeo_fill_in()
            for key, unit in (("electrons", u.electron), ("mean_electrons", u.electron),
                              ("radiance", u.W / u.cm ** 2 / u.sr)):
                h = fits.getheader(os.path.join(out, files[key]))
                t = Time(h["DATE-OBS"], format="fits", scale="utc")
                want = Time(fr["start_time"].rstrip("Z"), format="isot", scale="utc")
                check(abs(t.mjd - want.mjd) * 86400 < 1e-6,
                      f"{tag} {key}: DATE-OBS {h['DATE-OBS']!r} is a FITS time (the start of the integration)")
                # astropy reads BUNIT (CCDData, nddata) with its generic parser;
                # the radiance unit is also valid in the strict FITS syntax
                check(u.Unit(h["BUNIT"]) == unit, f"{tag} {key}: BUNIT {h['BUNIT']!r} = {unit}")
                if key == "radiance":
                    check(u.Unit(h["BUNIT"], format="fits") == unit, f"{tag} {key}: BUNIT in FITS syntax")
                WCS(h)
            with fits.open(os.path.join(out, files["mean_electrons"])) as hdul:
                w = WCS(hdul[0].header)
                data = hdul[0].data.astype(float)
        height, width = data.shape
        for t in truth:
            x, y = w.world_to_pixel_values(t["ra_deg"], t["dec_deg"])  # 0-based
            err = float(np.hypot(x + 1 - t["x_fits"], y + 1 - t["y_fits"]))
            worst = max(worst, err)
            check(err < 0.05, f"{tag} {t['object']}: WCS(RA, Dec) - truth pixel = {err:.4f} px")
            # the image peaks at the truth pixel (rows bottom-up as astropy reads them)
            iy, ix = int(round(t["y_fits"])) - 1, int(round(t["x_fits"])) - 1
            window = data[max(iy - 2, 0):iy + 3, max(ix - 2, 0):ix + 3]
            check(data[iy, ix] == window.max() and data[iy, ix] > 10 * np.median(data),
                  f"{tag} {t['object']}: data peak at FITS ({ix + 1}, {iy + 1})")
        png = matplotlib.image.imread(os.path.join(out, files["sensor_png"]))
        png = png[..., 0] if png.ndim == 3 else png
        top_down = np.flipud(data)
        py, px = np.unravel_index(np.argmax(top_down), top_down.shape)
        check(png[py, px] == png.max(), f"{tag}: the FITS flipped to top-down peaks where the PNG does ({px}, {py})")
        check(png[height - 1 - py, px] < png.max(), f"{tag}: ... and not where the unflipped FITS would put it")
        regions = open(os.path.join(out, files["regions"])).read()
        circles = re.findall(r"circle\(([-0-9.]+),([-0-9.]+),[0-9.]+\"\) # text=\{(\w+)\}", regions)
        check(regions.startswith("# Region file format: DS9") and "\nicrs\n" in regions, f"{tag}: ds9 region header")
        check(sorted(c[2] for c in circles) == sorted(t["object"] for t in truth), f"{tag}: one circle per object")
        for ra, dec, name in circles:
            t = next(t for t in truth if t["object"] == name)
            check(abs(float(ra) - t["ra_deg"]) < 1e-8 and abs(float(dec) - t["dec_deg"]) < 1e-8,
                  f"{tag}: region of {name} at its RA/Dec")

    cube_name = summary["cubes"]["Cam"]
    with fits.open(os.path.join(out, cube_name)) as hdul:
        cube, times = hdul[0], hdul["TIMES"].data
        frames = [f for f in summary["frames"] if f["sensor"] == "Cam"]
        check(cube.data.shape == (len(frames),) + data.shape, f"cube shape {cube.data.shape}")
        for k, fr in enumerate(frames):
            plane = fits.getdata(os.path.join(out, fr["files"]["electrons"]))
            check(np.array_equal(cube.data[k], plane), f"cube plane {k} = {fr['files']['electrons']}")
            check(times["DATE-AVG"][k] + "Z" == fr["time"] and times["DATE-OBS"][k] + "Z" == fr["start_time"],
                  f"cube TIMES[{k}] {times['DATE-OBS'][k]}, {times['DATE-AVG'][k]}")
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            allow_obsgeo_fill_in()
            wc = WCS(cube.header)
        w0 = WCS(fits.getheader(os.path.join(out, frames[0]["files"]["electrons"])))
        probe = np.array([[1.0, 1.0], [32.5, 32.5], [64.0, 10.0]])
        check(np.allclose(wc.celestial.all_pix2world(probe, 1), w0.all_pix2world(probe, 1), atol=1e-12, rtol=0),
              "cube celestial WCS = first frame's")
        check(cube.header["CTYPE3"] == "TIME" and abs(cube.header["CD3_3"] - 60.0) < 1e-9, "cube time axis 60 s")
        check(hdul[0].verify_checksum() == 1 and hdul["TIMES"].verify_checksum() == 1, "cube checksums")
    print(f"largest WCS-truth difference {worst:.5f} pixel; {failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
