"""Sites and pointing through the bindings (C ABI 1.5): the "site" kind,
Engine.point_at by azimuth/elevation and at a target, and the topocentric
azimuth and elevation of Engine.truth.

Expected directions are computed here: WGS84 geodetic to Earth-fixed in
closed form and the east-north-up basis of the geodetic normal."""

import math

import numpy as np
import pytest

import eoir

T0 = "2010-08-25T04:00:00Z"
LAT, LON, HEIGHT = -24.6272, -70.4042, 2635.0  # Paranal
N = 48
A, F = 6378137.0, 1.0 / 298.257223563


def ecef(lat, lon, h):
    e2 = F * (2 - F)
    p, l = math.radians(lat), math.radians(lon)
    n = A / math.sqrt(1 - e2 * math.sin(p) ** 2)
    return np.array([(n + h) * math.cos(p) * math.cos(l), (n + h) * math.cos(p) * math.sin(l),
                     (n * (1 - e2) + h) * math.sin(p)])


def enu(lat, lon):
    p, l = math.radians(lat), math.radians(lon)
    return (np.array([-math.sin(l), math.cos(l), 0.0]),
            np.array([-math.sin(p) * math.cos(l), -math.sin(p) * math.sin(l), math.cos(p)]),
            np.array([math.cos(p) * math.cos(l), math.cos(p) * math.sin(l), math.sin(p)]))


def at_azel(az, el, rng):
    e, n, u = enu(LAT, LON)
    a, b = math.radians(az), math.radians(el)
    return ecef(LAT, LON, HEIGHT) + rng * (math.cos(b) * math.sin(a) * e + math.cos(b) * math.cos(a) * n
                                           + math.sin(b) * u)


@pytest.fixture
def engine():
    with eoir.Engine(seed=1, threads=2) as e:
        e.set_time(T0)
        e.add_object("central_body", "Earth")
        e.add_object("site", "Paranal")
        e.set("Paranal", "latitude_deg", LAT)
        e.set("Paranal", "longitude_deg", LON)
        e.set("Paranal", "height_m", HEIGHT)
        e.add_sensor("Scope", "Paranal")
        for k, v in (("horizontal_pixels", N), ("vertical_pixels", N), ("horizontal_fov_deg", 0.5),
                     ("vertical_fov_deg", 0.5), ("noise_enabled", False)):
            e.set("Scope", k, v)
        yield e


def test_site_kind_and_properties(engine):
    assert ("Paranal", "site") in engine.objects()
    assert [p["name"] for p in engine.properties("Paranal")] == ["latitude_deg", "longitude_deg", "height_m"]
    assert engine.get("Paranal", "height_m") == HEIGHT
    assert eoir.KINDS["site"] == 8 and eoir.MAX_SITES == 16
    g = engine.get_state("Paranal", "geodetic")["position"]
    assert g == pytest.approx([LAT, LON, HEIGHT], abs=1e-6)


def test_point_at_azimuth_elevation_centres_the_target(engine):
    """A satellite placed at (az, el) lands on the centre (0.05 px) and truth
    returns its azimuth and elevation (1e-6 deg)."""
    engine.add_object("satellite", "Sat")
    engine.set_state("Sat", position=at_azel(222.0, 41.0, 1200e3), frame="earth_fixed")
    engine.point_at("Scope", azimuth_deg=222.0, elevation_deg=41.0)
    engine.render("Scope")
    (row,) = engine.truth("Scope")
    assert row["object"] == "Sat"
    assert row["pixel_x"] == pytest.approx((N - 1) / 2, abs=0.05)
    assert row["pixel_y"] == pytest.approx((N - 1) / 2, abs=0.05)
    assert row["azimuth_deg"] == pytest.approx(222.0, abs=1e-6)
    assert row["elevation_deg"] == pytest.approx(41.0, abs=1e-6)


def test_point_at_target_tracks_without_streak(engine):
    """Tracking a satellite crossing at 7 km/s: at the centre, no streak."""
    engine.set("Scope", "integration_time_ms", 200.0)
    engine.add_object("satellite", "Sat")
    engine.set_state("Sat", position=at_azel(10.0, 70.0, 800e3), frame="earth_fixed")
    s = engine.get_state("Sat")
    v = np.cross([0.0, 0.0, 1.0], s["position"] - engine.get_state("Paranal")["position"])
    engine.set_state("Sat", position=s["position"], velocity=7000.0 * v / np.linalg.norm(v))
    engine.point_at("Scope", target="Sat")
    engine.render("Scope")
    (row,) = engine.truth("Scope")
    assert row["pixel_x"] == pytest.approx((N - 1) / 2, abs=0.05)
    assert row["pixel_y"] == pytest.approx((N - 1) / 2, abs=0.05)
    assert np.hypot(row["end"][0] - row["start"][0], row["end"][1] - row["start"][1]) < 0.05
    assert row["elevation_deg"] == pytest.approx(70.0, abs=1e-6)


def test_truth_air_mass_and_refraction(engine):
    """With the atmosphere on, truth's air mass from Paranal (2635 m) is
    Kasten and Young (1989) times the US76 pressure there, p/p0 =
    (1 - 2.25577e-5 h)^5.25588 = 0.7246, within 1 %; the satellite moves up
    the picture by the refraction (about 1.3 px); off, the air mass is 0."""
    engine.add_object("satellite", "Sat")
    engine.set_state("Sat", position=at_azel(222.0, 41.0, 1200e3), frame="earth_fixed")
    engine.point_at("Scope", azimuth_deg=222.0, elevation_deg=41.0)
    engine.render("Scope")
    (off,) = engine.truth("Scope")
    assert off["air_mass"] == 0.0
    engine.set("Earth", "atmosphere", "simple")
    engine.render("Scope")
    (on,) = engine.truth("Scope")
    z = 90.0 - 41.0 - 0.014  # apparent zenith angle (deg): about 50" of refraction
    kasten_young = 1.0 / (math.cos(math.radians(z)) + 0.50572 * (96.07995 - z) ** -1.6364)
    assert on["air_mass"] == pytest.approx(kasten_young * (1 - 2.25577e-5 * HEIGHT) ** 5.25588, rel=0.01)
    assert on["pixel_x"] == pytest.approx(off["pixel_x"], abs=0.01)
    assert 1.0 < off["pixel_y"] - on["pixel_y"] < 1.6
    assert on["elevation_deg"] == off["elevation_deg"]


def test_truth_from_space_has_no_azimuth():
    with eoir.Engine(threads=1) as e:
        e.set_time(T0)
        e.add_object("satellite", "Host")
        e.set("Host", "shape", "none")
        e.set_state("Host", position=(42164e3, 0.0, 0.0))
        e.add_sensor("Cam", "Host")
        e.add_object("satellite", "Sat")
        e.set_state("Sat", position=(42164e3, 0.0, 50e3))
        e.render("Cam")
        (row,) = e.truth("Cam")
        assert row["azimuth_deg"] is None and row["elevation_deg"] is None


def test_bad_input_names_the_field(engine):
    with pytest.raises(eoir.OutOfRangeError, match="latitude_deg"):
        engine.set("Paranal", "latitude_deg", 91.0)
    with pytest.raises(eoir.OutOfRangeError, match="latitude_deg"):
        engine.set("Paranal", "latitude_deg", float("nan"))
    with pytest.raises(eoir.OutOfRangeError, match="elevation_deg"):
        engine.point_at("Scope", azimuth_deg=0.0, elevation_deg=90.5)
    with pytest.raises(eoir.OutOfRangeError, match="azimuth_deg"):
        engine.point_at("Scope", azimuth_deg=float("nan"), elevation_deg=10.0)
    with pytest.raises(eoir.NotAllowedError, match="target"):
        engine.point_at("Scope", target="Paranal")
    with pytest.raises(eoir.NotAllowedError, match="state"):
        engine.set_state("Paranal", position=(0.0, 0.0, 0.0), frame="geodetic")
    with pytest.raises(ValueError):
        engine.point_at("Scope")
    with pytest.raises(ValueError):
        engine.point_at("Scope", target="Paranal", azimuth_deg=1.0, elevation_deg=2.0)


def test_site_is_not_a_vehicle():
    with eoir.Engine(threads=1) as e:
        for i in range(eoir.MAX_VEHICLES):
            e.add_object("aircraft" if i % 2 else "ground_vehicle", f"V{i}")
        e.add_object("site", "Site")
        with pytest.raises(eoir.LimitExceededError, match="aircraft plus ground vehicles"):
            e.add_object("aircraft", "V6")
