"""What every Python example shares: where it writes, and two small writers.

An example writes into the folder named by its first argument (created if
missing), else the current folder, and prints each file it makes. PNGs are
written here with zlib alone (8-bit grey), so the examples need nothing but
numpy (and astropy for FITS files).

Run from a source tree after a build, the examples find the eoir package in
bindings/python and the engine in build/lib (else set PYTHONPATH and
EOIR_LIBRARY, as CTest does).
"""

import csv
import struct
import sys
import zlib
from pathlib import Path

_here = Path(__file__).resolve().parent
try:
    import eoir  # noqa: F401
except ModuleNotFoundError as e:
    if e.name != "eoir":
        raise
    sys.path.insert(0, str(_here.parent / "bindings" / "python"))

SOURCE_DIR = _here.parent  # the repository: scenarios/ and data/


def output_dir() -> Path:
    """The folder given on the command line, else the current one."""
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path.cwd()
    out.mkdir(parents=True, exist_ok=True)
    return out


def made(path: Path, what: str) -> None:
    print(f"made {path}: {what}")


def write_png(path: Path, grey) -> None:
    """An 8-bit greyscale PNG of a (rows, columns) uint8 array, row 0 at the top."""
    import numpy as np
    grey = np.ascontiguousarray(grey, dtype=np.uint8)
    rows, cols = grey.shape
    raw = b"".join(b"\x00" + grey[r].tobytes() for r in range(rows))  # filter 0 on each row

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", cols, rows, 8, 0, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    Path(path).write_bytes(png)


def write_csv(path: Path, rows, fields) -> None:
    """rows (dicts) as CSV with the given columns, in that order."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(fields), extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow(row)


def stretch(image, low_percent: float = 1.0, high_percent: float = 99.8, softening: float = 10.0):
    """A float image to uint8 between two percentiles, for PNGs: asinh
    (softening x) / asinh(softening), which lifts faint light; 0: linear."""
    import numpy as np
    lo, hi = np.percentile(image, [low_percent, high_percent])
    x = np.clip((image - lo) / max(hi - lo, 1e-300), 0.0, 1.0)
    y = np.arcsinh(softening * x) / np.arcsinh(softening) if softening > 0 else x
    return (255 * y).astype(np.uint8)


def check(condition: bool, message: str) -> None:
    """What an example asserts about its result (CTest fails on exit 1)."""
    if not condition:
        print(f"{Path(sys.argv[0]).name}: FAILED: {message}", file=sys.stderr)
        sys.exit(1)
