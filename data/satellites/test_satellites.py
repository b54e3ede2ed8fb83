"""Checks of the predefined composite satellites (pytest).

    /usr/bin/python3 -m pytest -q data/satellites

Reads the authored files of data/satellites/ and, when the data folder
($EOIR_DATA_DIR, default <repo>/build/data) has been built, its copies in
satellites/. Needs python3-numpy and python3-pytest.
"""
import glob
import json
import math
import os

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
DATA = os.environ.get("EOIR_DATA_DIR", os.path.join(REPO, "build", "data"))
MATERIALS = os.path.join(REPO, "data", "materials", "authored")
FILES = sorted(glob.glob(os.path.join(HERE, "*.json")))
NAMES = ["leo_earth_observing", "leo_communications", "geo_communications"]

# engine/universe/shapes.cpp: dimensions each shape takes; composite.cpp: part fields (+ material)
DIMS = {"sphere": 1, "oblate": 2, "box": 3, "plate": 2, "cylinder": 2, "cone": 2, "coupler": 3}
FIELDS = {"shape", "dimensions_m", "offset_m", "orientation_wxyz", "temperature_K", "reflectance", "parts",
          "material"}


def load(path):
    with open(path) as f:
        return json.load(f)


def flat_parts(parts):
    for p in parts:
        if "parts" in p:
            yield from flat_parts(p["parts"])
        else:
            yield p


def rotate(q, v):
    w, x, y, z = q
    r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return r @ np.asarray(v, dtype=float)


def corners(p):
    """Points bounding the part in the body frame (nesting not used by these files)."""
    d = p["dimensions_m"]
    s = p["shape"]
    if s == "box":
        h = [d[0] / 2, d[1] / 2, d[2] / 2]
    elif s == "plate":
        h = [d[0] / 2, d[1] / 2, 0.0]
    elif s in ("cylinder", "cone"):
        h = [d[0], d[0], d[1] / 2]
    elif s == "coupler":
        h = [max(d[0], d[1]), max(d[0], d[1]), d[2] / 2]
    else:
        h = [d[0], d[0], d[-1]]
    q = p.get("orientation_wxyz", [1, 0, 0, 0])
    o = np.asarray(p.get("offset_m", [0, 0, 0]), dtype=float)
    return [o + rotate(q, [sx * h[0], sy * h[1], sz * h[2]]) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]


def extent(doc):
    pts = np.array([c for p in flat_parts(doc["parts"]) for c in corners(p)])
    return pts.max(axis=0) - pts.min(axis=0)


def test_the_three_satellites_exist():
    assert [os.path.basename(f)[:-5] for f in FILES] == sorted(NAMES)


@pytest.mark.parametrize("path", FILES, ids=os.path.basename)
def test_format_and_parts(path):
    doc = load(path)
    assert doc["format"] == "eoir-composite" and doc["version"] == 1
    assert doc["name"] + ".json" == os.path.basename(path)
    assert doc["description"] and len(doc["sources"]) >= 2
    parts = list(flat_parts(doc["parts"]))
    assert 5 <= len(parts) <= 256
    for p in parts:
        assert set(p) <= FIELDS, set(p) - FIELDS
        assert len(p["dimensions_m"]) == DIMS[p["shape"]]
        assert all(isinstance(v, (int, float)) and v > 0 and math.isfinite(v) for v in p["dimensions_m"])
        assert len(p["offset_m"]) == 3
        q = p["orientation_wxyz"]
        assert len(q) == 4 and abs(math.sqrt(sum(c * c for c in q)) - 1) < 1e-6
        assert 150.0 <= p["temperature_K"] <= 400.0
        assert 0.0 <= p["reflectance"] <= 1.0


@pytest.mark.parametrize("path", FILES, ids=os.path.basename)
def test_materials_exist_and_reflectance_matches_solar_absorptance(path):
    from_e490 = {"gold_mli": 0.38, "aluminum_mli": 0.12, "silver_mli": 0.08, "white_thermal_control": 0.17,
                 "black_thermal_control": 0.95, "solar_panel": 0.80}
    for p in flat_parts(load(path)["parts"]):
        assert os.path.exists(os.path.join(MATERIALS, p["material"] + ".json")), p["material"]
        if p["material"] in from_e490:
            # the grey reflectance is 1 - alpha_s of the material (data/materials/README.md)
            assert abs(p["reflectance"] - (1 - from_e490[p["material"]])) < 0.011


def test_plausible_sizes():
    ext = {os.path.basename(f)[:-5]: extent(load(f)) for f in FILES}
    # Landsat-8 class: bus ~3 m plus one ~9 m wing -> largest extent 10-15 m
    assert 10.0 <= ext["leo_earth_observing"].max() <= 15.0
    # Iridium-NEXT class: ~3 m bus, two wings -> 8-12 m span
    assert 8.0 <= ext["leo_communications"].max() <= 12.0
    # SSL-1300 / Boeing-702 class: 26-31 m array span
    assert 26.0 <= ext["geo_communications"].max() <= 31.0
    for e in ext.values():
        assert e.min() > 1.0


def test_arrays_are_the_warmest_parts():
    for f in FILES:
        parts = list(flat_parts(load(f)["parts"]))
        arrays = [p["temperature_K"] for p in parts if p["material"] == "solar_panel"]
        bus = [p["temperature_K"] for p in parts if p["shape"] == "box"][0]
        assert arrays and min(arrays) >= 320.0 and bus == 290.0


def test_copied_to_the_data_folder():
    out = os.path.join(DATA, "satellites")
    assert os.path.isdir(out), f"{out} missing: build the eoir_data target first"
    for f in FILES:
        assert load(os.path.join(out, os.path.basename(f))) == load(f)
