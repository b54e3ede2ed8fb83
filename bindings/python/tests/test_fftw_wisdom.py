"""FFTW wisdom (core/fftw_plans.hpp): with EOIR_FFTW_WISDOM naming a file the
engine measures its FFT plans and keeps them there. Each case runs in a fresh
process, as the variable is read when a process first plans. Expected: the
frame equals the estimated plans' frame to rounding (1e-12 relative, the
transforms' own accuracy), the file holds FFTW wisdom, a second process that
reads it renders the same frame bit for bit, and a corrupt file is a cache
miss: the frame renders and the file is rewritten."""

import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SCENE = os.path.join(ROOT, "scenarios", "validation", "valid_sens_uniform_ext_area_src.json")

RENDER = """
import sys, numpy as np, eoir
with eoir.Scenario.load(sys.argv[1]) as sc:
    sc.set_time(sc.times()[0])
    sc.engine.set("Satellite2", "dimensions_m", [20000.0])  # a disc inside the field: edges to blur
    sc.engine.render("Sensor1")
    np.save(sys.argv[2], np.array(sc.engine.image("Sensor1", "sensor_mean"), dtype=float))
"""


def render(tmp_path, name, wisdom=None):
    env = dict(os.environ)
    env.pop("EOIR_FFTW_WISDOM", None)
    if wisdom is not None:
        env["EOIR_FFTW_WISDOM"] = str(wisdom)
    out = tmp_path / f"{name}.npy"
    subprocess.run([sys.executable, "-c", RENDER, SCENE, str(out)], env=env, check=True, timeout=300)
    return np.load(out)


def test_measured_plans_kept_in_the_wisdom_file(tmp_path):
    wisdom = tmp_path / "fftw_wisdom"
    estimated = render(tmp_path, "estimated")
    measured = render(tmp_path, "measured", wisdom)
    assert wisdom.read_text().startswith("(fftw-3")
    assert np.sum(estimated) > 0
    assert np.max(np.abs(measured - estimated)) <= 1e-12 * np.max(np.abs(estimated))
    again = render(tmp_path, "again", wisdom)
    assert np.array_equal(again, measured)
    assert not [p for p in os.listdir(tmp_path) if ".tmp" in p]  # written by a rename


def test_corrupt_wisdom_file_is_a_cache_miss(tmp_path):
    wisdom = tmp_path / "fftw_wisdom"
    wisdom.write_text("not wisdom\x00\xff")
    estimated = render(tmp_path, "estimated")
    measured = render(tmp_path, "measured", wisdom)
    assert np.max(np.abs(measured - estimated)) <= 1e-12 * np.max(np.abs(estimated))
    assert wisdom.read_text().startswith("(fftw-3")
