"""Checks of the generated Moon and Mars albedo maps (build/data/moon).

    /usr/bin/python3 -m pytest -q data/moon/test_moon_data.py
The data folder is $EOIR_DATA_DIR/moon (default: <repo>/build/data/moon).
"""
import json
import math
import os

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.environ.get("EOIR_DATA_DIR", os.path.join(HERE, "..", "..", "build", "data")), "moon")


def load(name):
    path = os.path.join(DATA, name + ".json")
    if not os.path.exists(path):
        pytest.fail(f"{path} missing: build the data first (cmake --build build --target eoir_data)")
    with open(path) as f:
        h = json.load(f)
    a = np.fromfile(os.path.join(DATA, h["file"]), dtype=np.uint8)
    assert a.size == h["width"] * h["height"] and h["encoding"] == "uint8"
    assert h["registration"] == "cell" and h["lon_west_deg"] == -180.0 and h["lat_north_deg"] == 90.0
    assert math.isclose(h["width"] * h["cell_deg"], 360.0) and math.isclose(h["height"] * h["cell_deg"], 180.0)
    return h, a.reshape(h["height"], h["width"]) * h["value_scale"] + h["value_offset"]


def area_mean(a):
    w = np.cos(np.radians(90 - (np.arange(a.shape[0]) + 0.5) * 180.0 / a.shape[0]))[:, None]
    return float((a * w).sum() / (w.sum() * a.shape[1]))


def at(h, a, lat, lon, half=2):
    i = int((h["lat_north_deg"] - lat) / h["cell_deg"])
    j = int((lon - h["lon_west_deg"]) % 360.0 / h["cell_deg"])
    return float(a[i - half:i + half + 1, j - half:j + half + 1].mean())


def near_side_disc_mean(a):
    lat = np.radians(90 - (np.arange(a.shape[0]) + 0.5) * 180.0 / a.shape[0])[:, None]
    lon = np.radians(-180 + (np.arange(a.shape[1]) + 0.5) * 360.0 / a.shape[1])[None, :]
    w = np.cos(lat) ** 2 * np.clip(np.cos(lon), 0, None)
    return float((a * w).sum() / w.sum())


# The Moon: geometric albedo 0.12 (NSSDC) as the full near-side disc's mean
# (a Lommel-Seeliger disc is uniform at full phase); Mars: the global mean.
@pytest.mark.parametrize("name,mean,weighting", [("moon_albedo_L0", 0.12, near_side_disc_mean),
                                                 ("moon_albedo_L1", 0.12, near_side_disc_mean),
                                                 ("mars_albedo_L0", 0.170, area_mean)])
def test_mean_albedo(name, mean, weighting):
    h, a = load(name)
    assert abs(weighting(a) - mean) < 0.002
    assert 0.02 < a.min() and a.max() < 0.5


def test_moon_maria_darker_than_highlands_and_east_is_east():
    h, a = load("moon_albedo_L1")
    mare = [at(h, a, 8.5, 31.4), at(h, a, 32.8, -15.6), at(h, a, 17.0, 59.1)]  # Tranquillitatis, Imbrium, Crisium
    high = [at(h, a, -20.0, 5.0), at(h, a, 0.0, 179.0), at(h, a, 20.0, -160.0)]  # near-side and far-side highlands
    assert max(mare) < 0.09 < 0.11 < min(high), (mare, high)
    # The bright craters Tycho (11.2 W) and Aristarchus (47.4 W) are brighter
    # than the mirrored positions east of the central meridian.
    assert at(h, a, -43.3, -11.2, 1) > at(h, a, -43.3, 11.2, 1) + 0.03
    assert at(h, a, 23.7, -47.4, 1) > at(h, a, 23.7, 47.4, 1) + 0.05


def test_mars_landmarks():
    h, a = load("mars_albedo_L0")
    syrtis, hellas = at(h, a, 9.0, 69.0, 1), at(h, a, -42.0, 70.0, 1)
    assert syrtis < 0.15 < hellas, (syrtis, hellas)   # dark Syrtis Major, bright Hellas
    assert at(h, a, 9.0, -69.0, 1) > syrtis + 0.03     # east is east
