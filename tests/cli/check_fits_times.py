#!/usr/bin/env python3
"""Times, observer and detector cards of `eoir run`'s FITS files (issue 21
item 2), read with astropy as an observer's pipeline would:

- FITS 4.0 section 9 and the FITS time paper (Rots et al. 2015, A&A 574,
  A36): DATE-OBS is the start of the integration and equals DATE-BEG;
  DATE-AVG is its middle (the frame time of summary.json and the truth);
  DATE-END - DATE-BEG = EXPTIME (MJD cards: 1 us; ISO cards: 1 ms);
  MJD-OBS/-BEG/-AVG/-END are the DATE cards as MJD (1 us); TIMESYS 'UTC',
  TREFPOS 'TOPOCENTER'; astropy's WCS reads every date, and the only
  FITSFixedWarning is wcslib filling in OBSGEO-L/B/H from OBSGEO-X/Y/Z
  (astropy issue #10365; FITS 4.0 section 8.4.1 allows one set per HDU);
- the observer at DATE-AVG: for a spacecraft (the star-field demo's GEO
  observer on a circular Kepler orbit) OBSJ2K-X/Y/Z and OBSJ2KVX/VY/VZ equal
  the orbit computed here, r = a (cos nu, sin nu, 0), v = sqrt(GM / a)
  (-sin nu, cos nu, 0) at the epoch (1 m, 1 mm/s), and OBSGEO-X/Y/Z is that
  position in ITRS by pyerfa (eraC2t06a with UT1 = UTC and no polar motion,
  the engine's documented model; 1 m); for a site (tests/cli/data/
  site_tracks_iss.json) OBSGEO-X/Y/Z is the site's WGS84 latitude,
  longitude and height (astropy EarthLocation; 1e-7 deg, 1 cm) and there
  are no OBSJ2K cards;
- GAIN = 1 electron/adu on the electron images; SATURATE and RDNOISE on the
  electrons image only, equal to SEI and dark NEI times the peak irradiance
  responsivity of `eoir report` (eqs. 43, 45; 1e-9);
- the truth gives each object's start, middle and end times (DATE-BEG,
  DATE-AVG, DATE-END) with its RA/Dec at each.

usage: check_fits_times.py EOIR_EXE STAR_FIELD_SCENARIO SITE_SCENARIO OUT_DIR
"""
import json
import math
import os
import shutil
import subprocess
import sys
import warnings

import erfa
import numpy as np
from astropy import units as u
from astropy.coordinates import EarthLocation
from astropy.io import fits
from astropy.time import Time
from astropy.utils import iers
from astropy.wcs import WCS, FITSFixedWarning

from cli_checks import check, failures, first_frame

iers.conf.auto_download = False
GM_EARTH = 3.986004418e14  # m^3/s^2 (the scenarios' Kepler motion, EGM96/WGS84)


def report(exe, scenario, sensor):
    r = subprocess.run([exe, "report", scenario, "--provider", "EOIR Radiometric Performance", "--sensor", sensor,
                        "--format", "json", "--stop", json.load(open(scenario))["start"], "--quiet"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"eoir report failed: {r.stderr}")
    return {k: v["value"] for k, v in json.loads(r.stdout)["rows"][0]["values"].items()}


def utc(text):
    return Time(text, format="fits", scale="utc")


def check_times(tag, h, frame, truth):
    exptime = h["EXPTIME"]
    check(h["DATE-OBS"] == h["DATE-BEG"], f"{tag}: DATE-OBS = DATE-BEG = {h['DATE-OBS']} (the start)")
    check(h["TIMESYS"] == "UTC" and h["TREFPOS"] == "TOPOCENTER", f"{tag}: TIMESYS UTC, TREFPOS TOPOCENTER")
    beg, avg, end = utc(h["DATE-BEG"]), utc(h["DATE-AVG"]), utc(h["DATE-END"])
    check(abs((end - beg).sec - exptime) < 1e-3, f"{tag}: DATE-END - DATE-BEG = {(end - beg).sec} s = EXPTIME")
    check(abs((avg - beg).sec - exptime / 2) < 1e-3, f"{tag}: DATE-AVG is the middle")
    check(abs((h["MJD-END"] - h["MJD-BEG"]) * 86400 - exptime) < 1e-6, f"{tag}: MJD-END - MJD-BEG = EXPTIME (1 us)")
    for key, date in (("MJD-OBS", "DATE-OBS"), ("MJD-BEG", "DATE-BEG"), ("MJD-AVG", "DATE-AVG"),
                      ("MJD-END", "DATE-END")):
        check(abs(h[key] - utc(h[date]).mjd) * 86400 < 1e-3, f"{tag}: {key} = {date} (ms of the ISO text)")
    check(h["DATE-AVG"] + "Z" == frame["time"], f"{tag}: DATE-AVG is summary.json's frame time {frame['time']}")
    check(h["DATE-BEG"] + "Z" == frame["start_time"] and h["DATE-END"] + "Z" == frame["end_time"],
          f"{tag}: summary start_time, end_time")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        w = WCS(h)
    unexpected = [str(c.message) for c in caught
                  if not (issubclass(c.category, FITSFixedWarning) and "Set OBSGEO-L" in str(c.message))]
    check(not unexpected, f"{tag}: astropy WCS reads the header without other warnings {unexpected}")
    check(w.wcs.dateobs == h["DATE-OBS"] and w.wcs.dateavg == h["DATE-AVG"] and w.wcs.dateend == h["DATE-END"],
          f"{tag}: astropy's WCS has DATE-OBS/AVG/END")
    check(abs(w.wcs.mjdavg - h["MJD-AVG"]) < 1e-12, f"{tag}: astropy's WCS has MJD-AVG")
    check(all(t["start_time"] == frame["start_time"] and t["time"] == frame["time"] and
              t["end_time"] == frame["end_time"] for t in truth), f"{tag}: {len(truth)} truth rows: start, middle "
                                                                   "and end times")
    check(all(t[k] is not None for t in truth for k in ("start_ra_deg", "start_dec_deg", "end_ra_deg", "end_dec_deg")),
          f"{tag}: truth RA/Dec at the start and the end")
    return w


def itrs_of(j2000_m, date_avg):
    t = utc(date_avg)
    tt = t.tt
    c2t = erfa.c2t06a(tt.jd1, tt.jd2, t.jd1, t.jd2, 0.0, 0.0)  # UT1 = UTC, no polar motion
    return c2t @ np.asarray(j2000_m)


def main():
    exe, star_field, site_scenario, out = sys.argv[1:5]

    # A spacecraft: the star-field demo's GEO observer.
    summary = first_frame(exe, star_field, os.path.join(out, "spacecraft"))
    frame = summary["frames"][0]
    files = {k: os.path.join(out, "spacecraft", v) for k, v in frame["files"].items()}
    truth = json.load(open(files["truth"]))
    sc = json.load(open(star_field))
    sensor = next(s for s in sc["sensors"] if s["name"] == frame["sensor"])
    orbit = next(o for o in sc["objects"] if o["name"] == sensor["parent"])["motion"]
    check(orbit["type"] == "kepler" and orbit["eccentricity"] == 0 and orbit["inclination_deg"] == 0 and
          orbit["raan_deg"] == 0 and orbit["arg_perigee_deg"] == 0, "the demo's observer is on a circular equatorial orbit")
    headers = {k: fits.getheader(files[k]) for k in ("electrons", "mean_electrons", "radiance")}
    for key, h in headers.items():
        check_times(f"spacecraft {key}", h, frame, truth)
    h = headers["electrons"]
    a = orbit["semi_major_axis_km"] * 1e3
    n = math.sqrt(GM_EARTH / a ** 3)
    dt = (utc(h["DATE-AVG"]) - Time(orbit["epoch"].rstrip("Z"), format="isot", scale="utc")).sec
    nu = math.radians(orbit["true_anomaly_deg"]) + n * dt
    r = a * np.array([math.cos(nu), math.sin(nu), 0.0])
    v = math.sqrt(GM_EARTH / a) * np.array([-math.sin(nu), math.cos(nu), 0.0])
    got_r = np.array([h[f"OBSJ2K-{c}"] for c in "XYZ"])
    got_v = np.array([h[f"OBSJ2KV{c}"] for c in "XYZ"])
    check(np.linalg.norm(got_r - r) < 1.0, f"spacecraft: OBSJ2K = the circular orbit at DATE-AVG "
                                            f"({np.linalg.norm(got_r - r):.2e} m)")
    check(np.linalg.norm(got_v - v) < 1e-3, f"spacecraft: OBSJ2KV = its velocity ({np.linalg.norm(got_v - v):.2e} m/s)")
    geo = np.array([h[f"OBSGEO-{c}"] for c in "XYZ"])
    check(np.linalg.norm(geo - itrs_of(r, h["DATE-AVG"])) < 1.0,
          f"spacecraft: OBSGEO = ITRS of that position at DATE-AVG ({np.linalg.norm(geo - itrs_of(r, h['DATE-AVG'])):.2e} m)")
    # Detector cards.
    perf = report(exe, star_field, frame["sensor"])
    resp = perf["Peak Irradiance Responsivity"]
    check(h["GAIN"] == 1.0, "electrons: GAIN = 1 electron/adu")
    check(abs(h["SATURATE"] / (perf["SEI"] * resp) - 1) < 1e-9, f"electrons: SATURATE {h['SATURATE']} = SEI x R")
    check(abs(h["RDNOISE"] / (perf["Dark NEI"] * resp) - 1) < 1e-9, f"electrons: RDNOISE {h['RDNOISE']} = dark NEI x R")
    m = headers["mean_electrons"]
    check(m["GAIN"] == 1.0 and "SATURATE" not in m and "RDNOISE" not in m,
          "mean electrons (noise-free, unclipped): GAIN only")
    check("GAIN" not in headers["radiance"], "radiance: no GAIN")

    # A site on the ground.
    summary = first_frame(exe, site_scenario, os.path.join(out, "site"))
    sc = json.load(open(site_scenario))
    for frame in summary["frames"]:
        files = {k: os.path.join(out, "site", v) for k, v in frame["files"].items()}
        h = fits.getheader(files["electrons"])
        tag = f"site {frame['sensor']}"
        check_times(tag, h, frame, json.load(open(files["truth"])))
        sensor = next(s for s in sc["sensors"] if s["name"] == frame["sensor"])
        site = next(o for o in sc["objects"] if o["name"] == sensor["parent"])["motion"]
        g = EarthLocation.from_geocentric(h["OBSGEO-X"], h["OBSGEO-Y"], h["OBSGEO-Z"], unit=u.m).to_geodetic("WGS84")
        check(abs(g.lat.deg - site["lat_deg"]) < 1e-7 and abs(g.lon.deg - site["lon_deg"]) < 1e-7 and
              abs(g.height.to_value(u.m) - site["alt_m"]) < 0.01,
              f"{tag}: OBSGEO-X/Y/Z is the site ({g.lat.deg:.9f}, {g.lon.deg:.9f}, {g.height.to_value(u.m):.4f} m)")
        check(not any(k.startswith("OBSJ2K") for k in h), f"{tag}: no J2000 state for a site")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
