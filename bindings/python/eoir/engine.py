"""The Pythonic API over the C ABI: :class:`Engine` and module functions."""

from __future__ import annotations

import ctypes
import datetime as _dt
import functools
import json
import math
import numbers
import os
from ctypes import byref, c_char_p, c_double, c_int32, c_int64, c_size_t
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple, TypeVar, Union

import numpy as np

from . import _lib
from . import errors
from .constants import Frame, ImageKind, Kind, TimeScale
from ._lib import check, decode, encode, encode_path, lib

__all__ = [
    "Engine",
    "TRUTH_FIELDS",
    "KINDS",
    "FRAMES",
    "TIME_SCALES",
    "TYPES",
    "IMAGE_KINDS",
    "version",
    "version_string",
    "status_name",
    "last_error",
    "provider_groups",
    "provider_elements",
    "time_from_iso",
    "time_to_iso",
]

# Names accepted wherever a kind, frame, time scale or image kind is taken
# (the lower-case names of eoir.constants' enums).
KINDS: Dict[str, int] = {m.name.lower(): int(m) for m in Kind}
_KIND_NAMES = {v: k for k, v in KINDS.items()}

FRAMES: Dict[str, int] = {m.name.lower(): int(m) for m in Frame}
_FRAME_NAMES = {v: k for k, v in FRAMES.items()}

TIME_SCALES: Dict[str, int] = {m.name.lower(): int(m) for m in TimeScale}
_SCALE_NAMES = {v: k for k, v in TIME_SCALES.items()}

TYPES = {
    "number": _lib.EOIR_TYPE_NUMBER,
    "integer": _lib.EOIR_TYPE_INTEGER,
    "bool": _lib.EOIR_TYPE_BOOL,
    "string": _lib.EOIR_TYPE_STRING,
    "array": _lib.EOIR_TYPE_ARRAY,
    "curve": _lib.EOIR_TYPE_CURVE,
}
_TYPE_NAMES = {v: k for k, v in TYPES.items()}

IMAGE_KINDS: Dict[str, int] = {m.name.lower(): int(m) for m in ImageKind}
_IMAGE_KIND_NAMES = {v: k for k, v in IMAGE_KINDS.items()}
_DISPLAY_KINDS = (_lib.EOIR_IMAGE_SCENE_DISPLAY, _lib.EOIR_IMAGE_SENSOR_DISPLAY)
_PICK_SPACES = {"sample": 0, "pixel": 1}
# Eq. 9's terms of a pick (C ABI 1.6, eoir_pick_term), in the order of the enum.
PICK_TERMS = ("surface", "downwelling", "transmittance", "path_thermal", "path_scatter", "at_sensor")

# The keys of every row of Engine.truth(): every field of
# schemas/truth.schema.json (Scenario.truth(), `eoir run`'s _truth.json), plus
# start and end in 0-based pixels.
TRUTH_FIELDS = (
    "object", "kind", "pixel_x", "pixel_y", "x_fits", "y_fits", "start", "end", "start_fits", "end_fits",
    "time", "start_time", "end_time", "ra_deg", "dec_deg", "start_ra_deg", "start_dec_deg", "end_ra_deg",
    "end_dec_deg", "apparent_ra_deg", "apparent_dec_deg", "geometric_ra_deg", "geometric_dec_deg", "range_m",
    "point_source", "visible", "effective_irradiance", "effective_radiance", "snr", "v_mag", "b_v_mag",
    "azimuth_deg", "elevation_deg", "air_mass",
)

Time = Union[str, _dt.datetime, Tuple[float, float], Tuple[float, float, str]]
"""A time the engine takes: ISO-8601 UTC, a datetime, (jd1, jd2) UTC or (jd1, jd2, scale)."""

_INITIAL_STRING_CAPACITY = 256
_INITIAL_ARRAY_CAPACITY = 64


def _lookup(table: Dict[str, int], value: Union[str, int], what: str) -> int:
    if isinstance(value, str):
        try:
            return table[value.lower()]
        except KeyError:
            raise ValueError(f"unknown {what} {value!r}; expected one of "
                             f"{', '.join(sorted(table))}") from None
    if isinstance(value, numbers.Integral):
        return int(value)
    raise TypeError(f"{what} must be a str or an int, got {type(value).__name__}")


def _type_name(code: int) -> str:
    return _TYPE_NAMES.get(code, str(code))


# ---------------------------------------------------------- module functions
def version() -> int:
    """eoir_version(): MAJOR*10000 + MINOR*100 + PATCH of the loaded library."""
    return int(lib.eoir_version())


def version_string() -> str:
    """eoir_version_string(), e.g. "1.0.0"."""
    return decode(lib.eoir_version_string())


def status_name(status: int) -> str:
    """eoir_status_name(), e.g. "EOIR_ERR_OUT_OF_RANGE"."""
    return _lib.status_name(status)


def last_error() -> str:
    """eoir_last_error() of the calling thread."""
    return _lib.last_error()


def provider_groups() -> List[str]:
    """Names of every data-provider group (eoir_provider_group_at)."""
    out = []
    name = c_char_p()
    index = 0
    while True:
        status = lib.eoir_provider_group_at(index, byref(name))
        if status == _lib.EOIR_ERR_OUT_OF_RANGE:
            return out
        check(status)
        out.append(decode(name.value))
        index += 1


@functools.lru_cache(maxsize=None)
def _elements(group: str) -> Tuple[Tuple[str, int, str, str], ...]:
    out = []
    g = encode(group, "group")
    index = 0
    while True:
        info = _lib.eoir_element_info()
        info.struct_size = ctypes.sizeof(info)
        status = lib.eoir_provider_element_at(g, index, byref(info))
        if status == _lib.EOIR_ERR_OUT_OF_RANGE and index > 0:
            return tuple(out)
        if status == _lib.EOIR_ERR_OUT_OF_RANGE:
            # An empty group (or an out-of-range answer for an unknown one).
            if group in provider_groups():
                return tuple(out)
        check(status)
        out.append((decode(info.name), int(info.type), decode(info.unit), decode(info.x_unit)))
        index += 1


def provider_elements(group: str) -> List[Dict[str, str]]:
    """The elements of a data-provider group as dicts with keys name, type
    ("number", "integer", "bool" or "curve"), unit and x_unit."""
    return [{"name": n, "type": _type_name(t), "unit": u, "x_unit": xu}
            for n, t, u, xu in _elements(group)]


def _element(group: str, element: str) -> Optional[Tuple[str, int, str, str]]:
    for info in _elements(group):
        if info[0] == element:
            return info
    return None


def time_from_iso(iso_utc: str) -> Tuple[float, float, str]:
    """ISO-8601 UTC to a two-part UTC Julian date (jd1, jd2, "utc")."""
    t = _lib.eoir_time()
    check(lib.eoir_time_from_iso(encode(iso_utc, "iso_utc"), byref(t)))
    return (t.jd1, t.jd2, _SCALE_NAMES.get(t.scale, t.scale))


def _iso_of(t: "_lib.eoir_time") -> str:
    capacity = 64
    while True:
        buf = ctypes.create_string_buffer(capacity)
        status = lib.eoir_time_to_iso(byref(t), buf, capacity)
        if status == _lib.EOIR_ERR_BUFFER_TOO_SMALL and capacity < (1 << 16):
            capacity *= 4
            continue
        check(status)
        return decode(buf.value)


def time_to_iso(time: Time) -> str:
    """A time (ISO string, (jd1, jd2, scale) or datetime) as ISO-8601 UTC."""
    return _iso_of(_to_c_time(time))


def _to_c_time(value: Time) -> "_lib.eoir_time":
    t = _lib.eoir_time()
    if isinstance(value, _lib.eoir_time):
        return value
    if isinstance(value, _dt.datetime):
        if value.tzinfo is not None:
            value = value.astimezone(_dt.timezone.utc).replace(tzinfo=None)
        value = value.isoformat() + "Z"
    if isinstance(value, (str, bytes)):
        check(lib.eoir_time_from_iso(encode(value, "time"), byref(t)))
        return t
    try:
        parts = tuple(value)
    except TypeError:
        raise TypeError("a time is an ISO-8601 UTC string, a datetime or "
                        "(jd1, jd2, scale)") from None
    if len(parts) == 2:
        jd1, jd2, scale = parts[0], parts[1], "utc"
    elif len(parts) == 3:
        jd1, jd2, scale = parts
    else:
        raise ValueError("a Julian date is (jd1, jd2, scale) or (jd1, jd2) in UTC")
    t.scale = _lookup(TIME_SCALES, scale, "time scale")
    t.jd1 = float(jd1)
    t.jd2 = float(jd2)
    return t


def heading_pitch_roll_quaternion(heading_deg: float, pitch_deg: float, roll_deg: float) -> Tuple[float, float, float, float]:
    """The unit quaternion (w, x, y, z) body -> local north-east-down of an
    aircraft's heading (from north through east), pitch (nose up) and roll
    (right wing down), deg: the ZYX Euler angles, q = Rz(heading) Ry(pitch)
    Rx(roll), body x forward, y right, z down (for frame="geodetic_ned")."""
    half = math.pi / 360.0
    angles = []
    for value, what in ((heading_deg, "heading_deg"), (pitch_deg, "pitch_deg"), (roll_deg, "roll_deg")):
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
            raise errors.OutOfRangeError(_lib.EOIR_ERR_OUT_OF_RANGE, "EOIR_ERR_OUT_OF_RANGE",
                                         f"{what}: must be a finite number, got {value!r}")
        angles.append(float(value) * half)
    ch, sh = math.cos(angles[0]), math.sin(angles[0])
    cp, sp = math.cos(angles[1]), math.sin(angles[1])
    cr, sr = math.cos(angles[2]), math.sin(angles[2])
    return (ch * cp * cr + sh * sp * sr,
            ch * cp * sr - sh * sp * cr,
            ch * sp * cr + sh * cp * sr,
            sh * cp * cr - ch * sp * sr)


def _vector(value, n: int, what: str) -> List[float]:
    arr = np.asarray(value, dtype=np.float64).ravel()
    if arr.size != n:
        raise ValueError(f"{what} needs {n} values, got {arr.size}")
    return [float(x) for x in arr]


# -------------------------------------------------------------------- engine
_C = TypeVar("_C", bound="_Closing")


class _Closing:
    """with-statement and garbage-collection support for a class whose close()
    releases a C handle and is idempotent."""

    def __enter__(self: _C) -> _C:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:
            pass


class Engine(_Closing):
    """One EOIR engine (eoir_engine_create .. eoir_engine_destroy).

    >>> with Engine(threads=0, seed=1) as engine:
    ...     engine.add_object("satellite", "Sat")
    ...     engine.add_sensor("Sensor", "Sat")
    ...     engine.provider("EOIR Sensor Optics", "Ensquared Energy", "Sensor")
    """

    def __init__(self, threads: int = 0, seed: int = 1) -> None:
        desc = _lib.eoir_engine_desc()
        desc.struct_size = ctypes.sizeof(desc)
        desc.threads = _lib.threads_argument(threads)
        desc.seed = int(seed) & 0xFFFFFFFFFFFFFFFF
        handle = _lib.eoir_engine()
        self._handle = None
        check(lib.eoir_engine_create(byref(desc), byref(handle)))
        if not handle.value:
            raise errors.InternalError(_lib.EOIR_ERR_INTERNAL, "EOIR_ERR_INTERNAL",
                                       "eoir_engine_create returned a NULL engine")
        self._handle = handle
        self._destroy = lib.eoir_engine_destroy  # kept for __del__ at exit

    @classmethod
    def _adopt(cls, handle, owner) -> "Engine":
        """An Engine over an engine someone else owns (eoir.Scenario's host
        session): calls go to the same library; close() only lets go of it."""
        self = cls.__new__(cls)
        self._handle = _lib.eoir_engine(handle)
        self._owner = owner
        self._destroy = lambda h: None
        return self

    # ---------------------------------------------------------- lifetime
    def close(self) -> None:
        """Destroy the engine; further calls raise ValueError. Idempotent."""
        handle, self._handle = getattr(self, "_handle", None), None
        if handle is not None:
            self._destroy(handle)

    @property
    def closed(self) -> bool:
        return self._handle is None

    @property
    def handle(self) -> ctypes.c_void_p:
        """The raw eoir_engine handle (ctypes.c_void_p)."""
        if self._handle is None:
            raise ValueError("the engine is closed")
        return self._handle

    def __repr__(self) -> str:
        if self._handle is None:
            return "<eoir.Engine closed>"
        return f"<eoir.Engine {len(self.objects())} objects at {self.time_iso()}>"

    # -------------------------------------------------------------- time
    def set_time(self, time: Time) -> None:
        """Set the engine time: an ISO-8601 UTC string, a datetime, or
        (jd1, jd2, scale) with scale "utc", "tai", "tt" or "tdb". Sensors
        under :meth:`track` are pointed again at their targets."""
        t = _to_c_time(time)
        check(lib.eoir_engine_set_time(self.handle, byref(t)))
        self._retrack(strict=False)

    def get_time(self, scale: Union[str, int] = "tt") -> Tuple[float, float, str]:
        """The engine time as (jd1, jd2, scale)."""
        t = _lib.eoir_time()
        code = _lookup(TIME_SCALES, scale, "time scale")
        check(lib.eoir_engine_get_time(self.handle, code, byref(t)))
        return (t.jd1, t.jd2, _SCALE_NAMES.get(t.scale, t.scale))

    def time_iso(self) -> str:
        """The engine time as ISO-8601 UTC."""
        t = _lib.eoir_time()
        check(lib.eoir_engine_get_time(self.handle, _lib.EOIR_TIME_UTC, byref(t)))
        return _iso_of(t)

    # ----------------------------------------------------------- objects
    def add_object(self, kind: Union[str, int], name: str) -> None:
        """Add an object; kind is "central_body", "star_field", "satellite",
        "aircraft", "ground_vehicle", "missile" or "site" (or its
        eoir_object_kind, e.g. eoir.Kind.SATELLITE). A site stays on the Earth at its properties
        latitude_deg, longitude_deg and height_m (WGS84), carries sensors,
        images nothing and takes no state."""
        code = _lookup(KINDS, kind, "object kind")
        check(lib.eoir_object_add(self.handle, code, encode(name, "name")))

    def add_sensor(self, name: str, parent: str) -> None:
        """Add a scene-generator/sensor-model pair attached to parent."""
        check(lib.eoir_sensor_add(self.handle, encode(name, "name"), encode(parent, "parent")))

    def remove(self, name: str) -> None:
        """Remove an object (its sensors go with it, and any track of it)."""
        check(lib.eoir_object_remove(self.handle, encode(name, "name")))
        tracks = self._tracks()
        for sensor, target in list(tracks.items()):
            if name in (sensor, target) or sensor not in self:
                del tracks[sensor]

    def object_count(self) -> int:
        n = c_size_t()
        check(lib.eoir_object_count(self.handle, byref(n)))
        return int(n.value)

    def objects(self) -> List[Tuple[str, str]]:
        """Every object as (name, kind) in insertion order."""
        out = []
        name = c_char_p()
        kind = c_int32()
        for i in range(self.object_count()):
            check(lib.eoir_object_at(self.handle, i, byref(name), byref(kind)))
            out.append((decode(name.value), _KIND_NAMES.get(kind.value, kind.value)))
        return out

    def __contains__(self, name: str) -> bool:
        return any(n == name for n, _ in self.objects())

    # ------------------------------------------------------------ limits
    _LIMIT_FIELDS = ("max_satellites", "max_vehicles", "max_sites", "max_missiles", "max_sensors")

    def limits(self) -> Dict[str, int]:
        """The engine's object limits (eoir_engine_get_limits): max_satellites,
        max_vehicles, max_sites, max_missiles, max_sensors; a new engine has
        the spec's profile (16, 6, 16, 6, 6)."""
        out = _lib.eoir_limits()
        out.struct_size = ctypes.sizeof(out)
        check(lib.eoir_engine_get_limits(self.handle, byref(out)))
        return {name: int(getattr(out, name)) for name in self._LIMIT_FIELDS}

    def set_limits(self, **limits: int) -> None:
        """Raise or lower some object limits (eoir_engine_set_limits; the
        others keep their values): e.g. set_limits(max_satellites=1000).
        Raises OutOfRangeError for 0 or a value above its ceiling (the
        message names the field), NotAllowedError below the objects of that
        kind the engine holds, ValueError for an unknown name."""
        unknown = sorted(set(limits) - set(self._LIMIT_FIELDS))
        if unknown:
            raise ValueError(f"set_limits: unknown limit {', '.join(unknown)} (known: {', '.join(self._LIMIT_FIELDS)})")
        values = self.limits()
        values.update(limits)
        st = _lib.eoir_limits()
        st.struct_size = ctypes.sizeof(st)
        for name, value in values.items():
            if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < 2 ** 32:
                raise errors.OutOfRangeError(f"{name}: must be a whole number in [1, its ceiling], not {value!r}")
            setattr(st, name, value)
        check(lib.eoir_engine_set_limits(self.handle, byref(st)))

    # ------------------------------------------------------------- state
    def set_state(self, name: str, position: Sequence[float], velocity: Sequence[float] = (0.0, 0.0, 0.0),
                  attitude: Sequence[float] = (1.0, 0.0, 0.0, 0.0), frame: Union[str, int] = "j2000",
                  time: Optional[Time] = None, angular_velocity: Sequence[float] = (0.0, 0.0, 0.0)) -> None:
        """Push a state: position in metres (or lat deg, lon deg, height m for
        "geodetic" and "geodetic_ned"), velocity in m/s, attitude quaternion
        (w, x, y, z) body to frame, angular velocity in rad/s about the
        frame's axes (the attitude turns at it between pushes); time None
        means the engine time. "geodetic_ned": velocity, attitude and angular
        velocity in the local north-east-down axes at that place (attitude
        from heading_pitch_roll_quaternion); height 0 m is the WGS84
        ellipsoid's surface (no terrain). A state set on a sensor under
        :meth:`track` ends the track; sensors tracking from or toward the
        object are pointed again."""
        st = _lib.eoir_state()
        st.struct_size = ctypes.sizeof(st)
        st.frame = _lookup(FRAMES, frame, "frame")
        st.position[:] = _vector(position, 3, "position")
        st.velocity[:] = _vector(velocity, 3, "velocity")
        st.attitude[:] = _vector(attitude, 4, "attitude")
        st.angular_velocity[:] = _vector(angular_velocity, 3, "angular_velocity")
        t = None if time is None else byref(_to_c_time(time))
        check(lib.eoir_object_set_state(self.handle, encode(name, "name"), t, byref(st)))
        self._tracks().pop(name, None)
        self._retrack(strict=False)

    def get_state(self, name: str, frame: Union[str, int] = "j2000") -> Dict[str, Any]:
        """The state at the engine time as a dict with numpy arrays position,
        velocity, attitude, angular_velocity (rad/s) and the frame name."""
        st = _lib.eoir_state()
        st.struct_size = ctypes.sizeof(st)
        st.frame = _lookup(FRAMES, frame, "frame")
        check(lib.eoir_object_get_state(self.handle, encode(name, "name"), byref(st)))
        return {
            "frame": _FRAME_NAMES.get(st.frame, st.frame),
            "position": np.array(st.position[:], dtype=np.float64),
            "velocity": np.array(st.velocity[:], dtype=np.float64),
            "attitude": np.array(st.attitude[:], dtype=np.float64),
            "angular_velocity": np.array(st.angular_velocity[:], dtype=np.float64),
        }

    def point_at(self, sensor: str, target: Optional[str] = None,
                 azimuth_deg: Optional[float] = None, elevation_deg: Optional[float] = None) -> None:
        """Point sensor at the engine time: give target, or azimuth_deg and
        elevation_deg. Sets the sensor's own attitude (its position stays its
        parent's) through eoir_sensor_point_at / eoir_sensor_point_azel.

        target: body +z toward the object, with the angular velocity that
        keeps it on the boresight during the integration (it stays still, the
        stars streak); body +y toward the sensor's zenith within 100 km of
        the Earth's surface, else toward the J2000 north pole. Call it again
        after each set_time to keep tracking.

        azimuth_deg (from north through east, within +-360) and
        elevation_deg (above the geodetic horizon, [-90, 90]): the direction
        on the local horizon of the sensor's place, body +y toward the
        zenith side (up in the picture), held fixed to the Earth.

        Raises OutOfRangeError naming azimuth_deg or elevation_deg (NaN
        included), NotAllowedError for the star field, the sensor's parent or
        a target at the sensor's place, NoStateError if the parent has no
        state, ValueError if neither or both ways are given. Ends a
        :meth:`track` of sensor.
        """
        self._tracks().pop(sensor, None)
        if target is not None:
            if azimuth_deg is not None or elevation_deg is not None:
                raise ValueError("point_at: give target or azimuth_deg and elevation_deg, not both")
            check(lib.eoir_sensor_point_at(self.handle, encode(sensor, "sensor"), encode(target, "target")))
            return
        if azimuth_deg is None or elevation_deg is None:
            raise ValueError("point_at: give target, or both azimuth_deg and elevation_deg")
        check(lib.eoir_sensor_point_azel(self.handle, encode(sensor, "sensor"), float(azimuth_deg),
                                         float(elevation_deg)))

    def track(self, sensor: str, target: Optional[str]) -> None:
        """Keep sensor pointed at target as time steps: :meth:`point_at` now
        (errors raised here), then again after every :meth:`set_time` and
        :meth:`set_state` (and :meth:`eoir.Scenario.set_time`, after the
        scenario's own pointing) and before every :meth:`render`, so each
        frame has target at its centre (truth pixel_x, pixel_y = (width - 1)
        / 2, (height - 1) / 2) with the angular velocity that holds it there
        during the integration. track(sensor, None) ends it, as do
        point_at(sensor, ...), set_state(sensor, ...) and removing either
        object."""
        tracks = self._tracks()
        if target is None:
            tracks.pop(sensor, None)
            return
        self.point_at(sensor, target)
        tracks[sensor] = target

    def tracks(self) -> Dict[str, str]:
        """The sensors under :meth:`track` and their targets."""
        return dict(self._tracks())

    def _tracks(self) -> Dict[str, str]:
        return self.__dict__.setdefault("_track_targets", {})

    def _retrack(self, strict: bool) -> None:
        """Point every tracking sensor at its target. Not strict (after a
        time or a state changes): a target or parent without a state yet is
        skipped, since the host may push it next; strict (before a render):
        every error is raised."""
        for sensor, target in self._tracks().items():
            try:
                check(lib.eoir_sensor_point_at(self.handle, encode(sensor, "sensor"), encode(target, "target")))
            except errors.NoStateError:
                if strict:
                    raise

    # -------------------------------------------------------- properties
    def properties(self, obj: str) -> List[Dict[str, object]]:
        """Every property of an object as dicts with keys name, type
        ("number", "integer", "bool", "string" or "array"), unit, description,
        fidelity (a knob trading speed for accuracy), minimum and maximum
        (None if unbounded; open bounds marked by minimum_open/maximum_open)
        and choices (the closed set of a string property, else [])."""
        return [dict(p, type=_type_name(p["type"])) for p in self._property_infos(obj)]

    def _property_infos(self, obj: str):
        out = []
        o = encode(obj, "obj")
        index = 0
        while True:
            info = _lib.eoir_property_info()
            info.struct_size = ctypes.sizeof(info)
            status = lib.eoir_property_info_at(self.handle, o, index, byref(info))
            if status == _lib.EOIR_ERR_OUT_OF_RANGE and (index > 0 or obj in self):
                return out
            check(status)
            choices = decode(info.choices) if info.choices else ""
            out.append({"name": decode(info.name), "type": int(info.type), "unit": decode(info.unit),
                        "description": decode(info.description),
                        "fidelity": bool(info.flags & _lib.EOIR_PROPERTY_FIDELITY),
                        "minimum": info.minimum if math.isfinite(info.minimum) else None,
                        "maximum": info.maximum if math.isfinite(info.maximum) else None,
                        "minimum_open": bool(info.range_open & 1),
                        "maximum_open": bool(info.range_open & 2),
                        "choices": choices.split(",") if choices else []})
            index += 1

    def property_type(self, obj: str, prop: str) -> Optional[str]:
        """The type name of a property, or None if the object lacks it."""
        for p in self._property_infos(obj):
            if p["name"] == prop:
                return _type_name(p["type"])
        return None

    def _type_code(self, obj: str, prop: str, value=None) -> int:
        for p in self._property_infos(obj):
            if p["name"] == prop:
                return p["type"]
        # Not listed: guess from the value and let the library name the error.
        if value is None or isinstance(value, (float, numbers.Real)) and not isinstance(value, numbers.Integral):
            return _lib.EOIR_TYPE_NUMBER
        if isinstance(value, (bool, np.bool_)):
            return _lib.EOIR_TYPE_BOOL
        if isinstance(value, numbers.Integral):
            return _lib.EOIR_TYPE_INTEGER
        if isinstance(value, (str, bytes)):
            return _lib.EOIR_TYPE_STRING
        return _lib.EOIR_TYPE_ARRAY

    def set(self, obj: str, prop: str, value: Any) -> None:
        """Set a property, converting value to the property's type (numbers,
        integers, bools, strings; arrays from lists or numpy arrays, flattened)."""
        h, o, p = self.handle, encode(obj, "obj"), encode(prop, "prop")
        t = self._type_code(obj, prop, value)
        if t == _lib.EOIR_TYPE_NUMBER:
            check(lib.eoir_set_number(h, o, p, float(value)))
        elif t == _lib.EOIR_TYPE_INTEGER:
            check(lib.eoir_set_integer(h, o, p, _as_integer(value, prop)))
        elif t == _lib.EOIR_TYPE_BOOL:
            if isinstance(value, str) or not isinstance(value, (bool, np.bool_, numbers.Integral)):
                raise TypeError(f"{prop}: expected a bool, got {type(value).__name__}")
            check(lib.eoir_set_bool(h, o, p, 1 if value else 0))
        elif t == _lib.EOIR_TYPE_STRING:
            if not isinstance(value, (str, bytes)):
                raise TypeError(f"{prop}: expected a str, got {type(value).__name__}")
            check(lib.eoir_set_string(h, o, p, encode(value, "value")))
        elif t == _lib.EOIR_TYPE_ARRAY:
            arr = np.ascontiguousarray(np.asarray(value, dtype=np.float64).ravel())
            ptr = arr.ctypes.data_as(ctypes.POINTER(c_double))
            check(lib.eoir_set_array(h, o, p, ptr, arr.size))
        else:
            raise errors.TypeMismatchError(_lib.EOIR_ERR_TYPE_MISMATCH, "EOIR_ERR_TYPE_MISMATCH",
                                           f"{prop}: properties of type {_type_name(t)} cannot be set")

    def get(self, obj: str, prop: str) -> Any:
        """A property's value: float, int, bool, str or a numpy float64 array."""
        h, o, p = self.handle, encode(obj, "obj"), encode(prop, "prop")
        t = self._type_code(obj, prop)
        if t == _lib.EOIR_TYPE_NUMBER:
            v = c_double()
            check(lib.eoir_get_number(h, o, p, byref(v)))
            return float(v.value)
        if t == _lib.EOIR_TYPE_INTEGER:
            v = c_int64()
            check(lib.eoir_get_integer(h, o, p, byref(v)))
            return int(v.value)
        if t == _lib.EOIR_TYPE_BOOL:
            v = c_int32()
            check(lib.eoir_get_bool(h, o, p, byref(v)))
            return bool(v.value)
        if t == _lib.EOIR_TYPE_STRING:
            capacity = _INITIAL_STRING_CAPACITY
            while True:
                buf = ctypes.create_string_buffer(capacity)
                status = lib.eoir_get_string(h, o, p, buf, capacity)
                if status == _lib.EOIR_ERR_BUFFER_TOO_SMALL and capacity < (1 << 26):
                    capacity *= 4
                    continue
                check(status)
                return decode(buf.value)
        if t == _lib.EOIR_TYPE_ARRAY:
            n = c_size_t()
            check(lib.eoir_get_array(h, o, p, None, 0, byref(n)))
            capacity = max(int(n.value), 1)
            for _ in range(8):
                arr = np.zeros(capacity, dtype=np.float64)
                ptr = arr.ctypes.data_as(ctypes.POINTER(c_double))
                status = lib.eoir_get_array(h, o, p, ptr, capacity, byref(n))
                if status == _lib.EOIR_ERR_BUFFER_TOO_SMALL:
                    capacity = max(int(n.value), capacity * 2)
                    continue
                check(status)
                return arr[: int(n.value)].copy()
            check(status)
        raise errors.TypeMismatchError(_lib.EOIR_ERR_TYPE_MISMATCH, "EOIR_ERR_TYPE_MISMATCH",
                                       f"{prop}: unsupported property type {_type_name(t)}")

    # ---------------------------------------------------- data providers
    def provider(self, group: str, element: str, sensor: str, target: Optional[str] = None) -> Any:
        """One data-provider element at the engine time: a float for numbers,
        an int for integers, a bool for bools, and (x, y) numpy float64 arrays
        for curves."""
        info = _element(group, element)
        etype = info[1] if info is not None else _lib.EOIR_TYPE_NUMBER
        g, e, s = encode(group, "group"), encode(element, "element"), encode(sensor, "sensor")
        tg = None if target is None else encode(target, "target")
        if etype == _lib.EOIR_TYPE_CURVE:
            return self._curve(g, e, s, tg)
        v = c_double()
        check(lib.eoir_provider_get(self.handle, g, e, s, tg, byref(v)))
        value = float(v.value)
        if etype == _lib.EOIR_TYPE_INTEGER:
            return int(round(value)) if math.isfinite(value) else value
        if etype == _lib.EOIR_TYPE_BOOL:
            return value != 0.0
        return value

    def _curve(self, g, e, s, tg):
        n = c_size_t()
        check(lib.eoir_provider_get_curve(self.handle, g, e, s, tg, None, None, 0, byref(n)))
        capacity = max(int(n.value), 1)
        for _ in range(8):
            x = np.zeros(capacity, dtype=np.float64)
            y = np.zeros(capacity, dtype=np.float64)
            dp = ctypes.POINTER(c_double)
            status = lib.eoir_provider_get_curve(self.handle, g, e, s, tg,
                                                 x.ctypes.data_as(dp), y.ctypes.data_as(dp),
                                                 capacity, byref(n))
            if status == _lib.EOIR_ERR_BUFFER_TOO_SMALL:
                capacity = max(int(n.value), capacity * 2)
                continue
            check(status)
            m = int(n.value)
            return x[:m].copy(), y[:m].copy()
        check(status)

    def provider_series(self, group: str, element: str, sensor: str, times: Iterable[Time], target: Optional[str] = None) -> np.ndarray:
        """A scalar element at each of `times` (each an ISO-8601 UTC string,
        a datetime or (jd1, jd2[, scale]), as set_time takes it) in one
        engine call (eoir_provider_series); the engine time is left at the last.
        Within the call sensors keep the attitude they have, turning at its
        angular velocity: a :meth:`track` is not re-pointed at each time (loop
        over set_time and :meth:`provider` for that)."""
        times = list(times)
        ts = (_lib.eoir_time * len(times))()
        for i, t in enumerate(times):
            ts[i] = _to_c_time(t)
        out = np.zeros(len(times), dtype=np.float64)
        tg = None if target is None else encode(target, "target")
        check(lib.eoir_provider_series(self.handle, encode(group, "group"), encode(element, "element"),
                                       encode(sensor, "sensor"), tg, ts, len(times),
                                       out.ctypes.data_as(ctypes.POINTER(c_double))))
        return out

    def report(self, group: str, sensor: str, target: Optional[str] = None) -> Dict[str, Tuple[Any, str]]:
        """Every element of a group: {element: (value, unit)} (curves give
        ((x, y), y unit))."""
        return {name: (self.provider(group, name, sensor, target), unit)
                for name, _, unit, _ in _elements(group)}

    # ------------------------------------------------- targets and truth
    def snr(self, sensor: str, target: str, time: Optional[Time] = None) -> float:
        """The SNR access constraint (spec 7.8, eoir_snr_constraint): the SNR
        of target seen by sensor. time None means the engine time; otherwise
        the engine time is set to it first and objects move from their last
        pushed states (constant velocity). 0 while the target is outside the
        field or hidden. Raises UnknownNameError for an unknown sensor or
        target and NotAllowedError for a target equal to the sensor's parent.
        Tracking sensors (:meth:`track`) are pointed at the new time first."""
        if time is not None and self._tracks():
            self.set_time(time)  # the same engine time, then the tracks
            time = None
        t = None if time is None else byref(_to_c_time(time))
        v = c_double()
        check(lib.eoir_snr_constraint(self.handle, encode(sensor, "sensor"), encode(target, "target"), t,
                                      byref(v)))
        return float(v.value)

    def truth(self, sensor: str) -> List[Dict[str, Any]]:
        """Per-frame truth of the last frame rendered for sensor
        (eoir_truth_count / eoir_truth_get): one dict per object or catalogue
        star in the field with keys kind ("object" or "star"), object (name
        or catalogue id), pixel_x, pixel_y (sub-pixel, 0 = centre of pixel 0,
        rows from the top), x_fits, y_fits (the same in FITS pixels: 1-based,
        row 1 at the bottom, as `eoir run` and :meth:`eoir.Scenario.truth`
        give them), range_m (0 for stars), point_source (bool),
        visible (bool), effective_irradiance (W/cm^2), effective_radiance
        (W/(cm^2 sr)), snr, v_mag, b_v_mag (stars), start and end (pixel_x,
        pixel_y) at the start and the end of the integration (a streak),
        start_fits and end_fits the same in FITS pixels, time, start_time and
        end_time (ISO-8601 UTC: the middle, start and end of the
        integration), and
        three directions from the sensor, in degrees:

        - ra_deg, dec_deg: astrometric (ICRS), what the frame's astrometric
          WCS (image_info's astrometric_*; the FITS WCS of `eoir run`) gives
          at the object's pixel, as a plate solution against a star
          catalogue does (the field's aberration and light deflection
          absorbed); start_ra_deg, start_dec_deg, end_ra_deg, end_dec_deg
          the same at the start and the end of the integration;
        - apparent_ra_deg, apparent_dec_deg: where the image has it, J2000
          (GCRS) axes (stars, the Moon and planets at their apparent places,
          other objects at their geometric direction), before refraction;
        - geometric_ra_deg, geometric_dec_deg: the true direction at the frame
          time (no light time, aberration or deflection; stars: the catalogue
          place with proper motion and parallax).

        azimuth_deg and elevation_deg: the apparent direction on the sensor's
        local horizon (from north through east, above the geodetic horizon,
        unrefracted; None unless the sensor is within 100 km of the Earth's
        surface); air_mass: the air along the line of sight, or toward space
        for a star, in sea-level vertical columns (1 straight up from sea
        level; 0 while the Earth's atmosphere is off). From inside the
        atmosphere the pixel positions of stars and of point sources beyond
        it are raised by the refraction, as in the image. Rows have the keys
        of TRUTH_FIELDS: every field of :meth:`eoir.Scenario.truth` with the
        same values (None where the file leaves a field out: v_mag and
        b_v_mag of objects, azimuth_deg and elevation_deg away from the
        Earth). Raises NoStateError if no frame was rendered."""
        s = encode(sensor, "sensor")
        n = c_size_t()
        check(lib.eoir_truth_count(self.handle, s, byref(n)))
        info = self._image_info(sensor, _lib.EOIR_IMAGE_SENSOR_ELECTRONS)
        height = float(info.height)
        times = []
        for jd in (info.time_jd_utc, info.start_jd_utc, info.end_jd_utc):
            tm = _lib.eoir_time()
            tm.scale = _lib.EOIR_TIME_UTC
            tm.jd1, tm.jd2 = jd[0], jd[1]
            times.append(_iso_of(tm))

        def fits(x: float, y: float) -> Tuple[float, float]:
            # FITS pixels: 1-based, row 1 at the bottom (plugin_host/cli/run.cpp)
            return (float(x) + 1.0, height - float(y))

        out = []
        for i in range(int(n.value)):
            t = _lib.eoir_truth()
            t.struct_size = ctypes.sizeof(t)
            check(lib.eoir_truth_get(self.handle, s, i, byref(t)))
            star = t.kind == _lib.EOIR_TRUTH_STAR
            x_fits, y_fits = fits(t.pixel_x, t.pixel_y)
            out.append({
                "object": decode(t.object),
                "pixel_x": float(t.pixel_x),
                "pixel_y": float(t.pixel_y),
                "x_fits": x_fits,
                "y_fits": y_fits,
                "time": times[0],
                "start_time": times[1],
                "end_time": times[2],
                "range_m": float(t.range_m),
                "point_source": bool(t.point_source),
                "visible": bool(t.visible),
                "effective_irradiance": float(t.effective_irradiance),
                "effective_radiance": float(t.effective_radiance),
                "snr": float(t.snr),
                "kind": "star" if star else "object",
                "ra_deg": float(t.astrometric_ra_deg),
                "dec_deg": float(t.astrometric_dec_deg),
                "start_ra_deg": float(t.start_astrometric_ra_deg),
                "start_dec_deg": float(t.start_astrometric_dec_deg),
                "end_ra_deg": float(t.end_astrometric_ra_deg),
                "end_dec_deg": float(t.end_astrometric_dec_deg),
                "apparent_ra_deg": float(t.right_ascension_deg),
                "apparent_dec_deg": float(t.declination_deg),
                "geometric_ra_deg": float(t.geometric_ra_deg),
                "geometric_dec_deg": float(t.geometric_dec_deg),
                "v_mag": float(t.v_mag) if star else None,
                "b_v_mag": float(t.b_v_mag) if star else None,
                "start": (float(t.start_pixel_x), float(t.start_pixel_y)),
                "end": (float(t.end_pixel_x), float(t.end_pixel_y)),
                "start_fits": fits(t.start_pixel_x, t.start_pixel_y),
                "end_fits": fits(t.end_pixel_x, t.end_pixel_y),
                "azimuth_deg": float(t.azimuth_deg) if t.topocentric else None,
                "elevation_deg": float(t.elevation_deg) if t.topocentric else None,
                "air_mass": float(t.air_mass),
            })
        return out

    def report_series(self, group: str, sensor: str, target: Optional[str], times: Iterable,
                      push: Optional[Callable[["Engine", Any], None]] = None) -> List[Dict[str, Any]]:
        """A data-provider group over time, as the eoir CLI's `report`: for
        each time (ISO string, datetime or (jd1, jd2[, scale])) the engine
        time is set, then push(engine, time) is called (the host pushes the
        states of its objects at that time, e.g. with set_state), then every
        element is read. Returns one dict per time: {"time": ISO-8601 UTC,
        ELEMENT: value, ...} (values as :meth:`provider`)."""
        names = [n for n, _, _, _ in _elements(group)]
        rows = []
        for time in times:
            self.set_time(time)
            if push is not None:
                push(self, time)
            row: Dict[str, Any] = {"time": self.time_iso()}
            for name in names:
                row[name] = self.provider(group, name, sensor, target)
            rows.append(row)
        return rows

    # -------------------------------------------------------- save, load
    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Save the whole engine state as a .scd file."""
        check(lib.eoir_state_save(self.handle, encode_path(path)))

    def load(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Replace the engine state by a .scd file (unchanged on error; ends
        every :meth:`track`)."""
        check(lib.eoir_state_load(self.handle, encode_path(path)))
        self._tracks().clear()

    def save_sensor(self, sensor: str, path: Union[str, "os.PathLike[str]"]) -> None:
        """Save one sensor's parameters."""
        check(lib.eoir_sensor_save(self.handle, encode(sensor, "sensor"), encode_path(path)))

    def load_sensor(self, sensor: str, path: Union[str, "os.PathLike[str]"]) -> None:
        """Replace an existing sensor's parameters from a sensor file."""
        check(lib.eoir_sensor_load(self.handle, encode(sensor, "sensor"), encode_path(path)))

    # ------------------------------------------------------------ images
    def render(self, sensor: str) -> None:
        """Render the frame of a sensor at the engine time (eoir_render),
        tracking sensors (:meth:`track`) pointed at their targets first."""
        self._retrack(strict=True)
        check(lib.eoir_render(self.handle, encode(sensor, "sensor")))

    def frame_fidelity(self, sensor: str) -> Dict[str, Any]:
        """The fidelity settings the last frame of a sensor was rendered with
        (eoir_frame_fidelity_get): a dict with error_budget, estimated_error,
        spectral_intervals and every fidelity knob; with error_budget > 0 the
        settings the engine chose for that frame (README "Adaptive fidelity")."""
        n = c_size_t()
        check(lib.eoir_frame_fidelity_get(self.handle, encode(sensor, "sensor"), None, 0, byref(n)))
        buf = ctypes.create_string_buffer(n.value + 1)
        check(lib.eoir_frame_fidelity_get(self.handle, encode(sensor, "sensor"), buf, n.value + 1, byref(n)))
        return json.loads(buf.value.decode("utf-8"))

    def _image_info(self, sensor: str, code: int) -> "_lib.eoir_image_info":
        info = _lib.eoir_image_info()
        info.struct_size = ctypes.sizeof(info)
        check(lib.eoir_image_info_get(self.handle, encode(sensor, "sensor"), code, byref(info)))
        return info

    def image_info(self, sensor: str, kind: Union[str, int]) -> Dict[str, Any]:
        """Size, unit, times, pointing and sky coordinates of the last frame's
        image of a kind ("scene_radiance", "scene_display",
        "sensor_electrons", "sensor_mean", "sensor_display"): a dict with
        width, height, kind, unit; time_jd_utc (jd1, jd2) and time (ISO-8601
        UTC) of the middle of the integration, start_jd_utc / start_time and
        end_jd_utc / end_time of its start and end; boresight_ra_deg,
        boresight_dec_deg, up_ra_deg, up_dec_deg (the sensor's +z and +y,
        J2000 axes); the astrometric TAN WCS (ICRS as a plate solution
        against a star catalogue gives it: the field's aberration and light
        deflection absorbed, refraction not): astrometric_ra_deg,
        astrometric_dec_deg at the image centre and astrometric_cd_deg
        (dxi/dcolumn, dxi/drow, deta/dcolumn, deta/drow in degrees per
        column and row of this image; xi east, eta north; rows from the
        top); observer_position_m, observer_velocity_m_s (J2000) and
        observer_earth_fixed_m (ITRS) of the sensor at the middle;
        saturation_electrons and read_noise_electrons of the sensor images
        (0 where saturation or noise is off; with the sensor's detector_model
        on, its full well and read noise); gain_e_per_adu, bias_adu,
        saturation_adu and adc_max_adu of the detector stage (0 with it off;
        README "Detector model"). "sensor_adu" raises NoStateError unless
        the frame was rendered with detector_model on."""
        code = _lookup(IMAGE_KINDS, kind, "image kind")
        info = self._image_info(sensor, code)

        def iso(jd):
            t = _lib.eoir_time()
            t.scale = _lib.EOIR_TIME_UTC
            t.jd1, t.jd2 = jd[0], jd[1]
            return _iso_of(t)

        return {
            "width": int(info.width),
            "height": int(info.height),
            "kind": _IMAGE_KIND_NAMES.get(info.kind, int(info.kind)),
            "unit": decode(info.unit),
            "time_jd_utc": (float(info.time_jd_utc[0]), float(info.time_jd_utc[1])),
            "time": iso(info.time_jd_utc),
            "start_jd_utc": (float(info.start_jd_utc[0]), float(info.start_jd_utc[1])),
            "start_time": iso(info.start_jd_utc),
            "end_jd_utc": (float(info.end_jd_utc[0]), float(info.end_jd_utc[1])),
            "end_time": iso(info.end_jd_utc),
            "boresight_ra_deg": float(info.boresight_ra_deg),
            "boresight_dec_deg": float(info.boresight_dec_deg),
            "up_ra_deg": float(info.up_ra_deg),
            "up_dec_deg": float(info.up_dec_deg),
            "astrometric_ra_deg": float(info.astrometric_ra_deg),
            "astrometric_dec_deg": float(info.astrometric_dec_deg),
            "astrometric_cd_deg": tuple(float(v) for v in info.astrometric_cd_deg),
            "observer_position_m": np.array(list(info.observer_position_m)),
            "observer_velocity_m_s": np.array(list(info.observer_velocity_m_s)),
            "observer_earth_fixed_m": np.array(list(info.observer_earth_fixed_m)),
            "saturation_electrons": float(info.saturation_electrons),
            "read_noise_electrons": float(info.read_noise_electrons),
            "gain_e_per_adu": float(info.gain_e_per_adu),
            "bias_adu": float(info.bias_adu),
            "saturation_adu": float(info.saturation_adu),
            "adc_max_adu": float(info.adc_max_adu),
        }

    def image(self, sensor: str, kind: Union[str, int]) -> np.ndarray:
        """The last frame's image of a kind as a (height, width) array, row 0
        at the top as seen on the sky: float64 for "scene_radiance"
        (W/(cm^2 sr)), "sensor_electrons" and "sensor_mean" (electrons);
        uint8 for "scene_display" and "sensor_display"; uint32 for
        "sensor_adu" (the detector stage's ADU, sensor property
        detector_model; NoStateError with it off)."""
        code = _lookup(IMAGE_KINDS, kind, "image kind")
        info = self._image_info(sensor, code)
        h, w = int(info.height), int(info.width)
        s = encode(sensor, "sensor")
        if code in _DISPLAY_KINDS:
            out = np.zeros((h, w), dtype=np.uint8)
            ptr = out.ctypes.data_as(ctypes.POINTER(ctypes.c_uint8))
            check(lib.eoir_image_get_bytes(self.handle, s, code, ptr, out.size))
        elif code == _lib.EOIR_IMAGE_SENSOR_ADU:
            out = np.zeros((h, w), dtype=np.uint32)
            ptr = out.ctypes.data_as(ctypes.POINTER(ctypes.c_uint32))
            check(lib.eoir_image_get_adu(self.handle, s, ptr, out.size))
        else:
            out = np.zeros((h, w), dtype=np.float64)
            ptr = out.ctypes.data_as(ctypes.POINTER(c_double))
            check(lib.eoir_image_get(self.handle, s, code, ptr, out.size))
        return out

    def pick(self, sensor: str, x: int, y: int, space: str = "sample") -> Dict[str, Any]:
        """What scene sample (space "sample") or sensor pixel ("pixel", its
        centre sample) (x = column, y = row from the top) sees in the last
        frame (spec 6.2.1): a dict with hit (bool), object ("" for the sky),
        patch, range_m, has_geodetic, latitude_deg, longitude_deg,
        right_ascension_deg, declination_deg, effective_radiance
        (W/(cm^2 sr)), temperature_K, and numpy arrays wavelengths_um and
        spectral_radiance (W/(cm^2 sr um)) on the sensor's spectral grid."""
        code = _lookup(_PICK_SPACES, space, "pick space")
        if not isinstance(x, numbers.Integral) or not isinstance(y, numbers.Integral):
            raise TypeError("pick: x and y are integer sample or pixel indices")
        if x < 0 or y < 0 or x > 0xFFFFFFFF or y > 0xFFFFFFFF:
            raise ValueError(f"pick: x and y must be non-negative, got ({x}, {y})")
        s = encode(sensor, "sensor")
        dp = ctypes.POINTER(c_double)
        n = c_size_t()
        pick = _lib.eoir_pick()
        pick.struct_size = ctypes.sizeof(pick)
        check(lib.eoir_pick_get(self.handle, s, code, int(x), int(y), byref(pick), None, None, 0, byref(n)))
        capacity = max(int(n.value), 1)
        for _ in range(8):
            wl = np.zeros(capacity, dtype=np.float64)
            rad = np.zeros(capacity, dtype=np.float64)
            pick = _lib.eoir_pick()
            pick.struct_size = ctypes.sizeof(pick)
            status = lib.eoir_pick_get(self.handle, s, code, int(x), int(y), byref(pick),
                                       wl.ctypes.data_as(dp), rad.ctypes.data_as(dp), capacity, byref(n))
            if status == _lib.EOIR_ERR_BUFFER_TOO_SMALL:
                capacity = max(int(n.value), capacity * 2)
                continue
            check(status)
            m = int(n.value)
            return {
                "hit": bool(pick.hit),
                "object": decode(pick.object),
                "patch": int(pick.patch),
                "range_m": float(pick.range_m),
                "has_geodetic": bool(pick.has_geodetic),
                "latitude_deg": float(pick.latitude_deg),
                "longitude_deg": float(pick.longitude_deg),
                "right_ascension_deg": float(pick.right_ascension_deg),
                "declination_deg": float(pick.declination_deg),
                "effective_radiance": float(pick.effective_radiance),
                "temperature_K": float(pick.temperature_K),
                "wavelengths_um": wl[:m].copy(),
                "spectral_radiance": rad[:m].copy(),
            }
        check(status)

    def pick_terms(self, sensor: str, x: int, y: int, space: str = "sample") -> Dict[str, np.ndarray]:
        """Eq. 9 term by term for the sample pick() reads (spec 4.1.5.3; the
        components of 6.2.5.4), each a numpy array on the sensor's spectral
        grid: surface (what leaves the surface: reflected light, DownWelling
        and emission; the background light for the sky), downwelling (of
        which DownWelling / pi x SRF), transmittance (T_out), path_thermal
        (L_path), path_scatter (L_scatter) and at_sensor (surface x T_out +
        L_path + L_scatter, pick()'s spectral_radiance); radiances in
        W/(cm^2 sr um), plus wavelengths_um. In vacuum transmittance is 1 and
        the path terms 0."""
        code = _lookup(_PICK_SPACES, space, "pick space")
        if not isinstance(x, numbers.Integral) or not isinstance(y, numbers.Integral):
            raise TypeError("pick_terms: x and y are integer sample or pixel indices")
        if x < 0 or y < 0 or x > 0xFFFFFFFF or y > 0xFFFFFFFF:
            raise ValueError(f"pick_terms: x and y must be non-negative, got ({x}, {y})")
        s = encode(sensor, "sensor")
        out = {"wavelengths_um": self.pick(sensor, x, y, space)["wavelengths_um"]}
        n = c_size_t()
        for term, name in enumerate(PICK_TERMS):
            check(lib.eoir_pick_term_get(self.handle, s, code, int(x), int(y), term, None, 0, byref(n)))
            values = np.zeros(max(int(n.value), 1), dtype=np.float64)
            check(lib.eoir_pick_term_get(self.handle, s, code, int(x), int(y), term,
                                         values.ctypes.data_as(ctypes.POINTER(c_double)), values.size, byref(n)))
            out[name] = values[:int(n.value)].copy()
        return out


def _as_integer(value, prop: str) -> int:
    if isinstance(value, (bool, np.bool_)):
        return int(value)
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real) and float(value).is_integer():
        return int(value)
    raise TypeError(f"{prop}: expected an integer, got {value!r}")
