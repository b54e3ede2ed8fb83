"""Objects, time, states and typed properties through the Pythonic API."""

import datetime

import numpy as np
import pytest

import eoir


def test_objects_and_remove(engine):
    engine.add_object("satellite", "Sat")
    engine.add_object("aircraft", "Plane")
    engine.add_object("ground_vehicle", "Truck")
    engine.add_object("missile", "Rocket")
    engine.add_object("central_body", "Earth")
    engine.add_sensor("Cam", "Sat")
    objs = engine.objects()
    assert objs[0] == ("Sun", "central_body")
    assert ("Sat", "satellite") in objs
    assert ("Plane", "aircraft") in objs
    assert ("Truck", "ground_vehicle") in objs
    assert ("Rocket", "missile") in objs
    assert ("Earth", "central_body") in objs
    assert ("Cam", "sensor") in objs
    assert [n for n, _ in objs].index("Sat") < [n for n, _ in objs].index("Plane")
    engine.remove("Sat")  # takes its sensor with it
    names = [n for n, _ in engine.objects()]
    assert "Sat" not in names and "Cam" not in names
    assert engine.object_count() == len(names)


def test_time_iso_and_julian_dates(engine):
    engine.set_time("2010-08-25T18:00:00Z")
    assert engine.time_iso().startswith("2010-08-25T18:00:00")
    jd1, jd2, scale = engine.get_time("utc")
    assert scale == "utc"
    assert jd1 + jd2 == pytest.approx(2455434.25, abs=1e-9)
    tt = engine.get_time("tt")
    # TT - UTC = 66.184 s in 2010.
    assert ((tt[0] - jd1) + (tt[1] - jd2)) * 86400 == pytest.approx(66.184, abs=1e-3)
    engine.set_time(tt)
    assert engine.time_iso().startswith("2010-08-25T18:00:00")
    engine.set_time((2451545.0, 0.0, "tt"))
    assert engine.get_time("tt") == pytest.approx((2451545.0, 0.0, "tt")) or \
        sum(engine.get_time("tt")[:2]) == pytest.approx(2451545.0, abs=1e-12)
    engine.set_time(datetime.datetime(2012, 1, 1, 12, 0, 0, tzinfo=datetime.timezone.utc))
    assert engine.time_iso().startswith("2012-01-01T12:00:00")
    assert eoir.time_from_iso("2010-08-25T18:00:00Z")[2] == "utc"
    assert eoir.time_to_iso((2455434.25, 0.0, "utc")).startswith("2010-08-25T18:00:00")


def test_bad_iso_time(engine):
    with pytest.raises(eoir.EoirError):
        engine.set_time("not a time")


def test_state_round_trip(engine):
    engine.set_time("2010-08-25T18:00:00Z")
    engine.add_object("satellite", "Sat")
    q = np.array([0.5, 0.5, 0.5, 0.5])
    engine.set_state("Sat", position=[7000e3, 1000.0, -2000.0], velocity=np.array([1.0, 7500.0, 3.0]),
                     attitude=q)
    s = engine.get_state("Sat")
    assert s["frame"] == "j2000"
    np.testing.assert_allclose(s["position"], [7000e3, 1000.0, -2000.0], rtol=0, atol=1e-6)
    np.testing.assert_allclose(s["velocity"], [1.0, 7500.0, 3.0], atol=1e-9)
    np.testing.assert_allclose(s["attitude"], q, atol=1e-12)
    ef = engine.get_state("Sat", "earth_fixed")
    assert np.linalg.norm(ef["position"]) == pytest.approx(np.linalg.norm(s["position"]), rel=1e-9)


def test_geodetic_state(engine):
    engine.set_time("2010-08-25T18:00:00Z")
    engine.add_object("ground_vehicle", "Truck")
    engine.set_state("Truck", position=(0.0, 0.0, 0.0), frame="geodetic")
    ef = engine.get_state("Truck", "earth_fixed")
    np.testing.assert_allclose(ef["position"], [6378137.0, 0.0, 0.0], atol=1e-3)
    geo = engine.get_state("Truck", "geodetic")
    np.testing.assert_allclose(geo["position"], [0.0, 0.0, 0.0], atol=1e-6)


def test_geodetic_ned_state(engine):
    """frame="geodetic_ned" with heading_pitch_roll_quaternion (issue 22):
    at 0 N 0 E north is Earth-fixed +z, east +y, down -x, so a heading of
    90 deg (east) with no pitch or roll puts the nose along +y and the right
    wing along -z (south); the NED velocity (north 100, east 20, down -3)
    is (3, 20, 100) Earth-fixed."""
    engine.set_time("2010-08-25T18:00:00Z")
    engine.add_object("aircraft", "Jet")
    q = eoir.heading_pitch_roll_quaternion(90.0, 0.0, 0.0)
    np.testing.assert_allclose(q, [np.sqrt(0.5), 0.0, 0.0, np.sqrt(0.5)], atol=1e-15)
    engine.set_state("Jet", position=(0.0, 0.0, 10000.0), velocity=(100.0, 20.0, -3.0), attitude=q,
                     frame="geodetic_ned")
    ef = engine.get_state("Jet", "earth_fixed")
    np.testing.assert_allclose(ef["position"], [6388137.0, 0.0, 0.0], atol=1e-3)
    np.testing.assert_allclose(ef["velocity"], [3.0, 20.0, 100.0], atol=1e-9)
    w, x, y, z = ef["attitude"]
    nose = [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)]
    wing = [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)]
    np.testing.assert_allclose(nose, [0.0, 1.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(wing, [0.0, 0.0, -1.0], atol=1e-12)
    back = engine.get_state("Jet", "geodetic_ned")
    assert back["frame"] == "geodetic_ned"
    np.testing.assert_allclose(back["position"], [0.0, 0.0, 10000.0], atol=1e-6)
    np.testing.assert_allclose(back["velocity"], [100.0, 20.0, -3.0], atol=1e-9)
    np.testing.assert_allclose(np.abs(np.dot(back["attitude"], q)), 1.0, atol=1e-12)
    with pytest.raises(eoir.OutOfRangeError, match="pitch_deg"):
        eoir.heading_pitch_roll_quaternion(0.0, float("nan"), 0.0)


def test_state_at_explicit_time_extrapolates(engine):
    engine.set_time("2010-08-25T18:00:00Z")
    engine.add_object("aircraft", "Plane")
    engine.set_state("Plane", position=(7000e3, 0, 0), velocity=(0, 100.0, 0),
                     time="2010-08-25T17:59:50Z")
    s = engine.get_state("Plane")
    np.testing.assert_allclose(s["position"], [7000e3, 1000.0, 0.0], atol=1e-3)


def test_state_shape_checked(engine):
    engine.add_object("satellite", "Sat")
    with pytest.raises(ValueError):
        engine.set_state("Sat", position=(1.0, 2.0))


def test_properties_listing(table3):
    props = {p["name"]: p for p in table3.properties("Sensor")}
    assert props["horizontal_pixels"]["type"] == "integer"
    assert props["horizontal_fov_deg"]["type"] == "number"
    assert props["horizontal_fov_deg"]["unit"] == "deg"
    assert props["image_quality"]["type"] == "string"
    assert props["sensitivity_pairs"]["type"] == "array"
    assert all(p["description"] for p in props.values())
    assert table3.property_type("Sensor", "f_number") == "number"
    assert table3.property_type("Sensor", "nope") is None
    # Ranges, closed sets and fidelity flags (C ABI 1.3).
    fov = props["horizontal_fov_deg"]
    assert fov["minimum"] == 1e-6 and not fov["minimum_open"] and fov["maximum"] == 179.9 and not fov["maximum_open"]
    assert props["image_quality"]["choices"][:2] == ["diffraction_limited", "negligible"]
    assert props["samples_per_pixel"]["fidelity"] and not props["f_number"]["fidelity"]
    assert props["noise_enabled"]["minimum"] is None and props["noise_enabled"]["choices"] == []
    # Objects have properties too (shape, material, ...), possibly none.
    assert isinstance(table3.properties("Sat"), list)


def test_typed_set_get(table3):
    table3.set("Sensor", "horizontal_pixels", np.int64(256))
    assert table3.get("Sensor", "horizontal_pixels") == 256
    table3.set("Sensor", "horizontal_pixels", 64.0)  # integral floats are accepted
    assert table3.get("Sensor", "horizontal_pixels") == 64
    table3.set("Sensor", "f_number", np.float64(4.25))
    assert table3.get("Sensor", "f_number") == 4.25
    table3.set("Sensor", "f_number", 4)  # ints are fine for numbers
    assert isinstance(table3.get("Sensor", "f_number"), float)
    table3.set("Sensor", "image_quality", "mild")
    assert table3.get("Sensor", "image_quality") == "mild"
    table3.set("Sensor", "saturation_pairs", [[10.0, 1e-15], [20.0, 2e-15]])
    got = table3.get("Sensor", "saturation_pairs")
    assert isinstance(got, np.ndarray) and got.dtype == np.float64
    np.testing.assert_array_equal(got, [10.0, 1e-15, 20.0, 2e-15])
    pairs = np.array([(float(t), 1e-18 * t) for t in range(1, eoir.MAX_REFERENCE_PAIRS + 1)])
    table3.set("Sensor", "sensitivity_pairs", pairs)
    np.testing.assert_array_equal(table3.get("Sensor", "sensitivity_pairs"), pairs.ravel())
    bools = [p["name"] for p in table3.properties("Sensor") if p["type"] == "bool"]
    for name in bools:
        old = table3.get("Sensor", name)
        assert isinstance(old, bool)
        table3.set("Sensor", name, not old)
        assert table3.get("Sensor", name) is (not old)
        table3.set("Sensor", name, old)


def test_every_property_reads(table3):
    for p in table3.properties("Sensor"):
        value = table3.get("Sensor", p["name"])
        expected = {"number": float, "integer": int, "bool": bool, "string": str,
                    "array": np.ndarray}[p["type"]]
        assert isinstance(value, expected), p["name"]


def test_limits_default_profile_and_raised():
    """Object limits (issue 23 item 3): the spec's profile by default, the
    17th satellite refused naming max_satellites, accepted once raised; bad
    values refused naming the field, an unknown name a ValueError."""
    with eoir.Engine() as e:
        assert e.limits() == {"max_satellites": 16, "max_vehicles": 6, "max_sites": 16, "max_missiles": 6,
                              "max_sensors": 6}
        for i in range(16):
            e.add_object("satellite", f"S{i}")
        with pytest.raises(eoir.LimitExceededError, match="max_satellites"):
            e.add_object("satellite", "S16")
        e.set_limits(max_satellites=1000)
        assert e.limits()["max_satellites"] == 1000 and e.limits()["max_vehicles"] == 6
        e.add_object("satellite", "S16")
        with pytest.raises(eoir.OutOfRangeError, match="max_satellites"):
            e.set_limits(max_satellites=0)
        with pytest.raises(eoir.NotAllowedError):
            e.set_limits(max_satellites=10)  # below the 17 it holds
        with pytest.raises(ValueError, match="max_planets"):
            e.set_limits(max_planets=3)
        assert e.limits()["max_satellites"] == 1000  # refusals change nothing
