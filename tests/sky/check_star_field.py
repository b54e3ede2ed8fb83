#!/usr/bin/env python3
"""Star fields (issue 9, spec 4.1.6.1, 4.3.2): astrometry, photometry and
streaks of catalogue stars through the whole engine, against values computed
here independently.

- Astrometry: a Nyquist-sampled camera on a LEO satellite (7.5 km/s: 5" of
  aberration from its own velocity) stares at a field of stars from a CSV
  catalogue written here with proper motions up to 2"/yr and parallaxes up to
  0.3" (epoch J2000, frame in 2026). Centroids of the isolated stars with
  SNR > 50 in the noise-free image agree within 0.05 px RMS with
  (a) their apparent places computed with ERFA (pyerfa: eraApcs13 for an
  observer in space, eraAtciq) mapped to pixels by the gnomonic projection
  of the sensor's axes (the header's BORE_RA/DEC, UP_RA/DEC), and
  (b) their astrometric places (eraPmpx: proper motion and parallax, no
  deflection or aberration) mapped through the frame's FITS WCS (astropy),
  which is astrometric (issue 21 item 1). The truth's RA/Dec are those
  astrometric places within 1 mas.
- Photometry: the noise-free electrons of a star summed over the image (the
  star alone at the centre) equal R_peak,E E / ENSQ (eqs. 50-51) within 1 %,
  with E the band integral of m0 B(T) computed here: T from B-V by Ballesteros
  (2012) eq. 14, m0 such that m0 B(0.55 um, T) = 3.631e-12 10^(-0.4 V)
  W cm^-2 um^-1 (Bessell, Castelli & Plez 1998; spec ERRATA 6.2.5.2), and
  R_peak,E, ENSQ the sensor's static metrics (data providers).
- Streaks: the same star with the sensor turning at a constant rate during
  the integration: the summed energy equals the star's at rest within 0.1 %
  and the streak's length (from the second moment of the profile along it,
  sigma^2 = L^2 / 12 + sigma_rest^2 for a uniform segment) equals rate x
  integration time within 0.05 px.

usage: check_star_field.py   (EOIR_LIBRARY and PYTHONPATH set by ctest)
"""
import json
import math
import os
import sys
import tempfile
import warnings

import erfa
import numpy as np
from astropy.wcs import WCS

import eoir

failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


TIME = "2026-11-23T06:00:00Z"
RA0, DEC0 = 83.0, -5.0        # Orion: boresight of the astrometry field
PIX, FOV = 256, 2.0           # pixels, degrees
BAND = (0.5, 0.9)             # um
F_NUMBER, LAMBDA_DIFF = 4.0, 0.7
# Nyquist: pitch = lambda F# / 2; pitch = 2 f tan(FOV / 2) / N.
FOCAL_CM = (LAMBDA_DIFF * 1e-4 * F_NUMBER / 2) * PIX / (2 * math.tan(math.radians(FOV / 2)))
LEO_A_KM = 6378.137 + 700.0


def unit(ra, dec):
    ra, dec = math.radians(ra), math.radians(dec)
    return np.array([math.cos(dec) * math.cos(ra), math.cos(dec) * math.sin(ra), math.sin(dec)])


def quat_from_axes(x, y, z):
    """Body -> J2000 quaternion (w, x, y, z) of the rotation whose columns are x, y, z."""
    m = np.column_stack([x, y, z])
    w = math.sqrt(max(0.0, 1.0 + m[0, 0] + m[1, 1] + m[2, 2])) / 2
    return [w, (m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w), (m[1, 0] - m[0, 1]) / (4 * w)]


def pointing(ra, dec):
    z = unit(ra, dec)
    north = np.array([0.0, 0.0, 1.0])
    y = north - z * (north @ z)
    y /= np.linalg.norm(y)
    return quat_from_axes(np.cross(y, z), y, z)


def scenario(catalogue, ra, dec, extra_pointing=None, integration_ms=100.0):
    p = {
        "horizontal_pixels": PIX, "vertical_pixels": PIX, "horizontal_fov_deg": FOV, "vertical_fov_deg": FOV,
        "band_low_um": BAND[0], "band_high_um": BAND[1], "spectral_intervals": 20,
        "f_number": F_NUMBER, "focal_length_cm": FOCAL_CM, "diffraction_wavelength_um": LAMBDA_DIFF,
        "image_quality": "diffraction_limited", "jitter_mrad": 0.0, "defocus_mm": 0.0,
        "integration_time_ms": integration_ms,
        "sensitivity_quantity": "irradiance", "sensitivity_pairs": [[100.0, 1e-17]],
        "saturation_quantity": "irradiance", "saturation_pairs": [[100.0, 1e-9]],
        "noise_enabled": False,
    }
    sensor_pointing = {"type": "fixed_inertial", "quaternion": pointing(ra, dec)}
    if extra_pointing:
        sensor_pointing = extra_pointing
    return {
        "format": "eoir-scenario", "version": 1, "name": "star field", "start": TIME, "stop": TIME, "step_s": 60,
        "central_bodies": [],
        "stars": {"properties": {"catalog_file": catalogue, "catalog_epoch_year": 2000.0,
                                 "limiting_magnitude": 9.0}},
        "objects": [{
            "name": "Sat", "kind": "satellite",
            # A circular polar orbit whose velocity is across the line of sight.
            "motion": {"type": "kepler", "central_body": "Earth", "semi_major_axis_km": LEO_A_KM,
                       "eccentricity": 0.0, "inclination_deg": 98.0, "raan_deg": 173.0, "arg_perigee_deg": 0.0,
                       "true_anomaly_deg": 20.0, "epoch": TIME},
            "attitude": {"type": "nadir"}}],
        "sensors": [{"name": "Cam", "parent": "Sat", "pointing": sensor_pointing, "parameters": p}],
    }


def write_catalogue(path, stars):
    with open(path, "w") as f:
        f.write("id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\n")
        for s in stars:
            f.write(",".join(str(x) for x in s) + "\n")


def load(tmp, name, doc):
    path = os.path.join(tmp, name + ".json")
    with open(path, "w") as f:
        json.dump(doc, f)
    sc = eoir.Scenario.load(path)
    sc.set_time(TIME)
    sc.engine.render("Cam")
    return sc


def mean_fits(sc):
    hdu = sc.fits_hdu("Cam", kind="sensor_mean")
    return np.asarray(hdu.data, dtype=float), hdu.header


def apparent_radec(star, sc):
    """ERFA apparent place (GCRS) of a catalogue star for the sensor's
    geocentric position and velocity."""
    st = sc.engine.get_state("Cam")
    pv = np.zeros((), dtype=erfa.dt_pv)  # eraApcs13 takes metres and m/s
    pv["p"] = np.asarray(st["position"])
    pv["v"] = np.asarray(st["velocity"])
    utc = erfa.dtf2d("UTC", 2026, 11, 23, 6, 0, 0.0)
    tt = erfa.taitt(*erfa.utctai(*utc))
    astrom = erfa.apcs13(tt[0], tt[1], pv)  # bpn = identity: GCRS
    _, ra, dec, pmra, pmdec, plx, v, bv = star
    rc, dc = math.radians(ra), math.radians(dec)
    pr = math.radians(pmra / 3.6e6) / math.cos(dc)  # d(RA)/dt [rad/yr] from mu_alpha*
    pd = math.radians(pmdec / 3.6e6)
    ri, di = erfa.atciq(rc, dc, pr, pd, plx / 1000.0, 0.0, astrom)
    # The astrometric place: space motion and parallax only (SOFA eraPmpx).
    p = erfa.pmpx(rc, dc, pr, pd, plx / 1000.0, 0.0, astrom["pmt"], astrom["eb"])
    ra_a, dec_a = erfa.c2s(p)
    return (math.degrees(ri) % 360.0, math.degrees(di)), (math.degrees(ra_a) % 360.0, math.degrees(dec_a))


def axes_wcs(header):
    """The gnomonic projection of the sensor's axes (apparent directions):
    the boresight at the centre, image up toward UP_RA/UP_DEC, the TAN pitch
    2 tan(FOV/2) / N."""
    ra0, dec0 = math.radians(header["BORE_RA"]), math.radians(header["BORE_DEC"])
    east = np.array([-math.sin(ra0), math.cos(ra0), 0.0])
    north = np.array([-math.sin(dec0) * math.cos(ra0), -math.sin(dec0) * math.sin(ra0), math.cos(dec0)])
    up = np.array([math.cos(math.radians(header["UP_DEC"])) * math.cos(math.radians(header["UP_RA"])),
                   math.cos(math.radians(header["UP_DEC"])) * math.sin(math.radians(header["UP_RA"])),
                   math.sin(math.radians(header["UP_DEC"]))])
    pa = math.atan2(up @ east, up @ north)
    step = math.degrees(2 * math.tan(math.radians(FOV / 2)) / PIX)
    w = WCS(naxis=2)
    w.wcs.ctype = ["RA---TAN", "DEC--TAN"]
    w.wcs.crval = [header["BORE_RA"], header["BORE_DEC"]]
    w.wcs.crpix = [(PIX + 1) / 2, (PIX + 1) / 2]
    w.wcs.cd = [[-step * math.cos(pa), step * math.sin(pa)], [step * math.sin(pa), step * math.cos(pa)]]
    return w


def centroid(img, x, y, half):
    xi, yi = int(round(x)), int(round(y))
    win = img[yi - half:yi + half + 1, xi - half:xi + half + 1]
    border = np.concatenate([win[0], win[-1], win[:, 0], win[:, -1]])
    w = win - np.median(border)
    ys, xs = np.mgrid[yi - half:yi + half + 1, xi - half:xi + half + 1]
    return (w * xs).sum() / w.sum(), (w * ys).sum() / w.sum(), w


def planck(l_um, t):
    h, c, k = 6.62607015e-34, 299792458.0, 1.380649e-23
    l = l_um * 1e-6
    return 2 * h * c * c / l ** 5 / math.expm1(h * c / (l * k * t)) * 1e-4 * 1e-6  # W cm^-2 sr^-1 um^-1


def star_band_irradiance(v, bv):
    t = 4600.0 * (1 / (0.92 * bv + 1.7) + 1 / (0.92 * bv + 0.62))  # Ballesteros (2012) eq. 14
    m0 = 3.631e-12 * 10 ** (-0.4 * v) / planck(0.55, t)
    ls = np.linspace(BAND[0], BAND[1], 20001)
    return m0 * np.trapz([planck(l, t) for l in ls], ls)


def astrometry(tmp):
    rng = np.random.default_rng(7)
    stars = []
    # A jittered grid: neighbours at least ~28 px apart, so every star is isolated.
    k = 0
    for i in range(-3, 4):
        for j in range(-3, 4):
            k += 1
            d_ra = (i * 0.27 + rng.uniform(-0.03, 0.03)) / math.cos(math.radians(DEC0))
            d_dec = j * 0.27 + rng.uniform(-0.03, 0.03)
            stars.append(("S%02d" % k, RA0 + d_ra, DEC0 + d_dec, rng.uniform(-2000, 2000), rng.uniform(-2000, 2000),
                          rng.uniform(0, 300), rng.uniform(4.0, 8.5), rng.uniform(-0.2, 1.6)))
    cat = os.path.join(tmp, "field.csv")
    write_catalogue(cat, stars)
    sc = load(tmp, "astrometry", scenario(cat, RA0, DEC0, integration_ms=2000.0))
    img, header = mean_fits(sc)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # wcslib filling in OBSGEO-L/B/H (astropy issue #10365)
        wcs = WCS(header)
    axes = axes_wcs(header)
    truth = {t["object"]: t for t in sc.truth("Cam") if t.get("kind") == "star"}
    check(len(truth) >= 30, f"astrometry: {len(truth)} of {len(stars)} stars imaged")
    errors = {"apparent": [], "astrometric": []}
    worst_truth_mas = 0.0
    for s in stars:
        t = truth.get(s[0])
        if t is None or not (t["snr"] > 50):
            continue
        apparent, astrometric = apparent_radec(s, sc)
        worst_truth_mas = max(worst_truth_mas, 3.6e6 * math.hypot(
            (t["ra_deg"] - astrometric[0]) * math.cos(math.radians(astrometric[1])), t["dec_deg"] - astrometric[1]))
        for kind, w, (ra, dec) in (("apparent", axes, apparent), ("astrometric", wcs, astrometric)):
            x, y = w.all_world2pix([[ra, dec]], 0)[0]  # 0-based FITS pixel = numpy index (row 0 at the bottom)
            if not (15 <= x <= PIX - 16 and 15 <= y <= PIX - 16):
                continue
            cx, cy, _ = centroid(img, x, y, 12)
            errors[kind].append(math.hypot(cx - x, cy - y))
    for kind, how in (("apparent", "the sensor's axes"), ("astrometric", "the FITS WCS")):
        e = errors[kind]
        rms = math.sqrt(np.mean(np.square(e))) if e else float("inf")
        print(f"astrometry: {len(e)} isolated stars with SNR > 50; centroid - ERFA {kind} place through {how}: "
              f"RMS {rms:.4f} px, max {max(e):.4f} px (pixel {FOV * 3600 / PIX:.1f}\")")
        check(len(e) >= 20, f"astrometry ({kind}): {len(e)} stars measured (>= 20)")
        check(rms <= 0.05, f"astrometry ({kind}): RMS {rms:.4f} px <= 0.05 px")
    check(worst_truth_mas < 1.0, f"astrometry: truth RA/Dec = ERFA astrometric places within {worst_truth_mas:.2g} mas")
    sc.close()


def photometry(tmp):
    cases = [("P1", 6.0, -0.1), ("P2", 7.5, 0.65), ("P3", 5.0, 1.5)]
    for sid, v, bv in cases:
        cat = os.path.join(tmp, sid + ".csv")
        write_catalogue(cat, [(sid, RA0, DEC0, 0.0, 0.0, 0.0, v, bv)])
        doc = scenario(cat, RA0, DEC0)
        doc["stars"]["properties"]["background_light"] = False
        sc = load(tmp, "photometry_" + sid, doc)
        # The star where the sensor sees it (aberration moves it off the centre).
        t = [x for x in sc.truth("Cam") if x.get("kind") == "star"]
        img, _ = mean_fits(sc)
        r_e = sc.engine.provider("EOIR Radiometric Performance", "Peak Irradiance Responsivity", "Cam")
        ensq = sc.engine.provider("EOIR Sensor Optics", "Ensquared Energy", "Cam")
        e = star_band_irradiance(v, bv)
        predicted = r_e * e / ensq
        ratio = img.sum() / predicted
        print(f"photometry {sid} V={v} B-V={bv}: E = {e:.4e} W/cm^2, sum {img.sum():.5e} e-, "
              f"R_E E / ENSQ {predicted:.5e} e-: ratio {ratio:.5f}")
        check(len(t) == 1, f"photometry {sid}: the star is in the truth")
        check(abs(ratio - 1) <= 0.01, f"photometry {sid}: within 1 % ({ratio:.5f})")
        sc.close()


def streaks(tmp):
    cat = os.path.join(tmp, "streak.csv")
    write_catalogue(cat, [("Q1", RA0, DEC0, 0.0, 0.0, 0.0, 6.0, 0.5)])
    rest_doc = scenario(cat, RA0, DEC0, integration_ms=200.0)
    rest_doc["stars"]["properties"]["background_light"] = False
    rest = load(tmp, "rest", rest_doc)
    rest_img, _ = mean_fits(rest)
    rest_sum = rest_img.sum()
    rest.close()
    # The sensor turns about its y axis (image up) at a constant rate: the
    # star moves along the image rows.
    pixel_rad = 2 * math.tan(math.radians(FOV / 2)) / PIX  # at the centre
    for length_px in (3.0, 12.0):
        rate_rad_s = length_px * pixel_rad / 0.2
        doc = scenario(cat, RA0, DEC0, integration_ms=200.0,
                       extra_pointing={"type": "spinning_inertial", "quaternion": pointing(RA0, DEC0),
                                       "axis_body": [0.0, 1.0, 0.0], "rate_deg_s": math.degrees(rate_rad_s)})
        doc["stars"]["properties"]["background_light"] = False
        sc = load(tmp, "streak_%g" % length_px, doc)
        img, _ = mean_fits(sc)
        t = [x for x in sc.truth("Cam") if x.get("kind") == "star"][0]
        # Profile along the rows (summed over the columns about the star).
        rows = img.sum(axis=0)
        xs = np.arange(PIX)
        c = (rows * xs).sum() / rows.sum()
        var = (rows * (xs - c) ** 2).sum() / rows.sum()
        rest_rows = rest_img.sum(axis=0)
        rc = (rest_rows * xs).sum() / rest_rows.sum()
        rest_var = (rest_rows * (xs - rc) ** 2).sum() / rest_rows.sum()
        measured = math.sqrt(max(0.0, 12 * (var - rest_var)))
        truth_len = math.hypot(t["end_fits"][0] - t["start_fits"][0], t["end_fits"][1] - t["start_fits"][1])
        print(f"streak {length_px} px: energy ratio {img.sum() / rest_sum:.6f}, length from the profile "
              f"{measured:.4f} px, truth start-end {truth_len:.4f} px")
        check(abs(img.sum() / rest_sum - 1) <= 1e-3, f"streak {length_px} px: energy within 0.1 %")
        check(abs(measured - length_px) <= 0.05, f"streak {length_px} px: length within 0.05 px ({measured:.4f})")
        check(abs(truth_len - length_px) <= 0.05, f"streak {length_px} px: truth start-end ({truth_len:.4f})")
        sc.close()


def main():
    warnings.simplefilter("ignore", erfa.ErfaWarning)  # "dubious year": leap seconds after the table's end
    with tempfile.TemporaryDirectory() as tmp:
        astrometry(tmp)
        photometry(tmp)
        streaks(tmp)
    if failures:
        print(f"{len(failures)} failure(s)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
