"""What the demo scripts share: the eoir package (from bindings/python unless
it is importable already; the library may be mid-rebuild: wait 30 s and
retry), WGS84 (Earth-fixed positions, the local east-north-up axes) and an
atomic JSON writer."""

from __future__ import annotations

import importlib
import importlib.util
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]

WGS84_A = 6378137.0
WGS84_F = 1.0 / 298.257223563
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)


def import_eoir():
    if importlib.util.find_spec("eoir") is None:
        sys.path.insert(0, str(REPO / "bindings" / "python"))
    for attempt in range(4):
        try:
            return importlib.import_module("eoir")
        except (ImportError, OSError) as exc:
            if attempt == 3:
                raise
            print(f"loading eoir failed ({exc}); retrying in 30 s", flush=True)
            time.sleep(30)


def ecef(lat_deg, lon_deg, h_m):
    """WGS84 geodetic (deg, deg, m) to Earth-fixed metres."""
    lat, lon = math.radians(lat_deg), math.radians(lon_deg)
    n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
    return np.array([(n + h_m) * math.cos(lat) * math.cos(lon), (n + h_m) * math.cos(lat) * math.sin(lon),
                     (n * (1.0 - WGS84_E2) + h_m) * math.sin(lat)])


def enu_axes(lat_deg, lon_deg):
    """The local east, north and up unit vectors (Earth-fixed)."""
    lat, lon = math.radians(lat_deg), math.radians(lon_deg)
    east = np.array([-math.sin(lon), math.cos(lon), 0.0])
    north = np.array([-math.sin(lat) * math.cos(lon), -math.sin(lat) * math.sin(lon), math.cos(lat)])
    up = np.array([math.cos(lat) * math.cos(lon), math.cos(lat) * math.sin(lon), math.sin(lat)])
    return east, north, up


def write_json(path, data):
    """JSON written to a temporary file and renamed (never half-written)."""
    tmp = f"{path}.tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)
