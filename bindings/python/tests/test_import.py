"""Import, version, constants and the static catalogue of data providers."""

import os
import re
from pathlib import Path

import pytest

import eoir
from eoir import _lib


def test_version_major_is_one():
    assert eoir.version() // 10000 == 1
    assert eoir.version_string().split(".")[0] == "1"
    major, minor, patch = (int(p) for p in eoir.version_string().split(".")[:3])
    assert eoir.version() == major * 10000 + minor * 100 + patch
    assert eoir.__version__ == f"{major}.{minor}.{patch}"


def test_library_location():
    assert os.path.exists(eoir.library_path) or "/" not in eoir.library_path
    if os.environ.get("EOIR_LIBRARY"):
        assert eoir.library_path == os.environ["EOIR_LIBRARY"]


def test_every_header_function_is_declared():
    for name, (restype, argtypes) in _lib._SIGNATURES.items():
        f = getattr(_lib.lib, name)
        assert f.restype is restype
        assert list(f.argtypes) == list(argtypes)
    header = Path(__file__).resolve().parents[3] / "capi" / "include" / "eoir" / "eoir.h"
    if header.exists():
        declared = set(re.findall(r"EOIR_API\s+[\w\s\*]+?\b(eoir_\w+)\s*\(", header.read_text()))
        assert declared == set(_lib._SIGNATURES)


def test_status_names():
    assert eoir.status_name(0) == "EOIR_OK"
    assert eoir.status_name(-102) == "EOIR_ERR_OUT_OF_RANGE"
    assert eoir.status_name(-301) == "EOIR_ERR_CORRUPT_FILE"
    assert eoir.errors.error_class(-102) is eoir.OutOfRangeError
    assert eoir.errors.error_class(-199) is eoir.ArgumentError
    assert issubclass(eoir.CorruptFileError, eoir.FileError)
    assert issubclass(eoir.LimitExceededError, eoir.EoirError)


def test_limits():
    assert eoir.MAX_SENSORS == 6
    assert eoir.MAX_SATELLITES == 16


def test_provider_groups_and_elements():
    groups = eoir.provider_groups()
    for g in ("EOIR Sensor Spatial Performance", "EOIR Sensor Spectral Performance",
              "EOIR Radiometric Performance", "EOIR Sensor Optics"):
        assert g in groups
    optics = {e["name"]: e for e in eoir.provider_elements("EOIR Sensor Optics")}
    for name in ("Effective Focal Length", "F-number", "Entrance Pupil Diameter",
                 "Diffraction Wavelength", "Airy Disk Diameter", "Rayleigh Resolution",
                 "Sparrow Resolution", "Ensquared Energy"):
        assert optics[name]["type"] in ("number", "integer"), name
    for name in ("Diffraction OTF", "Optics OTF", "Jitter OTF",
                 "Horizontal Detector Footprint MTF", "Vertical Detector Footprint MTF"):
        assert optics[name]["type"] == "curve", name
        assert optics[name]["x_unit"] == "cycles/mrad"
    spatial = {e["name"]: e for e in eoir.provider_elements("EOIR Sensor Spatial Performance")}
    assert spatial["Number of Horizontal Pixels"]["type"] == "integer"


def test_engine_lifetime():
    e = eoir.Engine()
    assert not e.closed
    assert e.objects()[0] == ("Sun", "central_body")
    e.close()
    e.close()
    assert e.closed
    with pytest.raises(ValueError):
        e.objects()
    with eoir.Engine(threads=2, seed=42) as e2:
        assert ("Sun", "central_body") in e2.objects()
