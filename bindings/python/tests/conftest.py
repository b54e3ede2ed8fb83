"""Shared fixtures: an engine holding the Table 3 sensor of spec 7.6."""

import numpy as np
import pytest

import eoir

# The sensor of spec 7.6 (scenario Valid_Sens_StaticMetrics).
TABLE3_PARAMETERS = {
    "horizontal_pixels": 128,
    "vertical_pixels": 128,
    "horizontal_fov_deg": 0.5,
    "vertical_fov_deg": 0.5,
    "band_low_um": 1.0,
    "band_high_um": 4.0,
    "f_number": 3.5,
    "focal_length_cm": 147.0,
    "defocus_mm": 0.0,
    "image_quality": "diffraction_limited",
    "diffraction_wavelength_um": 2.5,
    "integration_time_ms": 10.0,
    "sensitivity_quantity": "irradiance",
    "sensitivity_pairs": [10.0, 1e-18],
    "saturation_quantity": "irradiance",
    "saturation_pairs": [10.0, 1e-15],
    "jitter_mrad": 0.0,
}

STATIC_GROUPS = (
    "EOIR Sensor Spatial Performance",
    "EOIR Sensor Spectral Performance",
    "EOIR Radiometric Performance",
    "EOIR Sensor Optics",
)


def configure_table3(engine, sensor="Sensor"):
    for name, value in TABLE3_PARAMETERS.items():
        engine.set(sensor, name, value)


def build_table3(engine, satellite="Sat", sensor="Sensor"):
    engine.set_time("2010-08-25T18:00:00Z")
    engine.add_object("satellite", satellite)
    engine.set_state(satellite, position=(7000e3, 0.0, 0.0), velocity=(0.0, 7546.0, 0.0))
    engine.add_sensor(sensor, satellite)
    configure_table3(engine, sensor)
    return engine


@pytest.fixture
def engine():
    with eoir.Engine(threads=1, seed=1) as e:
        yield e


@pytest.fixture
def table3(engine):
    return build_table3(engine)


def assert_same_value(a, b, what=""):
    """Exact equality for provider values (scalars or (x, y) curves)."""
    if isinstance(a, tuple):
        assert isinstance(b, tuple), what
        assert len(a) == len(b), what
        for u, v in zip(a, b):
            np.testing.assert_array_equal(u, v, err_msg=what)
    else:
        assert type(a) is type(b), what
        assert a == b or (a != a and b != b), f"{what}: {a!r} != {b!r}"
