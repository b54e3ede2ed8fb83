"""The plugin entry point's function table, reached through ctypes."""

import ctypes

import pytest

import eoir
from eoir import _lib


def test_plugin_entry_major_1_table():
    api = ctypes.c_void_p()
    status = _lib.lib.eoir_plugin_entry(1, None, ctypes.byref(api))
    assert status == 0, eoir.last_error()
    table = ctypes.cast(api, ctypes.POINTER(_lib.eoir_api_v1)).contents
    assert table.struct_size >= ctypes.sizeof(_lib.eoir_api_v1)
    assert table.abi_major == 1
    assert table.version() == eoir.version()
    assert table.status_name(-102) == b"EOIR_ERR_OUT_OF_RANGE"
    # The table drives an engine like the exported functions do.
    engine = _lib.eoir_engine()
    assert table.engine_create(None, ctypes.byref(engine)) == 0
    try:
        n = ctypes.c_size_t()
        assert table.object_count(engine, ctypes.byref(n)) == 0
        assert n.value == 1  # the Sun
    finally:
        table.engine_destroy(engine)


def test_plugin_entry_other_major_is_abi_mismatch():
    api = ctypes.c_void_p()
    status = _lib.lib.eoir_plugin_entry(2, None, ctypes.byref(api))
    assert status == -400
    with pytest.raises(eoir.AbiMismatchError):
        _lib.check(status)


# The library copies the host table (callback pointers included) for the
# process: keep the ctypes callbacks alive for good.
_KEEP_ALIVE = []


def test_host_api_struct_accepted():
    logs = []
    host = _lib.eoir_host_api()
    host.struct_size = ctypes.sizeof(host)
    host.log = _lib.eoir_log_fn(lambda user, level, msg: logs.append((level, msg)))
    host.progress = _lib.eoir_progress_fn(lambda user, fraction, what: 0)
    _KEEP_ALIVE.append((host.log, host.progress))
    api = ctypes.c_void_p()
    try:
        assert _lib.lib.eoir_plugin_entry(1, ctypes.byref(host), ctypes.byref(api)) == 0
        assert api.value
    finally:
        # Hand the library a table without callbacks again.
        empty = _lib.eoir_host_api()
        empty.struct_size = ctypes.sizeof(empty)
        assert _lib.lib.eoir_plugin_entry(1, ctypes.byref(empty), ctypes.byref(api)) == 0
