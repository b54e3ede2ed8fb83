"""Spec 7.6 (Table 3): the static metrics of the Valid_Sens_StaticMetrics
sensor reproduced through the Python bindings within 0.1 %."""

import math

import numpy as np
import pytest

import eoir

from conftest import TABLE3_PARAMETERS

SPATIAL = "EOIR Sensor Spatial Performance"
SPECTRAL = "EOIR Sensor Spectral Performance"
RADIOMETRIC = "EOIR Radiometric Performance"
OPTICS = "EOIR Sensor Optics"

# (group, element, expected, unit of expected)
TABLE3 = [
    (SPATIAL, "Number of Horizontal Pixels", 128, "count"),
    (SPATIAL, "Number of Vertical Pixels", 128, "count"),
    (SPATIAL, "Horizontal FOV", 0.5, "deg"),
    (SPATIAL, "Vertical FOV", 0.5, "deg"),
    (SPATIAL, "FOV Solid Angle", 7.6154e-5, "sr"),
    (SPATIAL, "Horizontal IFOV", 6.818e-2, "mrad"),
    (SPATIAL, "Vertical IFOV", 6.818e-2, "mrad"),
    (SPATIAL, "IFOV Solid Angle", 4.648e-9, "sr"),
    (SPATIAL, "Effective Horizontal FOV", 0.5081, "deg"),
    (SPATIAL, "Effective Vertical FOV", 0.5081, "deg"),
    (SPATIAL, "Effective FOV Solid Angle", 7.865e-5, "sr"),
    (SPATIAL, "Effective Horizontal IFOV", 6.928e-2, "mrad"),
    (SPATIAL, "Effective Vertical IFOV", 6.928e-2, "mrad"),
    (SPATIAL, "Effective IFOV Solid Angle", 4.80e-9, "sr"),
    (SPECTRAL, "Low Band Edge Wavelength", 1.0, "um"),
    (SPECTRAL, "High Band Edge Wavelength", 4.0, "um"),
    (RADIOMETRIC, "Integration Time", 10.0, "ms"),
    (RADIOMETRIC, "Peak Irradiance Responsivity", 5.295e19, None),
    (RADIOMETRIC, "Dark NEI", 1.0e-18, "W/cm^2"),
    (RADIOMETRIC, "SEI", 1.0e-15, "W/cm^2"),
    (RADIOMETRIC, "Peak Radiance Responsivity", 2.542e11, None),
    (RADIOMETRIC, "Dark NER", 2.083e-10, None),
    (RADIOMETRIC, "SER", 2.083e-7, None),
    (OPTICS, "Effective Focal Length", 147.0, "cm"),
    (OPTICS, "F-number", 3.5, ""),
    (OPTICS, "Diffraction Wavelength", 2.5, "um"),
    (OPTICS, "Airy Disk Diameter", 1.452e-2, "mrad"),
    (OPTICS, "Rayleigh Resolution", 7.262e-3, "mrad"),
    (OPTICS, "Sparrow Resolution", 5.952e-3, "mrad"),
]

# Unit conversions for the case the library reports another (equivalent) unit.
_TO_SI = {
    "rad": 1.0, "mrad": 1e-3, "urad": 1e-6, "deg": math.pi / 180.0,
    "um": 1e-6, "nm": 1e-9, "mm": 1e-3, "cm": 1e-2, "m": 1.0,
    "s": 1.0, "ms": 1e-3, "us": 1e-6,
}


def _in_unit(value, unit, wanted):
    if wanted is None or unit == wanted or wanted in ("count", ""):
        return value
    if unit in _TO_SI and wanted in _TO_SI:
        return value * _TO_SI[unit] / _TO_SI[wanted]
    return value


@pytest.mark.parametrize("group,element,expected,unit", TABLE3,
                         ids=[f"{g}:{e}" for g, e, _, _ in TABLE3])
def test_table3_value(table3, group, element, expected, unit):
    value = table3.provider(group, element, "Sensor")
    units = {e["name"]: e["unit"] for e in eoir.provider_elements(group)}
    got = _in_unit(value, units[element], unit)
    if isinstance(expected, int):
        assert isinstance(value, int), f"{element} should be an integer, got {value!r}"
        assert value == expected
    else:
        assert isinstance(value, float)
        assert got == pytest.approx(expected, rel=1e-3), \
            f"{element}: {value} {units[element]} (expected {expected} {unit})"


def test_ensquared_energy(table3):
    ee = table3.provider(OPTICS, "Ensquared Energy", "Sensor")
    assert ee == pytest.approx(0.9683, abs=5e-4)


def test_entrance_pupil_and_spectral_intervals(table3):
    d = table3.provider(OPTICS, "Entrance Pupil Diameter", "Sensor")
    unit = {e["name"]: e["unit"] for e in eoir.provider_elements(OPTICS)}["Entrance Pupil Diameter"]
    assert _in_unit(d, unit, "cm") == pytest.approx(147.0 / 3.5, rel=1e-9)
    n = table3.provider(SPECTRAL, "Number of Spectral Intervals", "Sensor")
    assert isinstance(n, int) and n >= 1


def test_parameters_read_back(table3):
    for name, value in TABLE3_PARAMETERS.items():
        got = table3.get("Sensor", name)
        if isinstance(value, list):
            np.testing.assert_array_equal(got, np.asarray(value))
        elif isinstance(value, str):
            assert got == value
        else:
            assert got == value, name


def _diffraction_otf(xi, cutoff):
    r = np.clip(xi / cutoff, 0.0, 1.0)
    return np.where(xi < cutoff, 2 / np.pi * (np.arccos(r) - r * np.sqrt(1 - r * r)), 0.0)


def test_diffraction_otf_curve(table3):
    x, y = table3.provider(OPTICS, "Diffraction OTF", "Sensor")
    assert isinstance(x, np.ndarray) and isinstance(y, np.ndarray)
    assert x.dtype == np.float64 and y.dtype == np.float64
    assert x.shape == y.shape and x.size >= 2
    assert np.all(np.diff(x) > 0), "frequencies must increase"
    assert x[0] == pytest.approx(0.0, abs=1e-12)
    assert y[0] == pytest.approx(1.0, abs=1e-12)
    assert np.all(np.diff(y) <= 1e-12), "diffraction OTF must not increase"
    # Object-space cutoff D/lambda in cycles/mrad (eq. 34 with xi_cutoff = 1/(lambda F#)).
    cutoff = (147.0 / 3.5 * 1e-2) / 2.5e-6 * 1e-3
    beyond = x >= cutoff * (1 - 1e-9)
    assert np.all(np.abs(y[beyond]) <= 1e-12), "OTF must be 0 at and beyond the cutoff"
    np.testing.assert_allclose(y, _diffraction_otf(x, cutoff), atol=1e-6)


def test_every_curve_is_numpy(table3):
    for info in eoir.provider_elements(OPTICS):
        if info["type"] != "curve":
            continue
        x, y = table3.provider(OPTICS, info["name"], "Sensor")
        assert x.shape == y.shape and x.size >= 2, info["name"]
        assert np.all(np.isfinite(x)) and np.all(np.isfinite(y)), info["name"]
        assert y[0] == pytest.approx(1.0, abs=1e-9), info["name"]


def test_report_matches_provider(table3):
    report = table3.report(SPATIAL, "Sensor")
    assert report["Number of Horizontal Pixels"] == (128, report["Number of Horizontal Pixels"][1])
    assert report["FOV Solid Angle"][0] == pytest.approx(7.6154e-5, rel=1e-3)
    assert report["FOV Solid Angle"][1] == "sr"
    optics = table3.report(OPTICS, "Sensor")
    x, y = optics["Diffraction OTF"][0]
    assert isinstance(x, np.ndarray)
