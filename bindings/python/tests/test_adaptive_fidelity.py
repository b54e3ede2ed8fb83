"""Adaptive fidelity (README "Adaptive fidelity"): with the sensor property
error_budget the engine chooses each frame's knobs and reports them.

On the three reference scenes of the speed-against-accuracy sweep
(tests/bench/fidelity_sweep.py, whose high-fidelity settings REFERENCE this
test uses), the adaptive frame's relative RMS error of the noise-free pixel
means against the high-fidelity frame is within the budget: the tolerance is
the budget itself, the expected value an independent frame with every knob at
its high-fidelity value. Budget 0 renders the sensor's own settings, bit for
bit the frame rendered before any budget was set. Speed is the sweep's
business (no timing here)."""

import json
import os
import sys

import numpy as np
import pytest

import eoir

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "bench"))
import fidelity_sweep  # noqa: E402  (SCENES, REFERENCE, REFERENCE_OVERRIDES, relative_rms)

BUDGET = 0.005


def render_mean(engine, sensor):
    engine.render(sensor)
    return np.array(engine.image(sensor, "sensor_mean"), dtype=float)


@pytest.mark.parametrize("scene", sorted(fidelity_sweep.SCENES))
def test_adaptive_frame_within_budget_of_the_high_fidelity_frame(scene):
    path, sensor = fidelity_sweep.SCENES[scene]
    with eoir.Scenario.load(os.path.join(ROOT, path)) as sc:
        sc.set_time(sc.times()[0])
        e = sc.engine
        own = {k: e.get(sensor, k) for k in fidelity_sweep.REFERENCE}
        before = render_mean(e, sensor)  # budget 0: the sensor's own settings
        fixed = e.frame_fidelity(sensor)
        assert fixed["error_budget"] == 0 and fixed["estimated_error"] == 0
        assert all(fixed[k] == v for k, v in own.items())

        for k, v in {**fidelity_sweep.REFERENCE, **fidelity_sweep.REFERENCE_OVERRIDES.get(scene, {})}.items():
            e.set(sensor, k, v)
        reference = render_mean(e, sensor)
        for k, v in own.items():
            e.set(sensor, k, v)

        e.set(sensor, "error_budget", BUDGET)
        adaptive = render_mean(e, sensor)
        chosen = e.frame_fidelity(sensor)
        error = fidelity_sweep.relative_rms(adaptive, reference)
        print(f"{scene}: error {error:.2e} (estimated {chosen['estimated_error']:.2e}) with {chosen}")
        assert chosen["error_budget"] == BUDGET
        assert 0 <= chosen["estimated_error"]
        assert error <= BUDGET
        # The sensor's own settings are unchanged: the choice is the frame's.
        assert e.get(sensor, "samples_per_pixel") == own["samples_per_pixel"]
        # The choice is kept for its world only: a re-render reuses it, a new
        # step (set_time builds the world anew) makes the same one again, and
        # a changed budget makes a new one.
        assert np.array_equal(render_mean(e, sensor), adaptive) and e.frame_fidelity(sensor) == chosen
        sc.set_time(sc.times()[0])
        assert np.array_equal(render_mean(e, sensor), adaptive) and e.frame_fidelity(sensor) == chosen
        e.set(sensor, "error_budget", 2 * BUDGET)
        render_mean(e, sensor)
        assert e.frame_fidelity(sensor)["error_budget"] == 2 * BUDGET

        e.set(sensor, "error_budget", 0.0)
        assert np.array_equal(render_mean(e, sensor), before)
        assert e.frame_fidelity(sensor) == fixed


def test_error_budget_is_validated_and_saved(engine, table3, tmp_path):
    for bad in (float("nan"), -0.001, 1.0, 2.0):
        with pytest.raises(eoir.OutOfRangeError, match="error_budget"):
            engine.set("Sensor", "error_budget", bad)
    engine.set("Sensor", "error_budget", 0.02)
    path = tmp_path / "sensor.json"
    engine.save_sensor("Sensor", path)
    assert json.loads(path.read_text())["parameters"]["error_budget"] == 0.02
    engine.set("Sensor", "error_budget", 0.0)
    engine.load_sensor("Sensor", path)
    assert engine.get("Sensor", "error_budget") == 0.02
