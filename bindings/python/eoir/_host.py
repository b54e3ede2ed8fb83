"""ctypes declarations of libeoir_host (plugin_host/hostlib/eoir_host.h): the
eoir CLI's scenario, motion and session code, shared with eoir.Scenario.

The library is found, in order, at the path in ``EOIR_HOST_LIBRARY``; beside
the engine library the package loaded (``libeoir_host.so.1`` in the same
folder: ``build/lib`` or an installed ``lib``); ``ctypes.util.find_library``.
It is loaded on first use, so ``import eoir`` works without it.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
from ctypes import POINTER, c_char_p, c_double, c_int32, c_int64, c_size_t, c_uint32, c_uint64, c_void_p
from pathlib import Path

from . import _lib

_SIGNATURES = {
    "eoir_host_version": (c_uint32, []),
    "eoir_host_last_error": (c_char_p, []),
    "eoir_host_session_open": (c_int32, [c_char_p, c_char_p, c_uint64, c_uint32, POINTER(c_void_p)]),
    "eoir_host_session_open_with": (c_int32, [c_char_p, c_char_p, c_uint64, c_uint32, c_uint32, POINTER(c_void_p)]),
    "eoir_host_session_close": (None, [c_void_p]),
    "eoir_host_session_engine": (c_void_p, [c_void_p]),
    "eoir_host_session_library": (c_char_p, [c_void_p]),
    "eoir_host_session_describe": (c_int32, [c_void_p, c_char_p, c_size_t, POINTER(c_size_t)]),
    "eoir_host_session_times": (c_int32, [c_void_p, c_char_p, c_char_p, c_double, c_char_p, c_size_t,
                                          POINTER(c_size_t)]),
    "eoir_host_session_set_time": (c_int32, [c_void_p, c_char_p]),
    "eoir_host_session_fits_header": (c_int32, [c_void_p, c_char_p, c_int32, c_int64, c_char_p, c_size_t,
                                                POINTER(c_size_t)]),
    "eoir_host_session_truth": (c_int32, [c_void_p, c_char_p, c_char_p, c_size_t, POINTER(c_size_t)]),
    "eoir_host_tle_state": (c_int32, [c_char_p, c_char_p, c_char_p] + [POINTER(c_double * 3)] * 4),
}

ALLOW_PATHS_OUTSIDE = 1  # EOIR_HOST_ALLOW_PATHS_OUTSIDE

_NAMES = ("libeoir_host.so.1", "libeoir_host.so")
_host = None
host_library_path = None


def _candidates():
    env = os.environ.get("EOIR_HOST_LIBRARY")
    if env:
        yield env
        return
    beside = Path(_lib.library_path).resolve().parent
    for name in _NAMES:
        p = beside / name
        if p.exists():
            yield str(p)
    found = ctypes.util.find_library("eoir_host")
    if found:
        yield found


def host():
    """The loaded libeoir_host (ImportError if there is none)."""
    global _host, host_library_path
    if _host is not None:
        return _host
    tried = []
    for path in _candidates():
        try:
            h = ctypes.CDLL(path)
        except OSError as exc:
            tried.append(f"{path}: {exc}")
            continue
        for name, (restype, argtypes) in _SIGNATURES.items():
            f = getattr(h, name)
            f.restype = restype
            f.argtypes = argtypes
        _host, host_library_path = h, path
        return h
    raise ImportError("eoir: cannot load libeoir_host.so.1 (the CLI's scenario code; build the CMake target "
                      "'eoir_host' or set EOIR_HOST_LIBRARY): " + ("; ".join(tried) or "no candidate found"))


def check(status: int) -> None:
    if status < 0:
        message = _lib.decode(host().eoir_host_last_error())
        cls = _lib.errors.error_class(status)
        raise cls(status, _lib.status_name(status), message)


def json_out(call, *args) -> str:
    """Calls f(*args, buffer, capacity, &needed), growing the buffer."""
    needed = c_size_t(0)
    size = 4096
    while True:
        buf = ctypes.create_string_buffer(size)
        status = call(*args, buf, size, ctypes.byref(needed))
        if status == _lib.EOIR_ERR_BUFFER_TOO_SMALL and needed.value > size:
            size = needed.value
            continue
        check(status)
        return buf.value.decode("utf-8")
