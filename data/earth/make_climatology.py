#!/usr/bin/env python3
"""Writes climatology_land.csv and climatology_water.csv (spec 4.3.1.3).

Run by hand (the CSV files are committed; the build only copies them):
    /usr/bin/python3 data/earth/make_climatology.py data/earth
Needs numpy, python3-netcdf4 and Debian ferret-datasets 7.6.0-5
(/usr/share/ferret-vis/data/coads_climatology.cdf).

No published table of zonal monthly mean daily maximum/minimum SURFACE (skin)
temperature, separately for land and water, could be reached from this
workplace (the data sets behind the spec's tables, and gridded land
climatologies such as CRU CL or MODIS LST, are not in Debian). What is here:

WATER (observations): the monthly mean of the daily mean is the zonal mean sea
surface temperature of the COADS monthly climatology (Comprehensive
Ocean-Atmosphere Data Set, 1946-1989, 2x2 degrees; Woodruff, Slutz, Jenne and
Steurer 1987, Bull. Amer. Meteor. Soc. 68, 1239-1250), file
coads_climatology.cdf of Debian ferret-datasets, over the observed ocean
cells of each 10-degree band (cos-latitude weights). Band-months with fewer
than 10 observed cells (ice-covered seas) and values below freezing get the
freezing point of sea water, 271.35 K: sea ice is not represented. The diurnal
amplitude is MODELLED: periodic solution for a half-space forced by the first
diurnal harmonic F1 of the absorbed solar flux (1 - 0.3) S(t),
    amplitude = F1 / sqrt((lambda + I sqrt(w/2))^2 + (I sqrt(w/2))^2),
w = 7.29e-5 s-1 (e.g. Price 1977, J. Geophys. Res. 82, 2582-2590), with
I = 1.3e5 J m-2 K-1 s-1/2 (sea water with an eddy diffusivity of 1e-3 m2/s)
and lambda = 40 W m-2 K-1; floor 0.1 K. S(t) is the top-of-atmosphere
insolation (S0 = 1361 W m-2, obliquity 23.44 deg, eccentricity 0.0167).
t_min = mean - amplitude, t_max = mean + amplitude.

LAND (station observations of 2 m AIR temperature, used as a proxy for the
surface temperature; flagged): monthly mean daily maximum and minimum air
temperature of the stations in STATIONS below (each with the page it was read
from and the normals period and agency that page names), averaged over the
stations assigned to each band. Bands without a station: 35N, 15N and 5N are
interpolated linearly in latitude between the neighbouring station bands;
15S-55S take the COADS marine AIR temperature zonal mean (same file, variable
AIRT) as the daily mean, with the diurnal range interpolated linearly between
the 5S and 65S station bands; 65S uses McMurdo (coastal Antarctica).
"""
import math
import os
import sys

import numpy as np

COADS = "/usr/share/ferret-vis/data/coads_climatology.cdf"
BANDS = list(range(-85, 90, 10))
MONTH_DAYS = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
S0 = 1361.0
OBLIQ = math.radians(23.44)
ECC = 0.0167
PERIHELION_DAY = 3.0            # day of year (1 January = 1)
EQUINOX_DAY = 80.0              # March equinox, day of year
OMEGA = 2 * math.pi / 86400.0 * 1.0027
T_FREEZE_SEA = 271.35
WATER_INERTIA, WATER_LAMBDA, WATER_ALBEDO = 1.3e5, 40.0, 0.3

# Monthly mean daily maximum (hi) and minimum (lo) air temperature, deg C,
# January..December, as printed on the page named (read through the search
# tool of this project's workplace; the agency and period are the page's own).
STATIONS = {
    "Alert, Nunavut (82.5N)": dict(
        band=85, src="https://www.liquisearch.com/polar_ice_packs/climate (Wikipedia table, Environment Canada normals)",
        hi=[-28.8, -29.8, -28.7, -20.5, -8.7, 1.6, 5.9, 3.3, -6.0, -15.8, -22.8, -26.4],
        lo=[-35.9, -37.0, -36.1, -28.2, -14.9, -3.2, 0.7, -1.8, -12.2, -22.8, -30.0, -33.7]),
    "Mould Bay, Prince Patrick Island (76.2N)": dict(
        band=75, src="https://www.liquisearch.com/prince_patrick_island/climate (Environment Canada 1971-2000)",
        hi=[-29.4, -30.2, -28.3, -19.8, -7.9, 2.5, 6.8, 3.0, -3.9, -14.1, -23.1, -27.3],
        lo=[-36.8, -37.8, -35.5, -27.8, -14.1, -2.1, 1.3, -1.3, -8.8, -21.3, -30.3, -34.4]),
    "Nanisivik Airport, Arctic Bay (73.0N)": dict(
        band=75, src="https://www.liquisearch.com/arctic_bay/climate (Wikipedia table, Environment Canada)",
        hi=[-26.1, -27.5, -24.8, -16.6, -7.8, 1.9, 7.4, 3.7, -3.7, -12.5, -19.9, -23.7],
        lo=[-32.1, -33.1, -30.8, -23.4, -13.5, -2.8, 2.5, -0.8, -7.4, -17.2, -25.4, -29.4]),
    "Coral Harbour Airport (64.2N)": dict(
        band=65, src="https://www.liquisearch.com/coral_harbour/climate (Wikipedia table, Environment Canada)",
        hi=[-25.8, -25.9, -20.8, -11.3, -2.6, 6.3, 13.9, 11.4, 4.1, -3.9, -12.8, -21.6],
        lo=[-34.1, -34.1, -30.5, -22.0, -10.9, -0.8, 4.6, 3.1, -2.0, -10.7, -21.4, -29.9]),
    "Fairbanks, Alaska (64.8N)": dict(
        band=65, src="https://www.climate-zone.com/climate/us/fairbanks (1991-2020 normals)",
        hi=[-17, -11, -4, 8, 17, 22, 23, 19, 13, 1, -11, -15],
        lo=[-27, -24, -20, -6, 4, 10, 12, 9, 2, -8, -20, -25]),
    "Yakutsk (62.0N)": dict(
        band=65, src="http://friedrichmaier.de/?p=28868 (rounded to 1 C)",
        hi=[-36, -30, -14, 1, 13, 22, 25, 22, 12, -4, -25, -35],
        lo=[-45, -42, -30, -14, 0, 8, 12, 9, 0, -13, -34, -43]),
    "Moscow (55.8N)": dict(
        band=55, src="https://whenrome.com/weather/moscow/ (long-run averages, rounded to 1 C)",
        hi=[-5, -2, 3, 11, 18, 22, 24, 23, 16, 9, 1, -2],
        lo=[-9, -8, -5, 1, 8, 12, 15, 14, 9, 3, -3, -6]),
    "Minneapolis (45.0N)": dict(
        band=45, src="https://whenrome.com/weather/minneapolis/ (long-run averages, rounded to 1 C)",
        hi=[-5, -4, 6, 12, 21, 27, 28, 27, 23, 14, 5, -1],
        lo=[-14, -14, -5, 1, 9, 16, 18, 17, 14, 5, -3, -9]),
    "Riyadh (24.7N)": dict(
        band=25, src="https://eymaps.com/en/Climate_of_Saudi_Arabia (1985-2010, Jeddah Regional Climate Centre / PME)",
        hi=[20, 23, 28, 33, 39, 43, 43, 44, 41, 36, 28, 22],
        lo=[9, 11, 15, 21, 26, 28, 29, 29, 26, 21, 16, 11]),
    "Manaus (3.1S)": dict(
        band=-5, src="https://www.whatstheweatherlike.org/brazil/manaus.htm (long-term averages, rounded to 1 C)",
        hi=[31, 31, 31, 31, 31, 31, 32, 33, 33, 33, 32, 32],
        lo=[23, 23, 23, 23, 24, 23, 23, 23, 24, 24, 24, 24]),
    "McMurdo (77.9S)": dict(
        band=-75, src="https://www.coolantarctica.com/Antarctica%20fact%20file/antarctica%20environment/climate_graph/vostok_south_pole_mcmurdo.htm",
        hi=[-0.2, -6.3, -14.0, -17.4, -19.0, -19.1, -21.7, -22.8, -20.8, -15.5, -6.7, -0.8],
        lo=[-5.5, -11.6, -21.1, -24.9, -27.1, -27.3, -30.1, -31.8, -29.4, -23.4, -12.7, -6.0]),
    "Vostok (78.5S, 3488 m)": dict(
        band=-75, src="https://liquisearch.com/vostok_station/climate (1958-2010)",
        hi=[-27.1, -38.6, -52.8, -61.2, -62.0, -60.5, -62.4, -64.0, -61.8, -51.7, -37.3, -27.3],
        lo=[-37.6, -50.0, -61.7, -67.8, -69.1, -68.8, -70.4, -71.6, -70.3, -63.2, -49.9, -38.1]),
    "Amundsen-Scott South Pole (90S, 2835 m)": dict(
        band=-85, src="https://www.coolantarctica.com/Antarctica%20fact%20file/antarctica%20environment/climate_graph/vostok_south_pole_mcmurdo.htm (1957-1988)",
        hi=[-25.9, -38.1, -50.3, -54.2, -53.9, -54.4, -55.9, -55.6, -55.1, -48.4, -36.9, -26.5],
        lo=[-29.4, -42.7, -57.0, -61.2, -61.7, -61.2, -62.8, -62.5, -62.4, -53.8, -40.4, -29.3]),
}
# 65S (coastal Antarctica) uses McMurdo.
EXTRA_BAND_STATIONS = {-65: ["McMurdo (77.9S)"]}
INTERPOLATED = {35: (45, 25)}
# band: (station band to the north, station band to the south) for the diurnal range
MARINE_PROXY = {15: (25, -5), 5: (25, -5), -15: (-5, -65), -25: (-5, -65), -35: (-5, -65),
                -45: (-5, -65), -55: (-5, -65)}


def insolation(lat_deg, day, nsteps=96):
    """TOA insolation over one day (W m-2), nsteps samples from local midnight."""
    lat = math.radians(lat_deg)
    lam = 2 * math.pi * (day - EQUINOX_DAY) / 365.2422
    dec = math.asin(math.sin(OBLIQ) * math.sin(lam))
    rho = 1 - ECC * math.cos(2 * math.pi * (day - PERIHELION_DAY) / 365.2422)
    h = np.linspace(-math.pi, math.pi, nsteps, endpoint=False)
    mu = math.sin(lat) * math.sin(dec) + math.cos(lat) * math.cos(dec) * np.cos(h)
    return S0 / rho**2 * np.clip(mu, 0, None)


def first_harmonic(series):
    c = np.fft.rfft(series)
    return 2 * abs(c[1]) / series.size


def amplitude(f1, inertia, lam):
    x = inertia * math.sqrt(OMEGA / 2)
    return f1 / math.sqrt((lam + x) ** 2 + x ** 2)


def monthly(daily):
    out, d0 = [], 0
    for n in MONTH_DAYS:
        out.append(float(np.mean(daily[d0:d0 + n])))
        d0 += n
    return np.array(out)


def coads_zonal(var):
    import netCDF4
    d = netCDF4.Dataset(COADS)
    y = np.asarray(d["COADSY"][:])
    a = d[var][:]  # (12, 90, 180) masked, deg C
    out = np.full((len(BANDS), 12), np.nan)
    for b, c in enumerate(BANDS):
        sel = (y >= c - 5) & (y < c + 5)
        w = np.cos(np.radians(y[sel]))
        for m in range(12):
            v = a[m][sel, :]
            ok = ~np.ma.getmaskarray(v)
            ww = np.repeat(w[:, None], v.shape[1], axis=1)
            if ok.sum() >= 10:
                out[b, m] = float((np.asarray(v)[ok] * ww[ok]).sum() / ww[ok].sum())
    return out


def land_table():
    """{band: (tmin[12], tmax[12])} in deg C, and {band: description}."""
    per_band, how = {}, {}
    members = {}
    for name, st in STATIONS.items():
        members.setdefault(st["band"], []).append(name)
    for band, names in EXTRA_BAND_STATIONS.items():
        members.setdefault(band, []).extend(names)
    for band, names in members.items():
        lo = np.mean([STATIONS[n]["lo"] for n in names], axis=0)
        hi = np.mean([STATIONS[n]["hi"] for n in names], axis=0)
        per_band[band] = (lo, hi)
        how[band] = "stations: " + "; ".join(names)
    for band, (a, b) in INTERPOLATED.items():
        f = (band - b) / (a - b)
        per_band[band] = tuple(f * np.asarray(per_band[a][k]) + (1 - f) * np.asarray(per_band[b][k]) for k in (0, 1))
        how[band] = f"linear in latitude between the {a} and {b} bands"
    airt = coads_zonal("AIRT")
    for band, (a, b) in MARINE_PROXY.items():
        mean = airt[BANDS.index(band)]
        assert np.isfinite(mean).all(), band
        f = (band - b) / (a - b)
        dtr = f * (per_band[a][1] - per_band[a][0]) + (1 - f) * (per_band[b][1] - per_band[b][0])
        per_band[band] = (mean - dtr / 2, mean + dtr / 2)
        how[band] = (f"COADS marine air temperature (AIRT) zonal mean +- half the diurnal range "
                     f"interpolated between the {a} and {b} bands")
    assert sorted(per_band) == BANDS, sorted(per_band)
    return per_band, how


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    sst = coads_zonal("SST")
    land, how = land_table()
    land_rows, water_rows = [], []
    for b, lat in enumerate(BANDS):
        amp = np.zeros(365)
        for d in range(365):
            s = insolation(float(lat), d + 1.0)
            amp[d] = max(amplitude(first_harmonic((1 - WATER_ALBEDO) * s), WATER_INERTIA, WATER_LAMBDA), 0.1)
        aw = monthly(amp)
        lo, hi = land[lat]
        for m in range(12):
            land_rows.append((lat, m + 1, lo[m] + 273.15, hi[m] + 273.15))
            tw = sst[b, m] + 273.15 if np.isfinite(sst[b, m]) else T_FREEZE_SEA
            tw = max(tw, T_FREEZE_SEA)
            water_rows.append((lat, m + 1, tw - aw[m], tw + aw[m]))

    common = [
        "# columns: lat_center_deg (centre of a 10-degree band), month (1-12),",
        "#   t_min_K, t_max_K = monthly means of the daily minimum and maximum",
        "#   temperature. Interpolate linearly in latitude between band centres",
        "#   (hold the end values beyond +-85) and in time between mid-months.",
        "# generated by data/earth/make_climatology.py (method in its docstring and in",
        "#   data/earth/README.md)",
    ]
    land_hdr = [
        "# EOIR thermal climatology, LAND (spec 4.3.1.3). FLAGGED: NOT a zonal-mean",
        "# surface (skin) temperature table. It is 2 m AIR temperature of a few",
        "# stations per band (mean daily max/min), interpolation, and marine air",
        "# temperature (COADS, Woodruff et al. 1987, Debian ferret-datasets 7.6.0-5)",
        "# for the tropics and southern mid-latitudes. Expect +-5 to 10 K against",
        "# a true zonal land mean (one to three stations per band; e.g. 55N Moscow",
        "# is milder in winter than 45N Minneapolis), and daytime skin temperatures",
        "# of dry land 5-15 K above t_max.",
        "# Band by band:",
    ] + [f"#   {lat:+d}: {how[lat]}" for lat in BANDS] + [
        "# Stations (source page; normals period/agency as given there):",
    ] + [f"#   {n}: {st['src']}" for n, st in STATIONS.items()]
    water_hdr = [
        "# EOIR thermal climatology, WATER (spec 4.3.1.3)",
        "# daily mean = zonal mean SST of the COADS monthly climatology 1946-1989",
        "#   (Woodruff et al. 1987, Bull. Amer. Meteor. Soc. 68, 1239-1250), file",
        "#   coads_climatology.cdf of Debian ferret-datasets 7.6.0-5, observed ocean",
        "#   cells of each band, cos-latitude weights. Band-months with fewer than",
        "#   10 observed 2x2-degree cells (ice-covered seas) and values below it are",
        "#   set to 271.35 K (freezing sea water; sea ice is NOT represented).",
        "# diurnal amplitude: MODELLED (half-space heated by the first diurnal",
        "#   harmonic of absorbed sunlight, thermal inertia 1.3e5 SI, coupling",
        "#   40 W m-2 K-1), 0.1-0.5 K.",
        "# accuracy: within ~1 K of the COADS band means where observed; COADS is a",
        "#   bulk (about 1 m deep), not a skin temperature (skin ~0.1-0.5 K cooler).",
    ]
    for name, hdr, rows in (("climatology_land.csv", land_hdr, land_rows),
                            ("climatology_water.csv", water_hdr, water_rows)):
        with open(os.path.join(outdir, name), "w") as f:
            f.write("\n".join(hdr + common) + "\n")
            f.write("lat_center_deg,month,t_min_K,t_max_K\n")
            for lat, m, lo, hi in rows:
                f.write(f"{lat:d},{m:d},{lo:.2f},{hi:.2f}\n")


if __name__ == "__main__":
    main()
