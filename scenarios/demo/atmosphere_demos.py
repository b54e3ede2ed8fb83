#!/usr/bin/env python3
"""Pictures of the Earth's atmosphere (issue 20 item 10), made with the eoir
Python package (the library in build/lib, or EOIR_LIBRARY):

1. geo_disc_atmosphere.png: scenarios/demo/default.json's Sensor1 (GEO, 25 deg
   W, visible 0.45-0.75 um, bitmap mode) with the Earth's atmosphere off and
   on, the same asinh stretch, and the radiance along the row through the
   disc's centre (geo_disc_profile.csv); the mean radiance ratio is printed.
2. geo_belt_night.png: a ground telescope at Kitt Peak at local midnight near
   new moon stares at the GEO belt due south (3 deg field, 10 s exposure)
   among the catalogue stars of the star-field demo (Hipparcos/Tycho to
   V = 9); five GEO satellites fixed in the Earth-fixed frame over nearby
   longitudes stay put while the stars trail (geo_belt_night.csv: their
   truth).
3. iss_twilight_snr.png: an ISS pass (the README's TLE) over Kitt Peak in
   evening twilight, found by searching with python3-sgp4 and astropy (the
   Sun 4-12 deg below the horizon, the ISS sunlit and above 10 deg), tracked
   by a small camera; SNR against elevation with the atmosphere on and off,
   the sky's radiance beside the ISS and the air mass
   (iss_twilight_snr.csv).

Each scenario the engine ran is written beside its picture (JSON; `eoir run`
takes it). Run with Debian's python3 (numpy, matplotlib, PIL, astropy,
python3-sgp4):

    /usr/bin/python3 scenarios/demo/atmosphere_demos.py            # scenarios/demo/results
    /usr/bin/python3 scenarios/demo/atmosphere_demos.py --quick --out /tmp/demos   # tiny frames, 3 steps

What is modelled: single scattering of sunlight and moonlight (Rayleigh and
aerosol), the atmosphere's transmission and thermal emission, refraction of
stars and objects, and as the night sky the airglow's layer (lines, bands
and continuum to 0.92 um) and the background light of spec 4.1.4
(integrated starlight, zodiacal light) seen through the air. Not modelled
(yet): multiple scattering (the twilight sky away from the Sun is far too
dark in single scatter), light pollution and seeing; clouds are off in
these scenes.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from demo_support import ecef, enu_axes, import_eoir, write_json  # noqa: E402

eoir = import_eoir()

# ---------------------------------------------------------------- geometry
GEO_RADIUS_M = 42164.17e3

KITT_PEAK = {"name": "KittPeak", "lat_deg": 31.958, "lon_deg": -111.600, "alt_m": 2096.0}
ISS_TLE = ("1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927",
           "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537")


def azel_of(site, p_ecef):
    """Geometric azimuth (from north through east) and elevation above the
    geodetic horizon of an Earth-fixed point seen from a site (deg)."""
    d = p_ecef - ecef(site["lat_deg"], site["lon_deg"], site["alt_m"])
    e, n, u = enu_axes(site["lat_deg"], site["lon_deg"])
    return (math.degrees(math.atan2(d @ e, d @ n)) % 360.0,
            math.degrees(math.asin(d @ u / np.linalg.norm(d))))


def geo_ecef(lon_deg):
    lon = math.radians(lon_deg)
    return np.array([GEO_RADIUS_M * math.cos(lon), GEO_RADIUS_M * math.sin(lon), 0.0])


# ----------------------------------------------------------------- helpers
def write_csv(path, header, rows, comments=()):
    with open(path, "w", newline="", encoding="utf-8") as f:
        for c in comments:
            f.write(f"# {c}\n")
        w = csv.writer(f)
        w.writerow(header)
        for r in rows:
            w.writerow([f"{v:.6g}" if isinstance(v, float) else v for v in r])


def site_object(site):
    return {"name": site["name"], "kind": "site",
            "motion": {"type": "fixed_geodetic", "lat_deg": site["lat_deg"], "lon_deg": site["lon_deg"],
                       "alt_m": site["alt_m"]}}


def earth(atmosphere="simple"):
    return {"name": "Earth", "properties": {"atmosphere": atmosphere}}


def responsivities(params):
    """The peak irradiance and radiance responsivities (e- per W/cm^2 and per
    W/(cm^2 sr)) of a sensor's parameters, from a throwaway engine."""
    with eoir.Engine(threads=1) as e:
        e.add_object("satellite", "Host")
        e.add_sensor("S", "Host")
        for k, v in params.items():
            if not k.startswith(("sensitivity", "saturation")):
                e.set("S", k, v)
        g = "EOIR Radiometric Performance"
        return (e.provider(g, "Peak Irradiance Responsivity", "S"),
                e.provider(g, "Peak Radiance Responsivity", "S"))


def asinh_stretch(x, soft, top):
    """asinh(x / soft) scaled so that top maps to 1 (0 stays 0), clipped."""
    return np.clip(np.arcsinh(np.maximum(x, 0.0) / soft) / np.arcsinh(top / soft), 0.0, 1.0)


def bin2(a, n):
    h, w = a.shape
    return a[: h // n * n, : w // n * n].reshape(h // n, n, w // n, n).mean(axis=(1, 3))


# ============================================================ 1. GEO disc
def demo_geo_disc(out: Path, quick: bool, threads: int):
    scenario = REPO / "scenarios" / "demo" / "default.json"
    images = {}
    with eoir.Scenario.load(scenario, threads=threads) as sc:
        e = sc.engine
        if quick:
            e.set("Sensor1", "horizontal_pixels", 48)
            e.set("Sensor1", "vertical_pixels", 48)
        sc.set_time(sc.start)
        for atm in ("none", "simple"):
            e.set("Earth", "atmosphere", atm)
            t0 = time.time()
            e.render("Sensor1")
            images[atm] = e.image("Sensor1", "scene_radiance")
            print(f"  Sensor1, atmosphere {atm}: {images[atm].shape[1]}x{images[atm].shape[0]} samples "
                  f"in {time.time() - t0:.1f} s", flush=True)
        # What a pixel of open space, the disc's centre and the limb hold, term by term.
        h, w = images["none"].shape
        terms = e.pick_terms("Sensor1", w // 2, h // 2)
    off, on = images["none"], images["simple"]
    disc = off > 0  # the hard Earth (vacuum: nothing else in the field but black space)
    ratio_all = on.mean() / off.mean()
    ratio_disc = on[disc].mean() / off[disc].mean()
    haze = on[~disc]
    print(f"  mean radiance, atmosphere on / off: {ratio_all:.3f} over the frame, {ratio_disc:.3f} over the disc; "
          f"mean {off.mean():.4g} -> {on.mean():.4g} W/(cm^2 sr); off-disc (limb haze) samples lit: "
          f"{np.count_nonzero(haze > 0)} of {haze.size}, brightest {haze.max():.3g} W/(cm^2 sr)")
    scatter_share = float(np.sum(terms["path_scatter"]) / max(np.sum(terms["at_sensor"]), 1e-300))
    print(f"  nadir sample: T_out {terms['transmittance'].min():.3f}-{terms['transmittance'].max():.3f}, "
          f"L_scatter {100 * scatter_share:.0f} % of the at-sensor radiance")

    # Same display scaling: asinh with a soft knee at a few % of the frame's top.
    top = np.percentile(np.concatenate([off[disc], on[disc]]), 99.5)
    soft = 0.03 * top
    n = 2 if off.shape[0] >= 512 else 1
    panels = [asinh_stretch(bin2(a, n), soft, top) for a in (off, on)]
    row = off.shape[0] // 2
    x = np.arange(off.shape[1])
    deg = (x - (off.shape[1] - 1) / 2) * 20.0 / off.shape[1]  # Sensor1's 20 deg field
    write_csv(out / "geo_disc_profile.csv", ["sample", "angle_deg", "radiance_off_W_cm2_sr", "radiance_on_W_cm2_sr"],
              [(int(i), float(deg[i]), float(off[row, i]), float(on[row, i])) for i in x],
              comments=[f"scenarios/demo/default.json Sensor1 at {sc_start_of(scenario)}, scene radiance "
                        f"(0.45-0.75 um) along row {row} (through the disc's centre; rows from the top, south up)",
                        f"mean ratio on/off: frame {ratio_all:.4f}, disc {ratio_disc:.4f}"])

    fig = plt.figure(figsize=(15, 5.6), dpi=110)
    gs = fig.add_gridspec(1, 3, width_ratios=[1, 1, 1.15], wspace=0.08)
    # A zoom on the sunlit limb where the orange row leaves the disc (full resolution).
    limb = int(np.flatnonzero(off[row] > 0).max())
    half = max(8, off.shape[1] // 24)
    box = (max(limb - half, 0), max(row - half, 0))
    for k, (img, full, title) in enumerate(zip(panels, (off, on), ("atmosphere none (vacuum)",
                                                                    "atmosphere simple (US76, rural 23 km)"))):
        ax = fig.add_subplot(gs[0, k])
        ax.imshow(img, cmap="gray", vmin=0, vmax=1, interpolation="nearest")
        ax.set_title(title, fontsize=11)
        ax.axhline(row / n, color="tab:orange", lw=0.6, alpha=0.6)
        ax.add_patch(plt.Rectangle((box[0] / n, box[1] / n), 2 * half / n, 2 * half / n, fill=False,
                                   color="tab:cyan", lw=0.8))
        ax.set_xticks([])
        ax.set_yticks([])
        inset = ax.inset_axes([0.0, 0.66, 0.34, 0.34])  # over the night side
        zoom = full[box[1]:box[1] + 2 * half, box[0]:box[0] + 2 * half]
        inset.imshow(asinh_stretch(zoom, soft, top), cmap="gray", vmin=0, vmax=1, interpolation="nearest")
        inset.set_xticks([])
        inset.set_yticks([])
        for spine in inset.spines.values():
            spine.set_color("tab:cyan")
    ax = fig.add_subplot(gs[0, 2])
    ax.semilogy(deg, np.maximum(off[row], 1e-9), color="k", lw=1, label="none")
    ax.semilogy(deg, np.maximum(on[row], 1e-9), color="tab:blue", lw=1, label="simple")
    ax.set_ylim(1e-6, 3 * max(off[row].max(), on[row].max()))
    ax.set_xlabel("angle from nadir along the orange row (deg)")
    ax.set_ylabel("scene radiance 0.45-0.75 um (W cm$^{-2}$ sr$^{-1}$)")
    ax.yaxis.set_label_position("right")
    ax.yaxis.tick_right()
    ax.legend(loc="lower center", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    fig.suptitle(f"GEO full disc, 0.45-0.75 um (default.json Sensor1, 2010-08-25 18:00 UTC, 25 deg W), same asinh "
                 f"stretch; mean radiance on/off {ratio_all:.2f} (disc {ratio_disc:.2f})", fontsize=11)
    fig.text(0.01, 0.01, "Inset (cyan): the sunlit limb at full resolution. Eq. 9: surface x T_out + L_scatter (single "
             "scattering of sunlight, Rayleigh + rural aerosol) with DownWelling; no clouds, no multiple "
             "scattering.", fontsize=8)
    fig.savefig(out / "geo_disc_atmosphere.png", bbox_inches="tight")
    plt.close(fig)
    return {"ratio_frame": ratio_all, "ratio_disc": ratio_disc}


def sc_start_of(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)["start"]


# ======================================================= 2. GEO belt, night
GEO_BELT_TIME = "2010-06-12T07:26:00Z"  # local solar midnight at Kitt Peak; new moon 2010-06-12 11:15 UTC
GEO_BELT_SATS = [  # longitude offset from the site's meridian (deg), shape
    (-1.20, "box"), (-0.55, "composite"), (0.0, "box"), (0.35, "composite"), (1.05, "box")]


def geo_belt_scenario(quick: bool):
    site = KITT_PEAK
    az, el = azel_of(site, geo_ecef(site["lon_deg"]))
    pixels = 48 if quick else 320
    t_ms = 10000.0
    params = {"horizontal_pixels": pixels, "vertical_pixels": pixels, "horizontal_fov_deg": 3.0,
              "vertical_fov_deg": 3.0, "band_low_um": 0.45, "band_high_um": 0.9, "spectral_intervals": 9,
              "f_number": 2.0, "focal_length_cm": 30.0, "image_quality": "diffraction_limited",
              "diffraction_wavelength_um": 0.65, "integration_time_ms": t_ms, "jitter_mrad": 0.0}
    r_e, _ = responsivities(params)
    well = 2e5 * (320 / pixels) ** 2  # 200 ke- in the full frame's pixels; as deep per area in the quick one's
    params.update({"sensitivity_quantity": "irradiance", "sensitivity_pairs": [t_ms, 10.0 / r_e],   # 10 e- dark
                   "saturation_quantity": "irradiance", "saturation_pairs": [t_ms, well / r_e]})
    objects = [site_object(site)]
    for i, (dlon, shape) in enumerate(GEO_BELT_SATS):
        p = [float(v) for v in geo_ecef(site["lon_deg"] + dlon)]
        props = ({"shape": "composite", "composite": "geo_communications"} if shape == "composite" else
                 {"shape": "box", "dimensions_m": [2.5, 2.5, 4.0], "reflectance": 0.3})
        objects.append({"name": f"GEO{i + 1}", "kind": "satellite",
                        "motion": {"type": "ephemeris", "frame": "earth_fixed",
                                   "points": [{"time": "2010-06-12T07:00:00Z", "position_m": p},
                                              {"time": "2010-06-12T08:00:00Z", "position_m": p}]},
                        "attitude": {"type": "nadir"}, "properties": props})
    return {
        "format": "eoir-scenario", "version": 1,
        "name": "EOIR demo: the GEO belt from the ground at night",
        "description": (
            "A 15 cm f/2 camera at Kitt Peak (31.958 N, 111.600 W, 2096 m) stares at the GEO belt due south "
            f"(azimuth {az:.2f}, elevation {el:.2f} deg: the point over the site's meridian) at local solar "
            "midnight, 2010-06-12 07:26 UTC (new moon at 11:15 UTC; the Sun 35 deg below the horizon): 3 deg "
            f"field of {pixels} x {pixels} pixels, 0.45-0.90 um, 10 s exposure, 10 e- dark noise, "
            f"{well / 1e3:.0f} ke- full well. Five GEO satellites fixed in the Earth-fixed frame over longitudes "
            "1.2 deg W to 1.05 deg E of the site (three 2.5 x 2.5 x 4 m buses, two predefined GEO communications "
            "satellites with their wings) stay put while the Hipparcos/Tycho stars to V = 9 trail by about "
            f"{150.0 / (3.0 * 3600.0 / pixels):.1f} pixels. The Earth's atmosphere is on (US76, rural 23 km): "
            "the stars and satellites are dimmed by their air mass and raised by refraction, and the sky is the "
            "background light of spec 4.1.4 seen through the air."),
        "start": GEO_BELT_TIME, "stop": GEO_BELT_TIME, "step_s": 60,
        "central_bodies": [earth("simple"), "Moon"],
        "stars": {"properties": {"limiting_magnitude": 9.0}},
        "objects": objects,
        "sensors": [{"name": "Scope", "parent": site["name"],
                     "pointing": {"type": "azel", "azimuth_deg": round(az, 4), "elevation_deg": round(el, 4)},
                     "parameters": params}],
    }


def demo_geo_belt(out: Path, quick: bool, threads: int):
    path = out / "geo_belt_night.json"
    write_json(path, geo_belt_scenario(quick))
    with eoir.Scenario.load(path, threads=threads) as sc:
        e = sc.engine
        sc.set_time(sc.start)
        t0 = time.time()
        e.render("Scope")
        print(f"  Scope: {time.time() - t0:.1f} s", flush=True)
        img = e.image("Scope", "sensor_electrons")
        truth = e.truth("Scope")
        h, w = img.shape
        sky = e.pick("Scope", 2, 2, "pixel")
        terms = e.pick_terms("Scope", 2, 2, "pixel")
    sats = [t for t in truth if t["kind"] == "object"]
    stars = [t for t in truth if t["kind"] == "star"]
    k = int(np.argmin(np.abs(terms["wavelengths_um"] - 0.55)))
    sky_mag = v_mag_arcsec2(float(terms["at_sensor"][k]))
    med = float(np.median(img))
    noise = float(1.4826 * np.median(np.abs(img - med)))
    print(f"  {len(stars)} stars, {len(sats)} satellites in the field; sky {med:.0f} e- per pixel "
          f"(noise {noise:.1f} e-); sky radiance {sky['effective_radiance']:.3g} W/(cm^2 sr) ({sky_mag:.1f} "
          f"mag/arcsec^2 at 0.55 um), T_out {terms['transmittance'].min():.2f}-{terms['transmittance'].max():.2f}")
    for s in sats:
        print(f"    {s['object']}: pixel ({s['pixel_x']:.1f}, {s['pixel_y']:.1f}), az {s['azimuth_deg']:.2f} "
              f"el {s['elevation_deg']:.2f}, air mass {s['air_mass']:.3f}, SNR {s['snr']:.1f}, "
              f"E {s['effective_irradiance']:.3g} W/cm^2")
    write_csv(out / "geo_belt_night.csv",
              ["object", "pixel_x", "pixel_y", "azimuth_deg", "elevation_deg", "air_mass", "range_km",
               "effective_irradiance_W_cm2", "snr"],
              [(s["object"], s["pixel_x"], s["pixel_y"], s["azimuth_deg"], s["elevation_deg"], s["air_mass"],
                s["range_m"] / 1e3, s["effective_irradiance"], s["snr"]) for s in sats],
              comments=["geo_belt_night.json: truth of the satellites (pixels 0-based, rows from the top)",
                        f"sky: {med:.1f} e- per pixel, noise {noise:.2f} e-, radiance "
                        f"{sky['effective_radiance']:.4g} W/(cm^2 sr) ({sky_mag:.2f} mag/arcsec^2 at 0.55 um); "
                        f"{len(stars)} stars in the field"])

    # Sky-subtracted, asinh: the noise near black, the satellites bold, bright stars not burnt out.
    x = (img - med) / max(noise, 1e-9)
    peak = max([x[int(round(s["pixel_y"])), int(round(s["pixel_x"]))] for s in sats if 0 <= round(s["pixel_x"]) < w
                and 0 <= round(s["pixel_y"]) < h] + [30.0])
    disp = asinh_stretch(x, 2.0, 1.5 * peak)
    fig, ax = plt.subplots(figsize=(8.0, 8.4), dpi=120)
    ax.imshow(disp, cmap="gray", vmin=0, vmax=1, interpolation="nearest")
    r = max(3.0, w / 40)
    for i, s in enumerate(sats):
        ax.add_patch(plt.Circle((s["pixel_x"], s["pixel_y"]), r, fill=False, color="tab:orange", lw=1.2))
        above = i % 2 == 0
        ax.annotate(f"{s['object']}\nSNR {s['snr']:.0f}", (s["pixel_x"], s["pixel_y"] + (-1.3 if above else 1.3) * r),
                    color="tab:orange", fontsize=8, ha="center", va="bottom" if above else "top")
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title("GEO belt from Kitt Peak, 2010-06-12 07:26 UTC (local midnight, new moon), atmosphere on\n"
                 f"3 deg field, 10 s; asinh of (electrons - sky) / noise; {len(stars)} stars (V < 9) trail, "
                 "GEO satellites stay put", fontsize=10)
    ax.set_xlabel("Night sky: the airglow's layer and the background light of spec 4.1.4 (starlight, zodiacal "
                  "light) through the air,\nno moonlight or light pollution. Up is the zenith side; east is "
                  "on the left.", fontsize=8)
    fig.savefig(out / "geo_belt_night.png", bbox_inches="tight")
    plt.close(fig)
    return {"stars": len(stars), "satellites": len(sats), "sky_radiance": sky["effective_radiance"],
            "sky_mag_arcsec2": sky_mag}


# =================================================== 3. ISS pass, twilight
def _offline_astropy():
    """No network: the bundled IERS-B tables cover 2008-2010 (UT1 - UTC and
    polar motion); the leap-second table's age is harmless here."""
    import warnings
    from astropy.utils import iers
    iers.conf.auto_download = False
    warnings.filterwarnings("ignore", module="astropy.utils.iers")
    warnings.filterwarnings("ignore", message=".*leap-second.*")


def _sun_itrs_unit(times):
    """The Sun's direction in ITRS at astropy times, from a 10-minute grid."""
    import astropy.units as u
    from astropy.coordinates import ITRS, get_sun
    from astropy.time import Time
    jd = times.jd
    grid = Time(np.arange(jd.min() - 0.01, jd.max() + 0.02, 600.0 / 86400.0), format="jd", scale="utc")
    s = get_sun(grid).transform_to(ITRS(obstime=grid)).cartesian.xyz.to_value(u.m).T
    s /= np.linalg.norm(s, axis=1)[:, None]
    out = np.stack([np.interp(jd, grid.jd, s[:, k]) for k in range(3)], axis=1)
    return out / np.linalg.norm(out, axis=1)[:, None]


def iss_geometry(site, times):
    """The ISS (python3-sgp4, TEME -> ITRS by astropy) from the site: elevation
    (deg), sunlit (cylindrical shadow), the Sun's elevation (deg)."""
    import astropy.units as u
    from astropy.coordinates import ITRS, TEME, CartesianRepresentation
    from sgp4.api import Satrec
    sat = Satrec.twoline2rv(*ISS_TLE)
    err, r, _ = sat.sgp4_array(times.jd1, times.jd2)
    if np.any(err):
        raise RuntimeError("SGP4 failed")
    p = TEME(CartesianRepresentation(r.T * u.km), obstime=times).transform_to(ITRS(obstime=times))
    p = p.cartesian.xyz.to_value(u.m).T
    sun = _sun_itrs_unit(times)
    along = np.sum(p * sun, axis=1)
    sunlit = (along > 0) | (np.linalg.norm(p - along[:, None] * sun, axis=1) > 6371.0e3)
    g = ecef(site["lat_deg"], site["lon_deg"], site["alt_m"])
    _, _, up = enu_axes(site["lat_deg"], site["lon_deg"])
    d = p - g
    el = np.degrees(np.arcsin(d @ up / np.linalg.norm(d, axis=1)))
    sun_el = np.degrees(np.arcsin(sun @ up))
    return el, sunlit, sun_el


def find_twilight_pass(site, start_iso, days, step_s):
    """Passes of the ISS over site within `days` of start where, at once, the
    ISS is above 10 deg and sunlit and the Sun is 4-12 deg below the horizon;
    returns the one that culminates highest as (times, elevation, sun
    elevation) over its span above 5 deg (still sunlit, still twilight)."""
    import astropy.units as u
    from astropy.time import Time
    t = Time(start_iso, scale="utc") + np.arange(0.0, days * 86400.0, step_s) * u.s
    el, sunlit, sun_el = iss_geometry(site, t)
    twilight = (sun_el < -4) & (sun_el > -12)
    ok = (el > 10) & sunlit & twilight
    idx = np.flatnonzero(ok)
    if idx.size == 0:
        raise RuntimeError(f"no twilight pass of the ISS over {site['name']} from {start_iso} in {days} days")
    passes = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
    for p in passes:
        print(f"  candidate: {t[p[0]].isot[:19]}Z, {len(p) * step_s:.0f} s above 10 deg in twilight, "
              f"culminating at {el[p].max():.1f} deg, Sun {sun_el[p].min():.1f} to {sun_el[p].max():.1f} deg")
    best = max(passes, key=lambda p: el[p].max())
    # Widen to the contiguous span above 5 deg, sunlit, in twilight.
    lo, hi = best[0], best[-1]
    wide = (el > 5) & sunlit & twilight
    while lo > 0 and wide[lo - 1]:
        lo -= 1
    while hi + 1 < len(t) and wide[hi + 1]:
        hi += 1
    return t[lo], t[hi]


def iss_scenario(start, stop, params, atmosphere="simple"):
    site = KITT_PEAK
    n = params["horizontal_pixels"]
    return {
        "format": "eoir-scenario", "version": 1,
        "name": "EOIR demo: the ISS over Kitt Peak in twilight",
        "description": (
            "A 5 cm f/5 camera at Kitt Peak (31.958 N, 111.600 W, 2096 m) tracks the ISS (the README's TLE; drawn "
            "as a Lambertian sphere of 25 m radius and reflectance 0.5, so that its brightness follows range and "
            "phase only, not which face of a box the Sun lights) through an evening pass in twilight found by "
            f"scenarios/demo/atmosphere_demos.py: 1 deg field of {n} x {n} pixels, 0.45-0.90 um, 1 ms, 10 e- dark "
            "noise, 2 Me- full well (68 um pixels: the ISS saturates none). The Earth's atmosphere is on (US76, "
            "rural 23 km): the ISS is dimmed by its air mass and the sky beside it is the single-scattered "
            "twilight plus the background light of spec 4.1.4 through the air."),
        "start": start, "stop": stop, "step_s": 20,
        "central_bodies": [earth(atmosphere), "Moon"],
        "stars": {"properties": {"limiting_magnitude": 9.0}},
        "objects": [site_object(site),
                    {"name": "ISS", "kind": "satellite",
                     "motion": {"type": "tle", "line1": ISS_TLE[0], "line2": ISS_TLE[1]},
                     "properties": {"shape": "sphere", "dimensions_m": [25.0], "reflectance": 0.5}}],
        "sensors": [{"name": "Tracker", "parent": site["name"], "pointing": {"type": "target", "target": "ISS"},
                     "parameters": params}],
    }


def sky_terms(e, sensor, pixels):
    """The darkest of a few corner pixels (no star, no ISS): total radiance
    (W/(cm^2 sr)), the share of it that is single scatter, and the spectral
    radiance near 0.55 um (W/(cm^2 sr um))."""
    best = None
    for x, y in pixels:
        p = e.pick(sensor, x, y, "pixel")
        if p["object"] == "" and (best is None or p["effective_radiance"] < best[0]["effective_radiance"]):
            best = (p, (x, y))
    p, (x, y) = best
    terms = e.pick_terms(sensor, x, y, "pixel")
    at = terms["at_sensor"]
    share = float(np.sum(terms["path_scatter"]) / np.sum(at)) if np.sum(at) > 0 else 0.0
    k = int(np.argmin(np.abs(terms["wavelengths_um"] - 0.55)))
    return p["effective_radiance"], share, float(at[k])


def v_mag_arcsec2(l_550):
    """Surface brightness (mag/arcsec^2) of a spectral radiance at 0.55 um
    against the V zero point 3.631e-12 W cm^-2 um^-1 (an approximation of V)."""
    arcsec2_sr = (math.pi / 180 / 3600) ** 2
    return -2.5 * math.log10(l_550 * arcsec2_sr / 3.631e-12) if l_550 > 0 else float("nan")


def demo_iss_pass(out: Path, quick: bool, threads: int):
    _offline_astropy()
    import astropy.units as u
    site = KITT_PEAK
    t0 = time.time()
    # Near the TLE's epoch (2008-09-20), where SGP4 is good.
    start, stop = find_twilight_pass(site, "2008-09-20T12:00:00", 1.5 if quick else 3.0, 20.0 if quick else 10.0)
    start_iso, stop_iso = start.isot[:19] + "Z", stop.isot[:19] + "Z"
    print(f"  pass: {start_iso} .. {stop_iso} (search {time.time() - t0:.1f} s)", flush=True)
    steps = 3 if quick else 25
    params = {"horizontal_pixels": 64, "vertical_pixels": 64, "horizontal_fov_deg": 1.0, "vertical_fov_deg": 1.0,
              "band_low_um": 0.45, "band_high_um": 0.9, "spectral_intervals": 9, "f_number": 5.0,
              "focal_length_cm": 25.0, "image_quality": "diffraction_limited", "diffraction_wavelength_um": 0.65,
              "integration_time_ms": 1.0, "jitter_mrad": 0.0}
    if quick:
        params.update({"horizontal_pixels": 16, "vertical_pixels": 16})
    r_e, r_l = responsivities(params)
    params.update({"sensitivity_quantity": "irradiance", "sensitivity_pairs": [1.0, 10.0 / r_e],   # 10 e- dark
                   "saturation_quantity": "irradiance", "saturation_pairs": [1.0, 2e6 / r_e]})    # 2 Me- well
    scenario = iss_scenario(start_iso, stop_iso, params)
    path = out / "iss_twilight_pass.json"
    write_json(path, scenario)
    n = params["horizontal_pixels"]
    corners = [(1, 1), (n - 2, 1), (1, n - 2), (n - 2, n - 2)]
    sessions = {atm: eoir.Scenario.load(path, threads=threads) for atm in ("simple", "none")}
    rows = []
    try:
        sessions["none"].engine.set("Earth", "atmosphere", "none")
        span = (stop - start).sec
        times = start + np.linspace(0.0, span, steps) * u.s
        _, _, sun_el = iss_geometry(site, times)
        for k, t in enumerate(times):
            iso = t.isot[:23] + "Z"
            row = {"time_utc": iso, "sun_elevation_deg": float(sun_el[k])}
            for atm, sc in sessions.items():
                sc.set_time(iso)
                e = sc.engine
                e.render("Tracker")
                tr = next(x for x in e.truth("Tracker") if x["object"] == "ISS")
                key = "on" if atm == "simple" else "off"
                row[f"snr_{key}"] = e.snr("Tracker", "ISS")
                row[f"irradiance_{key}_W_cm2"] = tr["effective_irradiance"]
                sky, share, l550 = sky_terms(e, "Tracker", corners)
                row[f"sky_{key}_W_cm2_sr"] = sky
                row[f"sky_{key}_electrons"] = sky * r_l
                if atm == "simple":
                    row.update({"azimuth_deg": tr["azimuth_deg"], "elevation_deg": tr["elevation_deg"],
                                "air_mass": tr["air_mass"], "range_km": tr["range_m"] / 1e3,
                                "sky_scatter_share": share, "sky_v_mag_arcsec2": v_mag_arcsec2(l550)})
            rows.append(row)
            print(f"    {iso[11:19]} el {row['elevation_deg']:5.1f} az {row['azimuth_deg']:5.1f} "
                  f"air mass {row['air_mass']:5.2f} Sun {row['sun_elevation_deg']:5.1f}: SNR on {row['snr_on']:8.1f} "
                  f"off {row['snr_off']:8.1f}; sky {row['sky_on_W_cm2_sr']:.3g} W/(cm^2 sr) "
                  f"({row['sky_v_mag_arcsec2']:.1f} mag/arcsec^2, scatter {100 * row['sky_scatter_share']:.0f} %)",
                  flush=True)
    finally:
        for sc in sessions.values():
            sc.close()
    header = ["time_utc", "azimuth_deg", "elevation_deg", "air_mass", "range_km", "sun_elevation_deg", "snr_on",
              "snr_off", "irradiance_on_W_cm2", "irradiance_off_W_cm2", "sky_on_W_cm2_sr", "sky_off_W_cm2_sr",
              "sky_on_electrons", "sky_off_electrons", "sky_scatter_share", "sky_v_mag_arcsec2"]
    write_csv(out / "iss_twilight_snr.csv", header, [[r[h] for h in header] for r in rows],
              comments=["iss_twilight_pass.json (atmosphere on) and the same with the Earth's atmosphere none; "
                        "SNR: Engine.snr (spec eq. 65); elevation, azimuth (geometric) and air mass: truth",
                        "sky: the darkest corner pixel's radiance (pick), its single-scatter share (pick_terms) "
                        "and V-like surface brightness from its 0.55 um interval"])

    well = 2e6
    brightest = max(max(r["irradiance_on_W_cm2"], r["irradiance_off_W_cm2"]) for r in rows) * r_e
    if brightest > well:
        print(f"  warning: the ISS's peak pixel reaches {brightest:.3g} e-, above the {well:.3g} e- well: "
              "SNR clipped by saturation")

    el = np.array([r["elevation_deg"] for r in rows])
    peak = int(np.argmax(el))
    rising = np.arange(len(rows)) <= peak
    marks = {True: dict(marker="o", ls="-", ms=4), False: dict(marker="s", ls="--", ms=4, mfc="none")}

    def branches(ax, y, color, label):
        for up in (True, False):
            sel = rising if up else ~rising
            if np.any(sel):
                ax.plot(el[sel], y[sel], color=color, label=f"{label}, {'rising (Sun side)' if up else 'setting'}",
                        **marks[up])

    fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(18, 5.4), dpi=90)
    for key, color, label in (("on", "tab:blue", "atmosphere on"), ("off", "k", "atmosphere none")):
        branches(a1, np.array([r[f"snr_{key}"] for r in rows]), color, label)
    a1.set_yscale("log")
    a1.set_xlabel("ISS elevation (deg, geometric)")
    a1.set_ylabel("SNR (Engine.snr: spec eq. 65)")
    a1.grid(alpha=0.3, which="both")
    a1.legend(fontsize=8)
    a1.set_title(f"ISS over Kitt Peak, {rows[0]['time_utc'][:10]} {rows[0]['time_utc'][11:16]}-"
                 f"{rows[-1]['time_utc'][11:16]} UTC; Sun {max(r['sun_elevation_deg'] for r in rows):.1f} to "
                 f"{min(r['sun_elevation_deg'] for r in rows):.1f} deg", fontsize=10)

    t_path = np.array([r["irradiance_on_W_cm2"] / r["irradiance_off_W_cm2"] if r["irradiance_off_W_cm2"] > 0
                       else np.nan for r in rows])
    snr_ratio = np.array([r["snr_on"] / r["snr_off"] if r["snr_off"] > 0 else np.nan for r in rows])
    branches(a2, t_path, "tab:green", "ISS irradiance on/off (band transmittance)")
    branches(a2, snr_ratio, "tab:blue", "SNR on/off")
    a2.set_yscale("log")
    a2.set_xlabel("ISS elevation (deg, geometric)")
    a2.set_ylabel("atmosphere on / none")
    a2.grid(alpha=0.3, which="both")
    a2.legend(fontsize=8)
    a2.set_title("what the air takes: extinction, and the sky's photon noise", fontsize=10)

    branches(a3, np.array([r["sky_on_W_cm2_sr"] for r in rows]), "tab:purple", "sky beside the ISS")
    a3.axhline(rows[0]["sky_off_W_cm2_sr"], color="k", lw=0.8, ls=":", label="sky, atmosphere none")
    a3.set_yscale("log")
    a3.set_xlabel("ISS elevation (deg, geometric)")
    a3.set_ylabel("sky radiance 0.45-0.90 um (W cm$^{-2}$ sr$^{-1}$)")
    a3.grid(alpha=0.3, which="both")
    a4 = a3.twinx()
    a4.plot(el, [r["air_mass"] for r in rows], "^", color="tab:green", ms=4, label="air mass (truth)")
    a4.set_ylabel("air mass (sea-level vertical columns)", color="tab:green")
    h1, l1 = a3.get_legend_handles_labels()
    h4, l4 = a4.get_legend_handles_labels()
    a3.legend(h1 + h4, l1 + l4, fontsize=8, loc="upper right")
    a3.set_title("sky beside the ISS (darkest corner pixel) and air mass", fontsize=10)
    fig.text(0.01, 0.005, "ISS: the README's TLE, a Lambertian sphere of 25 m radius (reflectance 0.5). Camera: 5 cm "
             "f/5, 1 deg field, 64 x 64 pixels, 0.45-0.90 um, 1 ms, 10 e- dark noise; SNR of spec eq. 65 (dark and sky "
             "photon noise).\nSky: single scatter of sunlight (Rayleigh + rural aerosol), the airglow and the spec 4.1.4 "
             "background light through the air; no multiple scattering (away from the Sun the twilight sky falls to "
             "the night sky, darker than a real one).\nWith the atmosphere none the sky is the background light "
             "alone and the ISS is seen without extinction.", fontsize=8)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    fig.savefig(out / "iss_twilight_snr.png")
    plt.close(fig)
    return {"rows": rows}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", type=Path, default=HERE / "results", help="folder of the pictures (default: %(default)s)")
    ap.add_argument("--quick", action="store_true", help="tiny frames and 3 steps (a test)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", choices=("geo_disc", "geo_belt", "iss_pass"), action="append",
                    help="make only this demo (repeatable)")
    args = ap.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    demos = {"geo_disc": demo_geo_disc, "geo_belt": demo_geo_belt, "iss_pass": demo_iss_pass}
    t_all = time.time()
    for name, fn in demos.items():
        if args.only and name not in args.only:
            continue
        t0 = time.time()
        print(f"{name}:", flush=True)
        fn(args.out, args.quick, args.threads)
        print(f"  {name} done in {time.time() - t0:.1f} s", flush=True)
    print(f"all done in {time.time() - t_all:.1f} s; pictures in {args.out}")


if __name__ == "__main__":
    main()
