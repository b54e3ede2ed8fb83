#!/usr/bin/env python3
"""Parse KStars' text star catalogue (Debian kstars-data, stars.dat) for
build_catalogue.py, which writes the engine's binary star catalogue (format
described in data/stars/README.md).

stars.dat is fixed-column text, one star per line, sorted by V; its columns
(KStars data/tools/hipdatatomysql.pl, kstars_unpack) are

  0-8   RA  HHMMSS.SS               (ICRS, epoch J2000.0)
  10-18 Dec +DDMMSS.S
  20-28 pmRA  +NNNNNN.N  mas/yr     mu_alpha* = mu_alpha cos(delta) (Hipparcos pmRA)
  29-37 pmDec +NNNNNN.N  mas/yr
  38-44 parallax NNNNN.N mas
  46-50 V magnitude (Johnson V of Hipparcos/Tycho)
  51-55 B-V
  56-57 spectral type (2 characters, '?' when unknown)
  59    multiplicity flag (0/1)
  60-71 optional variability range and period
  72-   optional ", genitive name, common name"

Only the Python standard library is used (parse() below).
"""
import math
import re
import sys

LINE = re.compile(r"^(\d{6}\.\d\d) ([+-]\d{6}\.\d) ([+-]\d{6}\.\d)([+-]\d{6}\.\d)(\d{5}\.\d) "
                  r"([\d -]\d\.\d\d)([\d -]\d\.\d\d)(..) (\d)")


def sexagesimal(text):
    sign = -1.0 if text.startswith("-") else 1.0
    digits = text.lstrip("+-")
    return sign * (int(digits[0:2]) + int(digits[2:4]) / 60.0 + float(digits[4:]) / 3600.0)


def parse(path):
    stars = []
    with open(path, encoding="latin-1") as f:
        for line_number, line in enumerate(f, start=1):
            if line.startswith("#") or not line.strip():
                continue
            m = LINE.match(line)
            if not m:
                sys.exit(f"{path}:{line_number}: not a KStars stars.dat data line")
            ra_rad = math.radians(15.0 * sexagesimal(m.group(1)))
            dec_rad = math.radians(sexagesimal(m.group(2)))
            rest = line[60:].rstrip("\r\n")
            variable = bool(rest[:12].strip())
            names = ""
            if "," in rest:
                parts = [p.strip() for p in rest[12:].split(",")[1:]]
                names = "|".join(parts[:2]) if len(parts) > 1 else parts[0]
            stars.append(dict(number=len(stars) + 1, ra=ra_rad, dec=dec_rad,
                              pm_ra=float(m.group(3)), pm_dec=float(m.group(4)),
                              plx=float(m.group(5)), v=float(m.group(6)), bv=float(m.group(7)),
                              sp=m.group(8).encode("ascii", "replace"), mult=m.group(9) == "1",
                              var=variable, names=names))
    return stars
