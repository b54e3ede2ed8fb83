"""Targets through the bindings (C ABI 1.2): Engine.snr (the spec 7.8 SNR
access constraint), Engine.truth (per-frame truth) and Engine.report_series
(a data-provider group over time with states pushed by the host)."""

import math

import numpy as np
import pytest

import eoir

T0 = "2010-08-25T18:00:00Z"
GROUP = "EOIR Sensor-to-Target Metrics"
HOST = np.array([7000e3, 0.0, 0.0])
RANGE_M = 10e3
RADIUS_M = 0.01
TEMPERATURE_K = 300.0
NEI_DARK = 1e-18  # W/cm^2 at the 10 ms integration time of the pair
N = 64
FOV_DEG = 1.0


def planck_um(wl_um, t_k):
    """Blackbody spectral radiance, W/(cm^2 sr um)."""
    h, c, k = 6.62607015e-34, 2.99792458e8, 1.380649e-23
    wl = np.asarray(wl_um, dtype=np.float64) * 1e-6
    l_m = 2 * h * c ** 2 / wl ** 5 / np.expm1(h * c / (wl * k * t_k))  # W/(m^2 sr m)
    return l_m * 1e-4 * 1e-6


def band_radiance(lo_um, hi_um, t_k):
    wl = np.linspace(lo_um, hi_um, 20001)
    y = planck_um(wl, t_k)
    return float(np.sum((y[1:] + y[:-1]) / 2 * np.diff(wl)))


def build(engine, offset=(0.0, 0.0)):
    """Two satellites in space (no Earth): the sensor on Host looks along
    J2000 +z (identity attitude); Tgt, a 1 cm black sphere at 300 K, is
    RANGE_M along +z, displaced by offset (metres along J2000 x, y)."""
    engine.set_time(T0)
    engine.add_object("satellite", "Host")
    engine.add_object("satellite", "Tgt")
    engine.set_state("Host", HOST)
    engine.set_state("Tgt", HOST + [offset[0], offset[1], RANGE_M])
    for name, value in dict(shape="sphere", dimensions_m=[RADIUS_M], material="gray_body", reflectance=0.0,
                            temperature_K=TEMPERATURE_K).items():
        engine.set("Tgt", name, value)
    engine.add_sensor("Cam", "Host")
    for name, value in dict(horizontal_pixels=N, vertical_pixels=N, horizontal_fov_deg=FOV_DEG,
                            vertical_fov_deg=FOV_DEG, band_low_um=8.0, band_high_um=12.0, spectral_intervals=50,
                            sensitivity_quantity="irradiance", sensitivity_pairs=[10.0, NEI_DARK],
                            integration_time_ms=10.0, saturation_enabled=False).items():
        engine.set("Cam", name, value)
    return engine


def analytic_irradiance(range_m=RANGE_M):
    """E = L_band(T) * pi r^2 / R^2 (a black sphere, projected area pi r^2)."""
    return band_radiance(8.0, 12.0, TEMPERATURE_K) * math.pi * RADIUS_M ** 2 / range_m ** 2


def test_snr_is_analytic_irradiance_over_nei_against_space(engine):
    build(engine)
    snr = engine.snr("Cam", "Tgt")
    e_tgt = engine.provider(GROUP, "Effective Target Irradiance", "Cam", "Tgt")
    nei = engine.provider(GROUP, "Total NEI", "Cam", "Tgt")
    assert nei == pytest.approx(NEI_DARK, rel=1e-12)  # no background photons against space
    assert engine.provider(GROUP, "Scene Photon NEI", "Cam", "Tgt") == 0.0
    assert engine.provider(GROUP, "Target Is Point Source", "Cam", "Tgt") is True
    assert e_tgt == pytest.approx(analytic_irradiance(), rel=5e-3)
    assert snr == pytest.approx(analytic_irradiance() / NEI_DARK, rel=5e-3)
    # The constraint and the provider agree exactly.
    assert snr == engine.provider(GROUP, "Signal to Noise Ratio", "Cam", "Tgt")


def test_snr_at_a_time_moves_objects_along_their_velocity(engine):
    build(engine)
    # The target recedes along +z at 100 m/s: in 100 s the range doubles.
    engine.set_state("Tgt", HOST + [0.0, 0.0, RANGE_M], velocity=(0.0, 0.0, 100.0))
    snr0 = engine.snr("Cam", "Tgt")
    snr1 = engine.snr("Cam", "Tgt", time="2010-08-25T18:01:40Z")
    assert engine.time_iso().startswith("2010-08-25T18:01:40")
    assert engine.provider(GROUP, "Range to Target", "Cam", "Tgt") == pytest.approx(2 * RANGE_M / 1e3, rel=1e-9)
    assert snr1 == pytest.approx(snr0 / 4, rel=1e-6)


def test_snr_is_zero_outside_the_field(engine):
    build(engine, offset=(RANGE_M, 0.0))  # 45 deg off the boresight
    assert engine.snr("Cam", "Tgt") == 0.0


def test_truth_lists_the_target_at_the_expected_pixel(engine):
    # 20 m along +x and 10 m along +y at 10 km: columns grow toward body -x
    # and rows toward body -y (eoir.h), samples uniform in tan(angle).
    dx, dy = 20.0, 10.0
    build(engine, offset=(dx, dy))
    engine.render("Cam")
    truth = engine.truth("Cam")
    assert [t["object"] for t in truth] == ["Tgt"]
    t = truth[0]
    pitch = 2 * math.tan(math.radians(FOV_DEG / 2)) / N  # tan(angle) per pixel
    centre = (N - 1) / 2
    assert t["pixel_x"] == pytest.approx(centre - dx / RANGE_M / pitch, abs=0.02)
    assert t["pixel_y"] == pytest.approx(centre - dy / RANGE_M / pitch, abs=0.02)
    assert t["range_m"] == pytest.approx(math.sqrt(RANGE_M ** 2 + dx ** 2 + dy ** 2), rel=1e-9)
    assert t["point_source"] is True
    assert t["visible"] is True
    assert t["effective_irradiance"] == pytest.approx(analytic_irradiance(t["range_m"]), rel=5e-3)
    assert t["effective_radiance"] == 0.0
    assert t["snr"] == pytest.approx(engine.snr("Cam", "Tgt"), rel=1e-9)


def test_truth_is_empty_when_nothing_is_in_the_field(engine):
    build(engine, offset=(RANGE_M, 0.0))
    engine.render("Cam")
    assert engine.truth("Cam") == []


def test_truth_needs_a_frame(engine):
    build(engine)
    with pytest.raises(eoir.EoirError):
        engine.truth("Cam")


def test_report_series_pushes_states_at_each_time(engine):
    build(engine)
    times = ["2010-08-25T18:00:00Z", "2010-08-25T18:00:10Z", "2010-08-25T18:00:20Z"]
    pushed = []

    def push(eng, time):
        k = times.index(time)
        pushed.append(time)
        # The host's own motion: 1 km further at each step, no velocity.
        eng.set_state("Tgt", HOST + [0.0, 0.0, RANGE_M + 1e3 * k])

    rows = engine.report_series(GROUP, "Cam", "Tgt", times, push=push)
    assert pushed == times
    assert [r["time"][:19] for r in rows] == [t[:19] for t in times]
    names = [e["name"] for e in eoir.provider_elements(GROUP)]
    for k, row in enumerate(rows):
        assert set(names) <= set(row)
        assert row["Range to Target"] == pytest.approx(10.0 + k, rel=1e-9)
        assert row["Signal to Noise Ratio"] == pytest.approx(analytic_irradiance(RANGE_M + 1e3 * k) / NEI_DARK,
                                                             rel=5e-3)
        assert row["Target Is Point Source"] is True


def test_report_series_without_push(engine):
    build(engine)
    rows = engine.report_series(GROUP, "Cam", "Tgt", [T0])
    assert len(rows) == 1 and rows[0]["Range to Target"] == pytest.approx(10.0)


def test_unknown_target_sensor_and_target_equal_to_parent(engine):
    build(engine)
    with pytest.raises(eoir.UnknownNameError, match="Nobody"):
        engine.snr("Cam", "Nobody")
    with pytest.raises(eoir.UnknownNameError, match="Nope"):
        engine.snr("Nope", "Tgt")
    with pytest.raises(eoir.NotAllowedError, match="Host"):
        engine.snr("Cam", "Host")
    with pytest.raises(eoir.NotAllowedError):
        engine.report_series(GROUP, "Cam", "Host", [T0])
    with pytest.raises(eoir.UnknownNameError):
        engine.truth("Nope")


def test_function_table_has_the_target_entries():
    import ctypes
    from eoir import _lib
    api = ctypes.c_void_p()
    assert _lib.lib.eoir_plugin_entry(1, None, ctypes.byref(api)) == 0
    table = ctypes.cast(api, ctypes.POINTER(_lib.eoir_api_v1)).contents
    assert table.struct_size >= ctypes.sizeof(_lib.eoir_api_v1)
    assert table.abi_minor >= 2
    assert ctypes.cast(table.snr_constraint, ctypes.c_void_p).value is not None
    assert ctypes.cast(table.truth_get, ctypes.c_void_p).value is not None
