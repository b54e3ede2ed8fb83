#!/usr/bin/env python3
"""Plot the star catalogue's whole-sky counts per magnitude (issue 21 item 7)
against the Tycho-2 + UCAC4 counts of tests/data/tycho2_ucac4_star_counts.csv.

    /usr/bin/python3 tests/sky/plot_star_counts.py build/data/stars/hipparcos_tycho2_v10p5.eoirstars \\
        scenarios/demo/results/star_counts.png
The catalogue file is read as data/stars/README.md describes it (format v2).
"""
import csv
import os
import struct
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HEADER = struct.Struct("<8sIIIIdddIIIIddI")
RECORD = np.dtype([("ra", "<f8"), ("dec", "<f8"), ("pm_ra", "<f4"), ("pm_dec", "<f4"), ("plx", "<f4"), ("v", "<f4"),
                   ("bv", "<f4"), ("sp", "S2"), ("flags", "u1"), ("reserved", "u1"), ("number", "<u4"),
                   ("name", "<u4")])


def main():
    catalogue, out = sys.argv[1], sys.argv[2]
    data = open(catalogue, "rb").read()
    h = HEADER.unpack(data[:HEADER.size])
    if h[0] != b"EOIRSTAR" or h[1] != 2:
        sys.exit(f"{catalogue}: not an EOIRSTAR v2 file")
    header_bytes, count, tables_bytes = h[2], h[3], h[14]
    v = np.frombuffer(data, dtype=RECORD, count=count, offset=header_bytes + tables_bytes)["v"].astype(float)
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "..", "data", "tycho2_ucac4_star_counts.csv")) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))][1:]
    m_ref = np.array([float(r[0]) for r in rows])
    n_ref = np.array([float(r[1]) for r in rows])
    m = np.arange(-1.0, 11.01, 0.1)
    n = np.array([(v <= x + 1e-6).sum() for x in m])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.semilogy(m, np.maximum(n, 0.5), label=f"engine catalogue ({count:,} stars, V <= {v.max():.1f})")
    ax.semilogy(m_ref, n_ref, "o", label="Tycho-2 + UCAC4 counts (HNSKY table)")
    ax.set_xlabel("magnitude m")
    ax.set_ylabel("stars brighter than m (whole sky)")
    ax.set_title("Star counts: Hipparcos/Tycho-2 catalogue (kstars-data + stellarium-data)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"{out}: counts to V = 10: {int(n[np.argmin(abs(m - 10))]):,} (reference 382,925)")


if __name__ == "__main__":
    main()
