"""Named constants of the C ABI's enums (eoir.h), for hosts that prefer names
the type checker knows to strings: ``engine.add_object(eoir.Kind.SATELLITE,
"Sat")``, ``engine.get_state("Sat", frame=eoir.FRAME_EARTH_FIXED)``.

Each enum is an :class:`enum.IntEnum` with the values of eoir.h, and each
member is also a module constant named as in eoir.h without its ``EOIR_``
(``EOIR_KIND_SATELLITE`` is ``eoir.KIND_SATELLITE``, ``eoir.Kind.SATELLITE``).
Every call that takes a kind, frame, time scale or image kind accepts the
member, its integer or its lower-case name ("satellite").
"""

from __future__ import annotations

import enum

from . import _lib


class Kind(enum.IntEnum):
    """eoir_object_kind."""
    CENTRAL_BODY = _lib.EOIR_KIND_CENTRAL_BODY
    STAR_FIELD = _lib.EOIR_KIND_STAR_FIELD
    SATELLITE = _lib.EOIR_KIND_SATELLITE
    AIRCRAFT = _lib.EOIR_KIND_AIRCRAFT
    GROUND_VEHICLE = _lib.EOIR_KIND_GROUND_VEHICLE
    MISSILE = _lib.EOIR_KIND_MISSILE
    SENSOR = _lib.EOIR_KIND_SENSOR
    SITE = _lib.EOIR_KIND_SITE


class Frame(enum.IntEnum):
    """eoir_frame: the frame of a state (set_state, get_state)."""
    J2000 = _lib.EOIR_FRAME_J2000
    EARTH_FIXED = _lib.EOIR_FRAME_EARTH_FIXED
    GEODETIC = _lib.EOIR_FRAME_GEODETIC
    GEODETIC_NED = _lib.EOIR_FRAME_GEODETIC_NED


class TimeScale(enum.IntEnum):
    """eoir_time_scale."""
    UTC = _lib.EOIR_TIME_UTC
    TAI = _lib.EOIR_TIME_TAI
    TT = _lib.EOIR_TIME_TT
    TDB = _lib.EOIR_TIME_TDB


class ImageKind(enum.IntEnum):
    """eoir_image_kind: the images of a rendered frame (Engine.image)."""
    SCENE_RADIANCE = _lib.EOIR_IMAGE_SCENE_RADIANCE
    SCENE_DISPLAY = _lib.EOIR_IMAGE_SCENE_DISPLAY
    SENSOR_ELECTRONS = _lib.EOIR_IMAGE_SENSOR_ELECTRONS
    SENSOR_MEAN = _lib.EOIR_IMAGE_SENSOR_MEAN
    SENSOR_DISPLAY = _lib.EOIR_IMAGE_SENSOR_DISPLAY
    SENSOR_ADU = _lib.EOIR_IMAGE_SENSOR_ADU


KIND_CENTRAL_BODY = Kind.CENTRAL_BODY
KIND_STAR_FIELD = Kind.STAR_FIELD
KIND_SATELLITE = Kind.SATELLITE
KIND_AIRCRAFT = Kind.AIRCRAFT
KIND_GROUND_VEHICLE = Kind.GROUND_VEHICLE
KIND_MISSILE = Kind.MISSILE
KIND_SENSOR = Kind.SENSOR
KIND_SITE = Kind.SITE

FRAME_J2000 = Frame.J2000
FRAME_EARTH_FIXED = Frame.EARTH_FIXED
FRAME_GEODETIC = Frame.GEODETIC
FRAME_GEODETIC_NED = Frame.GEODETIC_NED

TIME_UTC = TimeScale.UTC
TIME_TAI = TimeScale.TAI
TIME_TT = TimeScale.TT
TIME_TDB = TimeScale.TDB

IMAGE_SCENE_RADIANCE = ImageKind.SCENE_RADIANCE
IMAGE_SCENE_DISPLAY = ImageKind.SCENE_DISPLAY
IMAGE_SENSOR_ELECTRONS = ImageKind.SENSOR_ELECTRONS
IMAGE_SENSOR_MEAN = ImageKind.SENSOR_MEAN
IMAGE_SENSOR_DISPLAY = ImageKind.SENSOR_DISPLAY
IMAGE_SENSOR_ADU = ImageKind.SENSOR_ADU

__all__ = [
    "Kind", "Frame", "TimeScale", "ImageKind",
    "KIND_CENTRAL_BODY", "KIND_STAR_FIELD", "KIND_SATELLITE", "KIND_AIRCRAFT", "KIND_GROUND_VEHICLE",
    "KIND_MISSILE", "KIND_SENSOR", "KIND_SITE",
    "FRAME_J2000", "FRAME_EARTH_FIXED", "FRAME_GEODETIC", "FRAME_GEODETIC_NED",
    "TIME_UTC", "TIME_TAI", "TIME_TT", "TIME_TDB",
    "IMAGE_SCENE_RADIANCE", "IMAGE_SCENE_DISPLAY", "IMAGE_SENSOR_ELECTRONS", "IMAGE_SENSOR_MEAN",
    "IMAGE_SENSOR_DISPLAY", "IMAGE_SENSOR_ADU",
]
