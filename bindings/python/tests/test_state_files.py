"""Save/restore of the whole engine (.scd) and of one sensor."""

import numpy as np
import pytest

import eoir

from conftest import STATIC_GROUPS, assert_same_value


def _all_values(engine, sensor="Sensor"):
    return {(g, name): value
            for g in STATIC_GROUPS
            for name, (value, _unit) in engine.report(g, sensor).items()}


def test_save_load_reproduces_every_provider_value(table3, tmp_path):
    table3.set("Sensor", "jitter_mrad", 0.01)  # a non-default value
    before = _all_values(table3)
    path = tmp_path / "scenario.scd"
    table3.save(path)
    assert path.exists() and path.stat().st_size > 0

    with eoir.Engine(threads=1, seed=7) as other:
        other.load(path)
        assert other.objects() == table3.objects()
        assert other.get_time("tt") == table3.get_time("tt")
        assert other.time_iso() == table3.time_iso()
        after = _all_values(other)
        assert after.keys() == before.keys()
        for key in before:
            assert_same_value(before[key], after[key], str(key))
        s1, s2 = table3.get_state("Sat"), other.get_state("Sat")
        for k in ("position", "velocity", "attitude"):
            np.testing.assert_array_equal(s1[k], s2[k])
        for p in table3.properties("Sensor"):
            a, b = table3.get("Sensor", p["name"]), other.get("Sensor", p["name"])
            if isinstance(a, np.ndarray):
                np.testing.assert_array_equal(a, b)
            else:
                assert a == b, p["name"]


def test_load_into_the_same_engine(table3, tmp_path):
    before = _all_values(table3)
    path = str(tmp_path / "same.scd")
    table3.save(path)
    table3.set("Sensor", "f_number", 5.0)
    table3.add_object("aircraft", "Plane")
    table3.load(path)
    assert "Plane" not in table3
    after = _all_values(table3)
    for key in before:
        assert_same_value(before[key], after[key], str(key))


def test_sensor_save_load(table3, tmp_path):
    path = tmp_path / "sensor.json"
    table3.set("Sensor", "f_number", 4.0)
    table3.set("Sensor", "sensitivity_pairs", np.array([[5.0, 2e-18], [10.0, 1e-18]]))
    before = _all_values(table3)
    table3.save_sensor("Sensor", path)
    assert path.exists()

    table3.add_sensor("Other", "Sat")
    table3.load_sensor("Other", path)
    after = _all_values(table3, "Other")
    for key in before:
        assert_same_value(before[key], after[key], str(key))
    np.testing.assert_array_equal(table3.get("Other", "sensitivity_pairs"),
                                  [5.0, 2e-18, 10.0, 1e-18])


def test_save_to_unwritable_path_is_file_error(table3, tmp_path):
    with pytest.raises(eoir.FileError):
        table3.save(tmp_path / "no" / "such" / "dir" / "x.scd")


def test_load_missing_file_is_file_error(engine, tmp_path):
    with pytest.raises(eoir.FileError):
        engine.load(tmp_path / "missing.scd")
