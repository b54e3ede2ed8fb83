#!/usr/bin/env python3
"""Convert the ASTM E-490-00a solar spectrum shipped by Debian's
python3-pyspectral (pyspectral/data/e490_00a.dat: wavelength in um,
spectral irradiance at 1 AU in W m^-2 um^-1) into the engine's solar table
(spec 4.1.4, eq. 6): wavelength_um, irradiance_W_cm2_um.

The total (trapezoid) irradiance must be 1366.1 W/m^2 within 0.5 %, else the
script fails. Only the Python standard library is used.
"""
import argparse
import os
import subprocess
import sys

EXPECTED_TOTAL_W_M2 = 1366.1  # ASTM E-490-00a solar constant
TOLERANCE = 0.005


def debian_version(path):
    """Version of the Debian package that owns `path`, or None."""
    try:
        owner = subprocess.run(["dpkg-query", "-S", os.path.realpath(path)],
                               capture_output=True, text=True, check=True).stdout
        package = owner.split(":")[0].strip()
        version = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package],
                                 capture_output=True, text=True, check=True).stdout.strip()
        return package, version
    except (OSError, subprocess.CalledProcessError, IndexError):
        return None


def read_e490(path):
    rows = []
    with open(path, encoding="ascii") as f:
        for number, line in enumerate(f, 1):
            text = line.strip()
            if not text or text.startswith("#"):
                continue
            fields = text.split()
            if len(fields) != 2:
                raise SystemExit(f"{path}:{number}: expected 2 columns, got {len(fields)}")
            rows.append((float(fields[0]), float(fields[1])))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--input", required=True, help="pyspectral/data/e490_00a.dat")
    parser.add_argument("--output", required=True, help="solar/e490.txt to write")
    parser.add_argument("--source-version", default=None,
                        help="Debian package version (default: asked of dpkg-query)")
    args = parser.parse_args()

    rows = read_e490(args.input)
    if len(rows) < 100:
        raise SystemExit(f"{args.input}: only {len(rows)} rows; not the E-490 table?")
    for (w0, _), (w1, _) in zip(rows, rows[1:]):
        if not w1 > w0:
            raise SystemExit(f"{args.input}: wavelengths not strictly increasing at {w0} -> {w1} um")
    if any(e < 0 for _, e in rows):
        raise SystemExit(f"{args.input}: negative irradiance")

    total = sum(0.5 * (e0 + e1) * (w1 - w0) for (w0, e0), (w1, e1) in zip(rows, rows[1:]))
    deviation = total / EXPECTED_TOTAL_W_M2 - 1.0
    print(f"convert_e490: {len(rows)} points, {rows[0][0]}-{rows[-1][0]} um, "
          f"total (trapezoid) {total:.3f} W/m^2 ({deviation * 100:+.3f} % from {EXPECTED_TOTAL_W_M2})")
    if abs(deviation) > TOLERANCE:
        print(f"convert_e490: FAIL: total {total:.3f} W/m^2 is not {EXPECTED_TOTAL_W_M2} W/m^2 within "
              f"{TOLERANCE * 100} %", file=sys.stderr)
        return 1

    if args.source_version:
        package = ("python3-pyspectral", args.source_version)
    else:
        package = debian_version(args.input) or ("python3-pyspectral", "unknown version")

    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    tmp = args.output + ".tmp"
    with open(tmp, "w", encoding="ascii", newline="\n") as f:
        f.write("# Solar spectral irradiance at 1 AU, ASTM E-490-00a (AM0) standard spectrum\n")
        f.write(f"# source: ASTM E-490-00a, file pyspectral/data/e490_00a.dat of Debian package "
                f"{package[0]} {package[1]}\n")
        f.write("# original units: wavelength um, spectral irradiance W m^-2 um^-1 (1 AU)\n")
        f.write("# converted by data/solar/convert_e490.py: irradiance divided by 1e4 (W m^-2 -> W cm^-2)\n")
        f.write(f"# points: {len(rows)}, wavelength {rows[0][0]:g}-{rows[-1][0]:g} um, strictly increasing\n")
        f.write(f"# total (trapezoid over the table): {total:.3f} W m^-2 = {total * 1e-4:.7f} W cm^-2 "
                f"(E-490 solar constant 1366.1 W m^-2)\n")
        f.write("# units: wavelength_um in um; irradiance_W_cm2_um in W cm^-2 um^-1\n")
        f.write("# wavelength_um  irradiance_W_cm2_um\n")
        for w, e in rows:
            f.write(f"{w:.6g} {e * 1e-4:.6g}\n")
    os.replace(tmp, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
