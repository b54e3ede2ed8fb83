"""Python bindings of the EOIR engine (ctypes over the C ABI of eoir.h).

    import eoir
    with eoir.Engine(threads=0, seed=1) as engine:
        engine.add_object("satellite", "Sat")
        engine.add_sensor("Sensor", "Sat")
        engine.set("Sensor", "f_number", 3.5)
        print(engine.provider("EOIR Sensor Optics", "Ensquared Energy", "Sensor"))

    with eoir.Scenario.load("scenarios/demo/default.json") as sc:   # the CLI's scenario code
        sc.set_time(sc.times()[-1]); sc.engine.render("WideLWIR")
        sc.write_fits("WideLWIR", "sensor_electrons", "frame.fits")  # astropy, with WCS

eoir.sweep runs parameter grids serially or on Dask. Kinds, frames, time
scales and image kinds have named constants (eoir.Kind.SATELLITE,
eoir.FRAME_J2000...; eoir.constants); Engine.point_at and Engine.track point a
sensor at an object.

The library is located through the environment variable EOIR_LIBRARY, then
build/lib above this package, then ctypes.util.find_library("eoir").
"""

import sys as _sys

try:
    import numpy as _numpy  # noqa: F401  (every image and series is a numpy array)
except ImportError as _missing:
    raise ImportError(
        f"eoir needs numpy, which this Python cannot import: {_sys.executable} "
        f"(Python {_sys.version.split()[0]}; {_missing}). "
        "What works: /usr/bin/python3 (Debian's, with python3-numpy), or a virtual environment "
        "that sees the system's packages: python3 -m venv --system-site-packages ENV, "
        f"or numpy installed into this one: {_sys.executable} -m pip install numpy") from _missing

from . import errors
from ._lib import library_path, version_number  # loads the library (ImportError on failure)
from ._version import __version__
from .errors import (AbiMismatchError, AlreadyExistsError, ArgumentError,
                     BufferTooSmallError, CancelledError, CorruptFileError, EoirError,
                     FileError, FileIOError, FileVersionError, HostRequestError, InternalError,
                     LimitExceededError, NoStateError, NotAllowedError,
                     NullArgumentError, OutOfRangeError, PluginError,
                     StructSizeError, TypeMismatchError, UniverseError,
                     UnknownNameError)
from .constants import *  # noqa: F401,F403  Kind, Frame, TimeScale, ImageKind and their KIND_..., FRAME_... members
from .constants import __all__ as _constants
from .engine import (FRAMES, IMAGE_KINDS, KINDS, PICK_TERMS, TIME_SCALES, TRUTH_FIELDS, TYPES, Engine, Time,
                     heading_pitch_roll_quaternion,
                     last_error,
                     provider_elements, provider_groups, status_name,
                     time_from_iso, time_to_iso, version, version_string)
from .scenario import Scenario, tle_state
from ._lib import (EOIR_MAX_MISSILE_STAGES as MAX_MISSILE_STAGES,
                   EOIR_MAX_MISSILES as MAX_MISSILES,
                   EOIR_MAX_NAME_LENGTH as MAX_NAME_LENGTH,
                   EOIR_MAX_REFERENCE_PAIRS as MAX_REFERENCE_PAIRS,
                   EOIR_MAX_SATELLITES as MAX_SATELLITES,
                   EOIR_MAX_SENSORS as MAX_SENSORS,
                   EOIR_MAX_SITES as MAX_SITES,
                   EOIR_MAX_VEHICLES as MAX_VEHICLES)

# __version__ (eoir/_version.py) is the package's; version_string() the loaded
# library's: the same number for the library of the same build.

__all__ = [
    "Engine", "Scenario", "tle_state", "version", "version_string", "status_name", "last_error",
    "provider_groups", "provider_elements", "time_from_iso", "time_to_iso",
    "heading_pitch_roll_quaternion",
    "KINDS", "FRAMES", "TIME_SCALES", "TYPES", "IMAGE_KINDS", "PICK_TERMS", "TRUTH_FIELDS", "Time",
    "MAX_SATELLITES", "MAX_VEHICLES", "MAX_MISSILES", "MAX_MISSILE_STAGES",
    "MAX_SENSORS", "MAX_SITES", "MAX_REFERENCE_PAIRS", "MAX_NAME_LENGTH",
    "library_path", "errors",
    "EoirError", "ArgumentError", "NullArgumentError", "StructSizeError",
    "OutOfRangeError", "UnknownNameError", "TypeMismatchError",
    "BufferTooSmallError", "UniverseError", "LimitExceededError",
    "AlreadyExistsError", "NotAllowedError", "NoStateError", "FileError",
    "FileIOError", "CorruptFileError", "FileVersionError", "PluginError",
    "AbiMismatchError", "HostRequestError", "CancelledError", "InternalError",
    "__version__",
] + list(_constants)
