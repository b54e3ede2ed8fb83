#!/usr/bin/env python3
"""Convert KStars' text star catalogue (Debian kstars-data, stars.dat) into the
engine's binary star catalogue (format described in data/stars/README.md).

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

Usage: convert_kstars.py INPUT OUTPUT [--package-version V]
Only the Python standard library is used.
"""
import argparse
import hashlib
import math
import re
import struct
import subprocess
import sys

MAGIC = b"EOIRSTAR"
FORMAT_VERSION = 1
RECORD = struct.Struct("<ddfffff2sBBII")  # 48 bytes, see README.md
FIXED_HEADER = struct.Struct("<8sIIIIdddII")  # 60 bytes
NO_NAME = 0xFFFFFFFF
EPOCH_JULIAN_YEAR = 2000.0

LINE = re.compile(r"^(\d{6}\.\d\d) ([+-]\d{6}\.\d) ([+-]\d{6}\.\d)([+-]\d{6}\.\d)(\d{5}\.\d) "
                  r"([\d -]\d\.\d\d)([\d -]\d\.\d\d)(..) (\d)")


def sexagesimal(text):
    sign = -1.0 if text.startswith("-") else 1.0
    digits = text.lstrip("+-")
    return sign * (int(digits[0:2]) + int(digits[2:4]) / 60.0 + float(digits[4:]) / 3600.0)


def package_version(package):
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package], check=True,
                             capture_output=True, text=True)
        return out.stdout.strip() or "unknown"
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


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


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--package", default="kstars-data")
    ap.add_argument("--package-version", default=None)
    args = ap.parse_args()

    stars = parse(args.input)
    if not stars:
        sys.exit(f"{args.input}: no stars")
    with open(args.input, "rb") as f:
        digest = hashlib.sha256(f.read()).hexdigest()
    version = args.package_version or package_version(args.package)
    source = (f"Debian package {args.package} {version}, file {args.input} (sha256 {digest}). "
              "KStars star catalogue derived from the Hipparcos and Tycho catalogues (ESA 1997, CDS I/239); "
              "the modified catalogue is (C) Jason Harris 2003, GPL. Converted by data/stars/convert_kstars.py. "
              "Positions ICRS at epoch J2000.0; proper motion mu_alpha* = mu_alpha cos(delta) and mu_delta "
              "in mas/yr; parallax in mas; Johnson V and B-V in mag.").encode("utf-8")

    names_blob = bytearray()
    records = bytearray()
    for s in stars:
        offset = NO_NAME
        if s["names"]:
            offset = len(names_blob)
            names_blob += s["names"].encode("utf-8") + b"\0"
        flags = (1 if s["mult"] else 0) | (2 if s["var"] else 0)
        records += RECORD.pack(s["ra"], s["dec"], s["pm_ra"], s["pm_dec"], s["plx"], s["v"], s["bv"],
                               s["sp"], flags, 0, s["number"], offset)

    header_bytes = FIXED_HEADER.size + len(source)
    header_bytes = (header_bytes + 7) // 8 * 8
    header = FIXED_HEADER.pack(MAGIC, FORMAT_VERSION, header_bytes, len(stars), RECORD.size, EPOCH_JULIAN_YEAR,
                               min(s["v"] for s in stars), max(s["v"] for s in stars), len(source),
                               len(names_blob))
    header += source
    header += b"\0" * (header_bytes - len(header))
    tmp = args.output + ".tmp"
    with open(tmp, "wb") as f:
        f.write(header)
        f.write(records)
        f.write(names_blob)
    import os
    os.replace(tmp, args.output)
    print(f"{args.output}: {len(stars)} stars, V {min(s['v'] for s in stars):.2f} .. "
          f"{max(s['v'] for s in stars):.2f}")


if __name__ == "__main__":
    main()
