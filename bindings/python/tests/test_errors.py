"""Errors raise eoir.EoirError subclasses carrying eoir_last_error()."""

import json
import math

import numpy as np
import pytest

import eoir

from conftest import STATIC_GROUPS, assert_same_value


def test_nan_state_is_out_of_range(engine):
    engine.add_object("satellite", "Sat")
    with pytest.raises(eoir.OutOfRangeError) as info:
        engine.set_state("Sat", position=(7000e3, math.nan, 0.0))
    err = info.value
    assert isinstance(err, eoir.EoirError) and isinstance(err, ValueError)
    assert err.status == -102
    assert err.status_name == "EOIR_ERR_OUT_OF_RANGE"
    assert "position" in err.message
    assert "position" in str(err)
    assert err.message == eoir.last_error()


def test_seventh_sensor_exceeds_the_limit(engine):
    engine.add_object("satellite", "Sat")
    for i in range(eoir.MAX_SENSORS):
        engine.add_sensor(f"S{i}", "Sat")
    with pytest.raises(eoir.LimitExceededError) as info:
        engine.add_sensor("S6", "Sat")
    assert info.value.status == -200
    assert info.value.message
    assert "S6" not in engine


def test_unknown_group_is_unknown_name(table3):
    with pytest.raises(eoir.UnknownNameError) as info:
        table3.provider("No Such Group", "Ensquared Energy", "Sensor")
    assert info.value.status == -103
    assert info.value.message
    with pytest.raises(eoir.UnknownNameError):
        eoir.provider_elements("No Such Group")
    with pytest.raises(eoir.UnknownNameError):
        table3.report("No Such Group", "Sensor")


def test_unknown_element_object_and_property(table3):
    with pytest.raises(eoir.UnknownNameError):
        table3.provider("EOIR Sensor Optics", "No Such Element", "Sensor")
    with pytest.raises(eoir.UnknownNameError):
        table3.provider("EOIR Sensor Optics", "Ensquared Energy", "NoSuchSensor")
    with pytest.raises(eoir.UnknownNameError):
        table3.set("Sensor", "no_such_property", 1.0)
    with pytest.raises(eoir.UnknownNameError):
        table3.get("Sensor", "no_such_property")
    with pytest.raises(eoir.UnknownNameError):
        table3.get("NoSuchObject", "f_number")
    with pytest.raises(eoir.UnknownNameError):
        table3.remove("NoSuchObject")


def test_universe_errors(engine):
    engine.add_object("satellite", "Sat")
    with pytest.raises(eoir.AlreadyExistsError):
        engine.add_object("satellite", "Sat")
    with pytest.raises(eoir.NotAllowedError):
        engine.remove("Sun")
    with pytest.raises(eoir.EoirError):
        engine.add_object("central_body", "Pluto")
    with pytest.raises(eoir.EoirError):
        engine.add_object("satellite", "x" * (eoir.MAX_NAME_LENGTH + 1))
    with pytest.raises(ValueError):
        engine.add_object("spaceship", "X")


def test_out_of_range_property(table3):
    with pytest.raises(eoir.OutOfRangeError) as info:
        table3.set("Sensor", "f_number", -1.0)
    assert "f_number" in info.value.message
    with pytest.raises(eoir.OutOfRangeError):
        table3.set("Sensor", "focal_length_cm", float("inf"))
    assert table3.get("Sensor", "f_number") == 3.5


def test_too_many_reference_pairs(table3):
    pairs = np.array([[t, 1e-18] for t in range(1, eoir.MAX_REFERENCE_PAIRS + 2)], dtype=float)
    with pytest.raises(eoir.EoirError):
        table3.set("Sensor", "sensitivity_pairs", pairs)
    np.testing.assert_array_equal(table3.get("Sensor", "sensitivity_pairs"), [10.0, 1e-18])


def test_python_side_type_errors(table3):
    with pytest.raises((TypeError, ValueError)):
        table3.set("Sensor", "horizontal_pixels", 12.5)
    with pytest.raises(TypeError):
        table3.set("Sensor", "image_quality", 3)
    with pytest.raises(ValueError):
        table3.set("Sensor", "f_number", "abc")


def _snapshot(engine):
    values = {(g, n): v for g in STATIC_GROUPS
              for n, (v, _) in engine.report(g, "Sensor").items()}
    return engine.objects(), engine.get_time("tt"), values


def _assert_unchanged(engine, snap):
    objects, time, values = snap
    assert engine.objects() == objects
    assert engine.get_time("tt") == time
    for key, v in _snapshot(engine)[2].items():
        assert_same_value(values[key], v, str(key))


@pytest.mark.parametrize("content", [
    b"this is not JSON {",
    b"",
    b"[1, 2, 3]",
    b"{\"objects\": 12}",
])
def test_corrupt_scd_leaves_engine_unchanged(table3, tmp_path, content):
    snap = _snapshot(table3)
    path = tmp_path / "corrupt.scd"
    path.write_bytes(content)
    with pytest.raises(eoir.EoirError) as info:
        table3.load(path)
    assert isinstance(info.value, (eoir.FileError, eoir.ArgumentError))
    assert info.value.message
    _assert_unchanged(table3, snap)


def test_truncated_scd_is_corrupt_and_engine_unchanged(table3, tmp_path):
    good = tmp_path / "good.scd"
    table3.save(good)
    text = good.read_bytes()
    bad = tmp_path / "truncated.scd"
    bad.write_bytes(text[: len(text) // 2])
    table3.set("Sensor", "f_number", 4.0)
    snap = _snapshot(table3)
    with pytest.raises(eoir.CorruptFileError) as info:
        table3.load(bad)
    assert info.value.status == -301
    _assert_unchanged(table3, snap)


def test_scd_with_unknown_field_is_corrupt(table3, tmp_path):
    good = tmp_path / "good.scd"
    table3.save(good)
    doc = json.loads(good.read_text())
    assert isinstance(doc, dict), "the .scd root is an object (schemas/scd.schema.json)"
    doc["no_such_field_xyz"] = 1
    bad = tmp_path / "unknown.scd"
    bad.write_text(json.dumps(doc))
    snap = _snapshot(table3)
    with pytest.raises(eoir.CorruptFileError):
        table3.load(bad)
    _assert_unchanged(table3, snap)


def test_corrupt_sensor_file(table3, tmp_path):
    bad = tmp_path / "sensor.json"
    bad.write_text("{ not json")
    snap = _snapshot(table3)
    with pytest.raises(eoir.FileError):
        table3.load_sensor("Sensor", bad)
    _assert_unchanged(table3, snap)


def test_last_error_cleared_by_success(engine):
    with pytest.raises(eoir.UnknownNameError):
        engine.remove("Nobody")
    assert eoir.last_error()
    engine.objects()
    assert eoir.last_error() == ""


def test_newer_scd_version_is_file_version_error(table3, tmp_path):
    good = tmp_path / "good.scd"
    table3.save(good)
    doc = json.loads(good.read_text())
    assert isinstance(doc, dict) and isinstance(doc.get("version"), int), "the .scd root has an integer version"
    doc["version"] = 999
    newer = tmp_path / "newer.scd"
    newer.write_text(json.dumps(doc))
    snap = _snapshot(table3)
    with pytest.raises(eoir.FileVersionError) as info:
        table3.load(newer)
    assert info.value.status == -302
    _assert_unchanged(table3, snap)


def test_error_text_is_not_duplicated(engine):
    with pytest.raises(eoir.UnknownNameError) as info:
        engine.remove("Nobody")
    assert str(info.value).count("EOIR_ERR_UNKNOWN_NAME") == 1
    assert "Nobody" in str(info.value)


def test_errors_are_thread_local(engine):
    import threading
    seen = []

    def worker():
        try:
            engine.remove("Ghost")
        except eoir.UnknownNameError as exc:
            seen.append(exc.message)

    engine.objects()
    t = threading.Thread(target=worker)
    t.start()
    t.join()
    assert seen and "Ghost" in seen[0]
    assert eoir.last_error() == ""
