"""ctypes declarations of every function, struct and constant of eoir.h.

The shared library is found, in order, at:

1. the path in the environment variable ``EOIR_LIBRARY``;
2. ``build/lib/libeoir.so.1`` (or ``libeoir.so``) in the directories above the
   package (``bindings/``, then the repository root);
3. ``ctypes.util.find_library("eoir")``.

Import fails with a clear ImportError if no library is found or if its major
version is not 1.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import operator
import os
from ctypes import (CFUNCTYPE, POINTER, Structure, c_char_p, c_double, c_int32,
                    c_int64, c_size_t, c_uint32, c_uint64, c_void_p)
from pathlib import Path

from . import errors

# ----------------------------------------------------------------- constants
EOIR_VERSION_MAJOR = 1  # the ABI major these bindings are written against

EOIR_OK = 0
EOIR_ERR_NULL_ARGUMENT = -100
EOIR_ERR_STRUCT_SIZE = -101
EOIR_ERR_OUT_OF_RANGE = -102
EOIR_ERR_UNKNOWN_NAME = -103
EOIR_ERR_TYPE_MISMATCH = -104
EOIR_ERR_BUFFER_TOO_SMALL = -105
EOIR_ERR_LIMIT_EXCEEDED = -200
EOIR_ERR_ALREADY_EXISTS = -201
EOIR_ERR_NOT_ALLOWED = -202
EOIR_ERR_NO_STATE = -203
EOIR_ERR_IO = -300
EOIR_ERR_CORRUPT_FILE = -301
EOIR_ERR_FILE_VERSION = -302
EOIR_ERR_ABI_MISMATCH = -400
EOIR_ERR_CANCELLED = -500
EOIR_PROPERTY_FIDELITY = 1
EOIR_TRUTH_OBJECT = 0
EOIR_TRUTH_STAR = 1
EOIR_ERR_INTERNAL = -900

EOIR_MAX_SATELLITES = 16
EOIR_MAX_VEHICLES = 6
EOIR_MAX_SITES = 16
EOIR_MAX_MISSILES = 6
EOIR_MAX_MISSILE_STAGES = 18
EOIR_MAX_SENSORS = 6
EOIR_MAX_REFERENCE_PAIRS = 8
EOIR_MAX_NAME_LENGTH = 63

EOIR_TIME_UTC = 0
EOIR_TIME_TAI = 1
EOIR_TIME_TT = 2
EOIR_TIME_TDB = 3

EOIR_KIND_CENTRAL_BODY = 1
EOIR_KIND_STAR_FIELD = 2
EOIR_KIND_SATELLITE = 3
EOIR_KIND_AIRCRAFT = 4
EOIR_KIND_GROUND_VEHICLE = 5
EOIR_KIND_MISSILE = 6
EOIR_KIND_SENSOR = 7
EOIR_KIND_SITE = 8  # 1.5

EOIR_FRAME_J2000 = 0
EOIR_FRAME_EARTH_FIXED = 1
EOIR_FRAME_GEODETIC = 2
EOIR_FRAME_GEODETIC_NED = 3

EOIR_TYPE_NUMBER = 1
EOIR_TYPE_INTEGER = 2
EOIR_TYPE_BOOL = 3
EOIR_TYPE_STRING = 4
EOIR_TYPE_ARRAY = 5
EOIR_TYPE_CURVE = 6

EOIR_IMAGE_SCENE_RADIANCE = 1
EOIR_IMAGE_SCENE_DISPLAY = 2
EOIR_IMAGE_SENSOR_ELECTRONS = 3
EOIR_IMAGE_SENSOR_MEAN = 4
EOIR_IMAGE_SENSOR_DISPLAY = 5
EOIR_IMAGE_SENSOR_ADU = 6  # 1.7

# ------------------------------------------------------------------- structs
eoir_status = c_int32
eoir_engine = c_void_p


class eoir_engine_desc(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("threads", c_uint32),
                ("seed", c_uint64),
                ("data_dir", c_char_p)]  # appended in 1.3


class eoir_time(Structure):
    _fields_ = [("scale", c_int32),
                ("jd1", c_double),
                ("jd2", c_double)]


class eoir_state(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("frame", c_int32),
                ("position", c_double * 3),
                ("velocity", c_double * 3),
                ("attitude", c_double * 4),
                ("angular_velocity", c_double * 3)]  # appended in 1.3


class eoir_property_info(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("name", c_char_p),
                ("type", c_int32),
                ("unit", c_char_p),
                ("description", c_char_p),
                ("flags", c_uint32),  # appended in 1.3
                ("range_open", c_uint32),
                ("minimum", c_double),
                ("maximum", c_double),
                ("choices", c_char_p)]


class eoir_element_info(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("name", c_char_p),
                ("type", c_int32),
                ("unit", c_char_p),
                ("x_unit", c_char_p)]


class eoir_image_info(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("width", c_uint32),
                ("height", c_uint32),
                ("kind", c_int32),
                ("unit", c_char_p),
                ("time_jd_utc", c_double * 2),
                ("boresight_ra_deg", c_double),
                ("boresight_dec_deg", c_double),
                ("up_ra_deg", c_double),
                ("up_dec_deg", c_double),
                ("start_jd_utc", c_double * 2),  # appended in 1.6
                ("end_jd_utc", c_double * 2),
                ("astrometric_ra_deg", c_double),
                ("astrometric_dec_deg", c_double),
                ("astrometric_cd_deg", c_double * 4),
                ("observer_position_m", c_double * 3),
                ("observer_velocity_m_s", c_double * 3),
                ("observer_earth_fixed_m", c_double * 3),
                ("saturation_electrons", c_double),
                ("read_noise_electrons", c_double),
                ("gain_e_per_adu", c_double),  # appended in 1.7 (the detector stage)
                ("bias_adu", c_double),
                ("saturation_adu", c_double),
                ("adc_max_adu", c_double)]


class eoir_pick(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("hit", c_int32),
                ("object", ctypes.c_char * 64),
                ("patch", c_int32),
                ("range_m", c_double),
                ("has_geodetic", c_int32),
                ("latitude_deg", c_double),
                ("longitude_deg", c_double),
                ("right_ascension_deg", c_double),
                ("declination_deg", c_double),
                ("effective_radiance", c_double),
                ("temperature_K", c_double)]


class eoir_truth(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("object", ctypes.c_char * 64),
                ("pixel_x", c_double),
                ("pixel_y", c_double),
                ("range_m", c_double),
                ("point_source", c_int32),
                ("visible", c_int32),
                ("effective_irradiance", c_double),
                ("effective_radiance", c_double),
                ("snr", c_double),
                ("kind", c_int32),  # appended in 1.3
                ("reserved", c_int32),
                ("right_ascension_deg", c_double),
                ("declination_deg", c_double),
                ("v_mag", c_double),
                ("b_v_mag", c_double),
                ("start_pixel_x", c_double),
                ("start_pixel_y", c_double),
                ("end_pixel_x", c_double),
                ("end_pixel_y", c_double),
                ("topocentric", c_int32),  # appended in 1.5
                ("reserved_1_5", c_int32),
                ("azimuth_deg", c_double),
                ("elevation_deg", c_double),
                ("air_mass", c_double),
                ("astrometric_ra_deg", c_double),  # appended in 1.6
                ("astrometric_dec_deg", c_double),
                ("start_astrometric_ra_deg", c_double),
                ("start_astrometric_dec_deg", c_double),
                ("end_astrometric_ra_deg", c_double),
                ("end_astrometric_dec_deg", c_double),
                ("geometric_ra_deg", c_double),
                ("geometric_dec_deg", c_double)]


eoir_log_fn = CFUNCTYPE(None, c_void_p, c_int32, c_char_p)
eoir_progress_fn = CFUNCTYPE(c_int32, c_void_p, c_double, c_char_p)


class eoir_host_api(Structure):
    _fields_ = [("struct_size", c_uint32),
                ("user", c_void_p),
                ("log", eoir_log_fn),
                ("progress", eoir_progress_fn)]


_c_str = c_char_p
_c_strp = POINTER(c_char_p)
class eoir_limits(Structure):  # 1.7
    _fields_ = [("struct_size", c_uint32),
                ("max_satellites", c_uint32),
                ("max_vehicles", c_uint32),
                ("max_sites", c_uint32),
                ("max_missiles", c_uint32),
                ("max_sensors", c_uint32)]


_c_dblp = POINTER(c_double)
_c_sizep = POINTER(c_size_t)

# name -> (restype, argtypes); the order and signatures of eoir.h.
_SIGNATURES = {
    "eoir_version": (c_uint32, []),
    "eoir_version_string": (c_char_p, []),
    "eoir_last_error": (c_char_p, []),
    "eoir_status_name": (c_char_p, [eoir_status]),
    "eoir_engine_create": (eoir_status, [POINTER(eoir_engine_desc), POINTER(eoir_engine)]),
    "eoir_engine_destroy": (None, [eoir_engine]),
    "eoir_engine_set_limits": (eoir_status, [eoir_engine, POINTER(eoir_limits)]),
    "eoir_engine_get_limits": (eoir_status, [eoir_engine, POINTER(eoir_limits)]),
    "eoir_engine_set_time": (eoir_status, [eoir_engine, POINTER(eoir_time)]),
    "eoir_engine_get_time": (eoir_status, [eoir_engine, c_int32, POINTER(eoir_time)]),
    "eoir_time_from_iso": (eoir_status, [_c_str, POINTER(eoir_time)]),
    "eoir_time_to_iso": (eoir_status, [POINTER(eoir_time), ctypes.c_char_p, c_size_t]),
    "eoir_object_add": (eoir_status, [eoir_engine, c_int32, _c_str]),
    "eoir_sensor_add": (eoir_status, [eoir_engine, _c_str, _c_str]),
    "eoir_object_remove": (eoir_status, [eoir_engine, _c_str]),
    "eoir_object_count": (eoir_status, [eoir_engine, _c_sizep]),
    "eoir_object_at": (eoir_status, [eoir_engine, c_size_t, _c_strp, POINTER(c_int32)]),
    "eoir_object_set_state": (eoir_status, [eoir_engine, _c_str, POINTER(eoir_time), POINTER(eoir_state)]),
    "eoir_object_get_state": (eoir_status, [eoir_engine, _c_str, POINTER(eoir_state)]),
    "eoir_set_number": (eoir_status, [eoir_engine, _c_str, _c_str, c_double]),
    "eoir_set_integer": (eoir_status, [eoir_engine, _c_str, _c_str, c_int64]),
    "eoir_set_bool": (eoir_status, [eoir_engine, _c_str, _c_str, c_int32]),
    "eoir_set_string": (eoir_status, [eoir_engine, _c_str, _c_str, _c_str]),
    "eoir_set_array": (eoir_status, [eoir_engine, _c_str, _c_str, _c_dblp, c_size_t]),
    "eoir_get_number": (eoir_status, [eoir_engine, _c_str, _c_str, _c_dblp]),
    "eoir_get_integer": (eoir_status, [eoir_engine, _c_str, _c_str, POINTER(c_int64)]),
    "eoir_get_bool": (eoir_status, [eoir_engine, _c_str, _c_str, POINTER(c_int32)]),
    "eoir_get_string": (eoir_status, [eoir_engine, _c_str, _c_str, ctypes.c_char_p, c_size_t]),
    "eoir_get_array": (eoir_status, [eoir_engine, _c_str, _c_str, _c_dblp, c_size_t, _c_sizep]),
    "eoir_property_info_at": (eoir_status, [eoir_engine, _c_str, c_size_t, POINTER(eoir_property_info)]),
    "eoir_provider_group_at": (eoir_status, [c_size_t, _c_strp]),
    "eoir_provider_element_at": (eoir_status, [_c_str, c_size_t, POINTER(eoir_element_info)]),
    "eoir_provider_get": (eoir_status, [eoir_engine, _c_str, _c_str, _c_str, _c_str, _c_dblp]),
    "eoir_provider_get_curve": (eoir_status, [eoir_engine, _c_str, _c_str, _c_str, _c_str,
                                              _c_dblp, _c_dblp, c_size_t, _c_sizep]),
    "eoir_state_save": (eoir_status, [eoir_engine, _c_str]),
    "eoir_state_load": (eoir_status, [eoir_engine, _c_str]),
    "eoir_sensor_save": (eoir_status, [eoir_engine, _c_str, _c_str]),
    "eoir_sensor_load": (eoir_status, [eoir_engine, _c_str, _c_str]),
    "eoir_render": (eoir_status, [eoir_engine, _c_str]),
    "eoir_image_info_get": (eoir_status, [eoir_engine, _c_str, c_int32, POINTER(eoir_image_info)]),
    "eoir_image_get": (eoir_status, [eoir_engine, _c_str, c_int32, _c_dblp, c_size_t]),
    "eoir_image_get_bytes": (eoir_status, [eoir_engine, _c_str, c_int32, POINTER(ctypes.c_uint8), c_size_t]),
    "eoir_image_get_adu": (eoir_status, [eoir_engine, _c_str, POINTER(ctypes.c_uint32), c_size_t]),
    "eoir_pick_get": (eoir_status, [eoir_engine, _c_str, c_int32, c_uint32, c_uint32, POINTER(eoir_pick),
                                    _c_dblp, _c_dblp, c_size_t, _c_sizep]),
    "eoir_snr_constraint": (eoir_status, [eoir_engine, _c_str, _c_str, POINTER(eoir_time), _c_dblp]),
    "eoir_truth_count": (eoir_status, [eoir_engine, _c_str, _c_sizep]),
    "eoir_truth_get": (eoir_status, [eoir_engine, _c_str, c_size_t, POINTER(eoir_truth)]),
    "eoir_provider_series": (eoir_status, [eoir_engine, _c_str, _c_str, _c_str, _c_str, POINTER(eoir_time),
                                           c_size_t, _c_dblp]),
    "eoir_material_load": (eoir_status, [eoir_engine, _c_str]),
    "eoir_spectrum_add": (eoir_status, [eoir_engine, _c_str, _c_dblp, _c_dblp, c_size_t]),
    "eoir_target_spectrum_get": (eoir_status, [eoir_engine, _c_str, _c_str, _c_dblp, _c_dblp, c_size_t, _c_sizep]),
    "eoir_frame_fidelity_get": (eoir_status, [eoir_engine, _c_str, c_char_p, c_size_t, _c_sizep]),
    "eoir_sensor_point_azel": (eoir_status, [eoir_engine, _c_str, c_double, c_double]),
    "eoir_pick_term_get": (eoir_status, [eoir_engine, _c_str, c_int32, c_uint32, c_uint32, c_int32,
                                         POINTER(c_double), c_size_t, POINTER(c_size_t)]),
    "eoir_sensor_point_at": (eoir_status, [eoir_engine, _c_str, _c_str]),
    "eoir_plugin_entry": (eoir_status, [c_uint32, POINTER(eoir_host_api), POINTER(c_void_p)]),
}


def _fn(name):
    restype, argtypes = _SIGNATURES[name]
    return CFUNCTYPE(restype, *argtypes)


class eoir_api_v1(Structure):
    """The append-only function table of ABI major 1 (eoir_plugin_entry)."""
    _fields_ = [("struct_size", c_uint32),
                ("abi_major", c_uint32),
                ("abi_minor", c_uint32),
                ("version", _fn("eoir_version")),
                ("last_error", _fn("eoir_last_error")),
                ("status_name", _fn("eoir_status_name")),
                ("engine_create", _fn("eoir_engine_create")),
                ("engine_destroy", _fn("eoir_engine_destroy")),
                ("engine_set_time", _fn("eoir_engine_set_time")),
                ("engine_get_time", _fn("eoir_engine_get_time")),
                ("time_from_iso", _fn("eoir_time_from_iso")),
                ("time_to_iso", _fn("eoir_time_to_iso")),
                ("object_add", _fn("eoir_object_add")),
                ("sensor_add", _fn("eoir_sensor_add")),
                ("object_remove", _fn("eoir_object_remove")),
                ("object_count", _fn("eoir_object_count")),
                ("object_at", _fn("eoir_object_at")),
                ("object_set_state", _fn("eoir_object_set_state")),
                ("object_get_state", _fn("eoir_object_get_state")),
                ("set_number", _fn("eoir_set_number")),
                ("set_integer", _fn("eoir_set_integer")),
                ("set_bool", _fn("eoir_set_bool")),
                ("set_string", _fn("eoir_set_string")),
                ("set_array", _fn("eoir_set_array")),
                ("get_number", _fn("eoir_get_number")),
                ("get_integer", _fn("eoir_get_integer")),
                ("get_bool", _fn("eoir_get_bool")),
                ("get_string", _fn("eoir_get_string")),
                ("get_array", _fn("eoir_get_array")),
                ("property_info_at", _fn("eoir_property_info_at")),
                ("provider_group_at", _fn("eoir_provider_group_at")),
                ("provider_element_at", _fn("eoir_provider_element_at")),
                ("provider_get", _fn("eoir_provider_get")),
                ("provider_get_curve", _fn("eoir_provider_get_curve")),
                ("state_save", _fn("eoir_state_save")),
                ("state_load", _fn("eoir_state_load")),
                ("sensor_save", _fn("eoir_sensor_save")),
                ("sensor_load", _fn("eoir_sensor_load")),
                # appended in 1.1 (images)
                ("render", _fn("eoir_render")),
                ("image_info_get", _fn("eoir_image_info_get")),
                ("image_get", _fn("eoir_image_get")),
                ("image_get_bytes", _fn("eoir_image_get_bytes")),
                ("pick_get", _fn("eoir_pick_get")),
                # appended in 1.2 (targets)
                ("snr_constraint", _fn("eoir_snr_constraint")),
                ("truth_count", _fn("eoir_truth_count")),
                ("truth_get", _fn("eoir_truth_get")),
                # appended in 1.3
                ("provider_series", _fn("eoir_provider_series")),
                ("material_load", _fn("eoir_material_load")),
                ("spectrum_add", _fn("eoir_spectrum_add")),
                ("target_spectrum_get", _fn("eoir_target_spectrum_get")),
                # appended in 1.4 (adaptive fidelity)
                ("frame_fidelity_get", _fn("eoir_frame_fidelity_get")),
                # appended in 1.5 (pointing)
                ("sensor_point_azel", _fn("eoir_sensor_point_azel")),
                ("sensor_point_at", _fn("eoir_sensor_point_at")),
                # appended in 1.6 (eq. 9's terms)
                ("pick_term_get", _fn("eoir_pick_term_get")),
                # appended in 1.7 (the detector stage)
                ("image_get_adu", _fn("eoir_image_get_adu")),
                # appended in 1.7 (object limits)
                ("engine_set_limits", _fn("eoir_engine_set_limits")),
                ("engine_get_limits", _fn("eoir_engine_get_limits"))]


# ------------------------------------------------------------------- loading
_LIB_NAMES = ("libeoir.so.1", "libeoir.so", "libeoir.dylib", "eoir.dll")


def _candidates():
    env = os.environ.get("EOIR_LIBRARY")
    if env:
        yield env
        return  # an explicit choice is not second-guessed
    here = Path(__file__).resolve().parent
    # ../../build/lib relative to the package, then the repository root's
    # build/lib (bindings/python/eoir -> bindings -> repository root).
    for base in (here.parent.parent, here.parent.parent.parent, here.parent):
        for name in _LIB_NAMES:
            p = base / "build" / "lib" / name
            if p.exists():
                yield str(p)
    found = ctypes.util.find_library("eoir")
    if found:
        yield found


def _load():
    tried = []
    for path in _candidates():
        try:
            return ctypes.CDLL(path), path
        except OSError as exc:
            tried.append(f"{path}: {exc}")
    hint = "; ".join(tried) if tried else "no candidate found"
    raise ImportError(
        "eoir: cannot load the EOIR shared library (libeoir.so.1). Set "
        "EOIR_LIBRARY to its path or build the CMake target 'eoir' into "
        f"build/lib ({hint})")


lib, library_path = _load()

for _name, (_restype, _argtypes) in _SIGNATURES.items():
    try:
        _f = getattr(lib, _name)
    except AttributeError as exc:
        raise ImportError(f"eoir: {library_path} lacks the symbol {_name} of eoir.h") from exc
    _f.restype = _restype
    _f.argtypes = _argtypes
del _name, _restype, _argtypes, _f

version_number = int(lib.eoir_version())
if version_number // 10000 != EOIR_VERSION_MAJOR:
    raise ImportError(
        f"eoir: {library_path} has ABI version {version_number // 10000}."
        f"{version_number // 100 % 100}.{version_number % 100}; these bindings "
        f"need major version {EOIR_VERSION_MAJOR}")


# -------------------------------------------------------------------- errors
def decode(b) -> str:
    return "" if b is None else b.decode("utf-8", "replace")


def encode(s, argument: str) -> bytes:
    """A str (or bytes) argument as the C string the engine reads: UTF-8,
    refused with ValueError naming the argument if it holds a NUL (C would
    silently cut it there)."""
    if isinstance(s, str):
        s = s.encode("utf-8")
    elif not isinstance(s, bytes):
        raise TypeError(f"{argument}: expected a str, got {type(s).__name__}")
    if b"\0" in s:
        raise ValueError(f"{argument}: contains a NUL character")
    return s


def encode_path(path, argument: str = "path") -> bytes:
    """A path (str, bytes or os.PathLike) as the C string the engine opens,
    refused as encode() refuses it."""
    return encode(os.fsencode(path), argument)


def threads_argument(threads) -> int:
    """The worker-thread count of eoir_engine_desc: 0 (all cores) to 1024."""
    value = operator.index(threads)
    if not 0 <= value <= 1024:
        raise ValueError(f"threads: must be in [0, 1024] (0 = all cores), got {threads}")
    return value


def status_name(status: int) -> str:
    return decode(lib.eoir_status_name(int(status)))


def last_error() -> str:
    return decode(lib.eoir_last_error())


def make_error(status: int) -> errors.EoirError:
    """The exception for a failing status; read right after the call."""
    message = last_error()
    cls = errors.error_class(status)
    return cls(status, status_name(status), message)


def check(status: int) -> int:
    """Raise the matching EoirError for a negative status; return it otherwise."""
    if status < 0:
        raise make_error(status)
    return status
