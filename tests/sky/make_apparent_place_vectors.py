#!/usr/bin/python3
"""Independent oracle for the apparent places of stars (tests/sky).

Computes GCRS apparent right ascension and declination with astropy (Debian
python3-astropy; its ICRS -> GCRS transformation applies parallax, light
deflection by the Sun and aberration with the observer's geocentric position
and velocity, and SkyCoord.apply_space_motion propagates proper motion with
erfa.pmsafe) and writes them as CSV to stdout. Regenerate with

    /usr/bin/python3 tests/sky/make_apparent_place_vectors.py > tests/sky/apparent_place_vectors.csv

Star data (ICRS, epoch J2000.0, mu_alpha* = mu_alpha cos delta) are test
inputs, close to the Hipparcos (van Leeuwen 2007) values of the named stars.
"""
import sys
import warnings

import astropy
import astropy.units as u
from astropy.coordinates import GCRS, ICRS, CartesianRepresentation, Distance, SkyCoord
from astropy.time import Time

warnings.simplefilter("ignore")

# id, ra_deg, dec_deg, pm_ra_cosdec_mas_yr, pm_dec_mas_yr, parallax_mas
STARS = [
    ("pollux", 116.328958, 28.026183, -626.55, -45.80, 96.54),
    ("sirius", 101.287155, -16.716116, -546.01, -1223.07, 379.21),
    ("polaris", 37.954561, 89.264109, 44.48, -11.85, 7.54),
    ("barnard", 269.452076, 4.693364, -798.58, 10328.12, 548.31),
    ("ecliptic_pole", 270.0, 66.560709, 0.0, 0.0, 0.001),
    ("near_sun_2024_03_20", 1.0, 1.0, 0.0, 0.0, 0.001),
]
# observer id, geocentric position [m], velocity [m/s] (GCRS)
OBSERVERS = [
    ("geocentre", (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
    ("leo", (7000e3, 0.0, 0.0), (0.0, 7500.0, 0.0)),
    ("geo", (0.0, -42164e3, 0.0), (3074.7, 0.0, 0.0)),
]
TIMES_TDB = ["2024-03-20T12:00:00", "2010-07-01T00:00:00"]

out = sys.stdout
out.write(f"# astropy {astropy.__version__}; columns: time_tdb_iso, jd1_tdb, jd2_tdb, star, observer, "
          "ra_deg, dec_deg (GCRS apparent place)\n")
out.write("time_tdb,jd1,jd2,star,observer,ra_deg,dec_deg\n")
for iso in TIMES_TDB:
    t = Time(iso, scale="tdb")
    for sid, ra, dec, pmra, pmde, plx in STARS:
        c = SkyCoord(ra=ra * u.deg, dec=dec * u.deg, pm_ra_cosdec=pmra * u.mas / u.yr, pm_dec=pmde * u.mas / u.yr,
                     distance=Distance(parallax=plx * u.mas), radial_velocity=0 * u.km / u.s, frame=ICRS,
                     obstime=Time("J2000", scale="tdb"))
        moved = c.apply_space_motion(new_obstime=t)
        for oid, pos, vel in OBSERVERS:
            frame = GCRS(obstime=t, obsgeoloc=CartesianRepresentation(*pos, unit=u.m),
                         obsgeovel=CartesianRepresentation(*vel, unit=u.m / u.s))
            g = moved.transform_to(frame)
            out.write(f"{iso},{t.jd1:.1f},{t.jd2:.17g},{sid},{oid},{g.ra.deg:.12f},{g.dec.deg:.12f}\n")
