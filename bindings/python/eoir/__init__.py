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

eoir.sweep runs parameter grids serially or on Dask.

The library is located through the environment variable EOIR_LIBRARY, then
build/lib above this package, then ctypes.util.find_library("eoir").
"""

from . import errors
from ._lib import library_path, version_number  # loads the library (ImportError on failure)
from .errors import (AbiMismatchError, AlreadyExistsError, ArgumentError,
                     BufferTooSmallError, CancelledError, CorruptFileError, EoirError,
                     FileError, FileIOError, FileVersionError, HostRequestError, InternalError,
                     LimitExceededError, NoStateError, NotAllowedError,
                     NullArgumentError, OutOfRangeError, PluginError,
                     StructSizeError, TypeMismatchError, UniverseError,
                     UnknownNameError)
from .engine import (FRAMES, IMAGE_KINDS, KINDS, PICK_TERMS, TIME_SCALES, TYPES, Engine, heading_pitch_roll_quaternion,
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

__version__ = "{}.{}.{}".format(version_number // 10000, version_number // 100 % 100,
                                version_number % 100)

__all__ = [
    "Engine", "Scenario", "tle_state", "version", "version_string", "status_name", "last_error",
    "provider_groups", "provider_elements", "time_from_iso", "time_to_iso",
    "heading_pitch_roll_quaternion",
    "KINDS", "FRAMES", "TIME_SCALES", "TYPES", "IMAGE_KINDS", "PICK_TERMS",
    "MAX_SATELLITES", "MAX_VEHICLES", "MAX_MISSILES", "MAX_MISSILE_STAGES",
    "MAX_SENSORS", "MAX_SITES", "MAX_REFERENCE_PAIRS", "MAX_NAME_LENGTH",
    "library_path", "errors",
    "EoirError", "ArgumentError", "NullArgumentError", "StructSizeError",
    "OutOfRangeError", "UnknownNameError", "TypeMismatchError",
    "BufferTooSmallError", "UniverseError", "LimitExceededError",
    "AlreadyExistsError", "NotAllowedError", "NoStateError", "FileError",
    "FileIOError", "CorruptFileError", "FileVersionError", "PluginError",
    "AbiMismatchError", "HostRequestError", "CancelledError", "InternalError",
]
