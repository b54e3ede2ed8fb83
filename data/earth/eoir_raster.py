"""Reader and writer of the engine's "eoir-raster" files (format version 1).

A raster is a global (or regional) grid of uint8 values in a plate carree
(equirectangular latitude/longitude) layout, described by a JSON sidecar and
stored in a separate data file. The format is specified in data/earth/README.md;
this module is the reference implementation used by the conversion scripts and
the checks. It needs numpy only.

Registration ("registration": "cell"): cell (row i, column j), i = 0 at the
north edge, covers longitudes [lon_west + j*cell, lon_west + (j+1)*cell] and
latitudes [lat_north - (i+1)*cell, lat_north - i*cell]; its value is the value
at (or representative of) the cell centre. Rows run north to south, columns
west to east. Longitudes are degrees east of Greenwich (planetocentric east for
the Moon and Mars), latitudes geodetic for the Earth (WGS84, as GSHHG).

Encodings:
  "uint8"      width*height bytes, row-major, row 0 = north.
  "uint8-rle"  little-endian: 8-byte magic b"EOIRRLE1", uint32 width,
               uint32 height, then (height+1) uint64 byte offsets from the
               start of the file (row i's runs occupy [off[i], off[i+1])),
               then the runs: 3 bytes each, uint8 value then uint16 count
               (1..65535); the counts of a row add up to width.
"""
import json
import os

import numpy as np

RLE_MAGIC = b"EOIRRLE1"
RUN_DTYPE = np.dtype([("value", "u1"), ("count", "<u2")])


def header(*, source, width, height, lon_west_deg, lat_north_deg, cell_deg,
           encoding, classes, file, **extra):
    h = {
        "format": "eoir-raster",
        "version": 1,
        "source": source,
        "width": int(width),
        "height": int(height),
        "lon_west_deg": float(lon_west_deg),
        "lat_north_deg": float(lat_north_deg),
        "cell_deg": float(cell_deg),
        "registration": "cell",
        "row_order": "north_to_south",
        "encoding": encoding,
        "classes": classes,
        "file": file,
    }
    h.update(extra)
    return h


def write_header(path_json, hdr):
    with open(path_json, "w") as f:
        json.dump(hdr, f, indent=1)
        f.write("\n")


def rle_encode_rows(block):
    """Runs of each row of a 2-D uint8 array: list of RUN_DTYPE arrays."""
    block = np.ascontiguousarray(block, dtype=np.uint8)
    h, w = block.shape
    change = np.empty((h, w), dtype=bool)
    change[:, 0] = True
    np.not_equal(block[:, 1:], block[:, :-1], out=change[:, 1:])
    # Split runs longer than 65535 (only possible for width > 65535).
    if w > 65535:
        change[:, ::65535] = True
    rows, cols = np.nonzero(change)
    starts_per_row = np.bincount(rows, minlength=h)
    ends = np.empty_like(cols)
    ends[:-1] = cols[1:]
    # the last run of each row ends at w
    last = np.cumsum(starts_per_row) - 1
    ends[last] = w
    runs = np.empty(cols.size, dtype=RUN_DTYPE)
    runs["value"] = block[rows, cols]
    runs["count"] = (ends - cols).astype(np.uint16)
    out = []
    pos = 0
    for n in starts_per_row:
        out.append(runs[pos:pos + n])
        pos += n
    return out


class RleWriter:
    """Streams rows (in blocks, north first) into a uint8-rle file."""

    def __init__(self, path, width, height):
        self.path, self.width, self.height = path, width, height
        self.f = open(path, "wb")
        self.f.write(RLE_MAGIC)
        self.f.write(np.array([width, height], dtype="<u4").tobytes())
        self.table_pos = self.f.tell()
        self.offsets = np.zeros(height + 1, dtype="<u8")
        self.f.write(self.offsets.tobytes())  # placeholder
        self.row = 0

    def add_block(self, block):
        assert block.shape[1] == self.width
        for runs in rle_encode_rows(block):
            self.offsets[self.row] = self.f.tell()
            self.f.write(runs.tobytes())
            self.row += 1

    def close(self):
        assert self.row == self.height, (self.row, self.height)
        self.offsets[self.height] = self.f.tell()
        self.f.seek(self.table_pos)
        self.f.write(self.offsets.tobytes())
        self.f.close()


class Raster:
    """Reads an eoir-raster (JSON sidecar path). Rows are decoded lazily."""

    def __init__(self, json_path):
        with open(json_path) as f:
            self.h = json.load(f)
        assert self.h["format"] == "eoir-raster" and self.h["version"] == 1
        self.width, self.height = self.h["width"], self.h["height"]
        self.cell = self.h["cell_deg"]
        self.lon_west, self.lat_north = self.h["lon_west_deg"], self.h["lat_north_deg"]
        self.path = os.path.join(os.path.dirname(json_path), self.h["file"])
        self.enc = self.h["encoding"]
        if self.enc == "uint8":
            self.data = np.memmap(self.path, dtype=np.uint8, mode="r",
                                  shape=(self.height, self.width))
        elif self.enc == "uint8-rle":
            self.buf = np.memmap(self.path, dtype=np.uint8, mode="r")
            assert bytes(self.buf[:8]) == RLE_MAGIC
            w, h = np.frombuffer(bytes(self.buf[8:16]), dtype="<u4")
            assert (w, h) == (self.width, self.height)
            self.offsets = np.frombuffer(bytes(self.buf[16:16 + 8 * (h + 1)]), dtype="<u8")
        else:
            raise ValueError(self.enc)

    def row(self, i):
        if self.enc == "uint8":
            return np.asarray(self.data[i])
        runs = np.frombuffer(bytes(self.buf[self.offsets[i]:self.offsets[i + 1]]), dtype=RUN_DTYPE)
        assert int(runs["count"].astype(np.int64).sum()) == self.width
        return np.repeat(runs["value"], runs["count"].astype(np.int64))

    def rows(self, i0, i1):
        return np.stack([self.row(i) for i in range(i0, i1)])

    def index(self, lat, lon):
        """(row, col) of the cell containing (lat, lon)."""
        i = int(np.floor((self.lat_north - lat) / self.cell))
        j = int(np.floor(((lon - self.lon_west) % 360.0) / self.cell))
        return min(max(i, 0), self.height - 1), min(j, self.width - 1)

    def centre(self, i, j):
        return (self.lat_north - (i + 0.5) * self.cell,
                self.lon_west + (j + 0.5) * self.cell)

    def value(self, lat, lon):
        i, j = self.index(lat, lon)
        return int(self.row(i)[j])

    def window(self, lat, lon, half):
        """(2*half+1)^2 values around the cell of (lat, lon), longitude wrapped."""
        i, j = self.index(lat, lon)
        rows = [self.row(min(max(k, 0), self.height - 1)) for k in range(i - half, i + half + 1)]
        cols = [(j + d) % self.width for d in range(-half, half + 1)]
        return np.stack([r[cols] for r in rows])
