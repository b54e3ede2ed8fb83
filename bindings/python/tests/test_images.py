"""Images through the bindings: Engine.render, image, image_info, pick."""

import math

import numpy as np
import pytest

import eoir

T0 = "2010-08-25T18:00:00Z"
HOST = np.array([7000e3, 0.0, 0.0])
W, H = 16, 12  # sensor pixels (non-square counts to catch swapped axes)
TEMPERATURE_K = 300.0
REFLECTANCE = 0.2  # emissivity 0.8


def planck_um(wl_um, t_k):
    """Blackbody spectral radiance, W/(cm^2 sr um)."""
    h, c, k = 6.62607015e-34, 2.99792458e8, 1.380649e-23
    wl = np.asarray(wl_um, dtype=np.float64) * 1e-6
    l_m = 2 * h * c ** 2 / wl ** 5 / np.expm1(h * c / (wl * k * t_k))  # W/(m^2 sr m)
    return l_m * 1e-4 * 1e-6


def band_radiance(lo_um, hi_um, t_k, emissivity):
    wl = np.linspace(lo_um, hi_um, 20001)
    y = planck_um(wl, t_k)
    return emissivity * float(np.sum((y[1:] + y[:-1]) / 2 * np.diff(wl)))


def build(engine, attitude=(1.0, 0.0, 0.0, 0.0), **params):
    """A 1 km sphere 10 km along J2000 +z from the sensor; the sensor looks
    along its body +z, so with the identity attitude the sphere (half-angle
    5.7 deg) fills the 2 x 1.5 deg field."""
    engine.set_time(T0)
    engine.add_object("satellite", "Host")
    engine.add_object("satellite", "Ball")
    engine.set_state("Host", HOST)
    engine.set_state("Ball", HOST + [0.0, 0.0, 10e3])
    engine.set("Ball", "shape", "sphere")
    engine.set("Ball", "dimensions_m", [1000.0])
    engine.set("Ball", "temperature_K", TEMPERATURE_K)
    engine.set("Ball", "reflectance", REFLECTANCE)
    engine.add_sensor("Cam", "Host")
    settings = dict(horizontal_pixels=W, vertical_pixels=H, horizontal_fov_deg=2.0, vertical_fov_deg=1.5,
                    band_low_um=8.0, band_high_um=12.0)
    settings.update(params)
    for name, value in settings.items():
        engine.set("Cam", name, value)
    engine.set_state("Cam", HOST, attitude=attitude)  # the sensor's own attitude
    return engine


def test_shapes_and_dtypes(engine):
    build(engine)
    engine.render("Cam")
    shapes = {"scene_radiance": ((4 * H, 4 * W), np.float64), "scene_display": ((4 * H, 4 * W), np.uint8),
              "sensor_electrons": ((H, W), np.float64), "sensor_mean": ((H, W), np.float64),
              "sensor_display": ((H, W), np.uint8)}
    for kind, (shape, dtype) in shapes.items():
        img = engine.image("Cam", kind)
        assert img.shape == shape, kind
        assert img.dtype == dtype, kind
        info = engine.image_info("Cam", kind)
        assert (info["height"], info["width"]) == shape, kind
        assert info["kind"] == kind
    assert set(eoir.IMAGE_KINDS) == set(shapes) | {"sensor_adu"}  # with detector_model on: below


def test_detector_adu_image(engine):
    """The detector stage (README "Detector model"): an unsigned ADU image
    beside the electrons, ADU = clamp(floor(e / gain + bias + 1/2), 0,
    2^bits - 1), and no ADU image with the stage off."""
    build(engine)
    engine.render("Cam")
    with pytest.raises(eoir.NoStateError):
        engine.image("Cam", "sensor_adu")
    build_detector = dict(detector_model=True, gain_e_per_adu=3.0, bias_adu=200.0, read_noise_e=4.0,
                          full_well_e=5.0e4, adc_bits=12, dark_current_e_s=50.0)
    for name, value in build_detector.items():
        engine.set("Cam", name, value)
    engine.render("Cam")
    adu = engine.image("Cam", "sensor_adu")
    e = engine.image("Cam", "sensor_electrons")
    assert adu.dtype == np.uint32 and adu.shape == (H, W)
    np.testing.assert_array_equal(adu, np.clip(np.floor(e / 3.0 + 200.0 + 0.5), 0, 4095))
    info = engine.image_info("Cam", "sensor_adu")
    assert info["unit"] == "adu"
    assert info["gain_e_per_adu"] == 3.0 and info["bias_adu"] == 200.0 and info["adc_max_adu"] == 4095.0
    assert info["saturation_adu"] == 4095.0  # 5e4 / 3 + 200 is past 2^12 - 1
    assert info["saturation_electrons"] == 5.0e4 and info["read_noise_electrons"] == 4.0


def test_image_info_fields(engine):
    build(engine)
    engine.render("Cam")
    info = engine.image_info("Cam", "sensor_electrons")
    assert info["unit"] == "electrons"
    assert engine.image_info("Cam", "scene_radiance")["unit"] == "W/(cm^2 sr)"
    assert engine.image_info("Cam", "sensor_display")["unit"] == ""
    assert info["time"].startswith("2010-08-25T18:00:00")
    jd = sum(info["time_jd_utc"])
    assert jd == pytest.approx(2455434.25, abs=1e-9)
    # Identity attitude: body +z = J2000 +z (the pole), body +y = J2000 +y.
    assert info["boresight_dec_deg"] == pytest.approx(90.0, abs=1e-9)
    assert info["up_dec_deg"] == pytest.approx(0.0, abs=1e-9)
    assert info["up_ra_deg"] % 360.0 == pytest.approx(90.0, abs=1e-9)


def test_scene_radiance_is_gray_body_band_radiance(engine):
    build(engine, band_integration="exact")
    engine.render("Cam")
    rad = engine.image("Cam", "scene_radiance")
    expected = band_radiance(8.0, 12.0, TEMPERATURE_K, 1.0 - REFLECTANCE)
    np.testing.assert_allclose(rad, expected, rtol=1e-4)
    # The default spectral grid is close to the exact integral.
    engine.set("Cam", "band_integration", "grid")
    engine.render("Cam")
    np.testing.assert_allclose(engine.image("Cam", "scene_radiance"), expected, rtol=1e-2)


def test_pick_names_the_object(engine):
    build(engine)
    engine.render("Cam")
    rad = engine.image("Cam", "scene_radiance")
    for x, y in ((0, 0), (4 * W - 1, 4 * H - 1), (17, 5)):
        p = engine.pick("Cam", x, y)
        assert p["hit"] is True
        assert p["object"] == "Ball"
        assert p["patch"] >= 0
        assert 9000.0 <= p["range_m"] < 9100.0
        assert p["temperature_K"] == pytest.approx(TEMPERATURE_K)
        assert p["effective_radiance"] == pytest.approx(rad[y, x], rel=1e-12)
        wl, spec = p["wavelengths_um"], p["spectral_radiance"]
        assert wl.dtype == np.float64 and wl.shape == spec.shape and wl.size >= 2
        assert np.all((wl > 8.0) & (wl < 12.0))
        np.testing.assert_allclose(spec, (1.0 - REFLECTANCE) * planck_um(wl, TEMPERATURE_K), rtol=1e-3)
    pix = engine.pick("Cam", W - 1, H - 1, space="pixel")
    assert pix["object"] == "Ball"
    with pytest.raises(eoir.OutOfRangeError):
        engine.pick("Cam", W, 0, space="pixel")
    with pytest.raises(eoir.OutOfRangeError):
        engine.pick("Cam", 0, 4 * H, space="sample")
    with pytest.raises(ValueError):
        engine.pick("Cam", 0, 0, space="detector")


def test_pick_sky(engine):
    # Turned 180 deg about x: the sensor looks along -z, away from the ball.
    build(engine, attitude=(0.0, 1.0, 0.0, 0.0))
    engine.render("Cam")
    p = engine.pick("Cam", 5, 5)
    assert p["hit"] is False
    assert p["object"] == ""
    assert p["patch"] == -1
    assert p["declination_deg"] < -85.0
    assert np.all(engine.image("Cam", "scene_radiance") == 0.0)


def test_orientation_row0_is_up(engine):
    # Ball 0.5 deg toward body +y (up) and 0.7 deg toward +x, which pictures
    # show on the LEFT (as seen looking along +z with +y up; eoir.h): it must
    # land in the top-left quarter of the images (row 0 at the top).
    build(engine, horizontal_fov_deg=4.0, vertical_fov_deg=3.0)
    engine.set("Ball", "dimensions_m", [20.0])
    off = 10e3 * np.array([math.tan(math.radians(0.7)), math.tan(math.radians(0.5)), 1.0])
    engine.set_state("Ball", HOST + off)
    engine.render("Cam")
    rad = engine.image("Cam", "scene_radiance")
    rows, cols = np.nonzero(rad > 0)
    assert rows.size > 0
    assert rows.mean() < 4 * H / 2 and cols.mean() < 4 * W / 2
    p = engine.pick("Cam", int(round(cols.mean())), int(round(rows.mean())))
    assert p["object"] == "Ball"
    mean = engine.image("Cam", "sensor_mean")
    r, c = np.unravel_index(np.argmax(mean), mean.shape)
    assert r < H / 2 and c < W / 2


def test_no_frame_yet(engine):
    build(engine)
    with pytest.raises(eoir.NoStateError):
        engine.image("Cam", "sensor_electrons")
    with pytest.raises(eoir.NoStateError):
        engine.pick("Cam", 0, 0)
    with pytest.raises(ValueError):
        engine.image("Cam", "thermal")
    with pytest.raises(eoir.UnknownNameError):
        engine.render("NoSuchSensor")


def test_save_render_load_render_is_identical(engine, tmp_path):
    # Noise on, no saturation: the electrons differ from frame to frame, and
    # the generator's state travels in the .scd.
    build(engine, saturation_enabled=False, integration_time_ms=0.01, noise_enabled=True)
    engine.render("Cam")
    first = engine.image("Cam", "sensor_electrons")
    mean = engine.image("Cam", "sensor_mean")
    assert np.std(first - mean) > 0.0
    path = tmp_path / "frame.scd"
    engine.save(path)
    engine.render("Cam")
    after_save = engine.image("Cam", "sensor_electrons")
    assert not np.array_equal(after_save, first), "the noise generator did not advance"
    engine.load(path)
    engine.render("Cam")
    np.testing.assert_array_equal(engine.image("Cam", "sensor_electrons"), after_save)
    np.testing.assert_array_equal(engine.image("Cam", "sensor_mean"), mean)
    # A fresh engine (other seed, other thread count) loading the file too.
    with eoir.Engine(threads=2, seed=12345) as other:
        other.load(path)
        other.render("Cam")
        np.testing.assert_array_equal(other.image("Cam", "sensor_electrons"), after_save)


def test_plugin_table_has_image_entries():
    import ctypes
    from eoir import _lib
    api = ctypes.c_void_p()
    assert _lib.lib.eoir_plugin_entry(1, None, ctypes.byref(api)) == 0
    table = ctypes.cast(api, ctypes.POINTER(_lib.eoir_api_v1)).contents
    assert table.struct_size >= ctypes.sizeof(_lib.eoir_api_v1)
    assert table.abi_minor >= 1
    for name in ("render", "image_info_get", "image_get", "image_get_bytes", "pick_get"):
        assert getattr(table, name), name
