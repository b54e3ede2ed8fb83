"""Exceptions raised by the eoir bindings.

Every failing C call raises a subclass of :class:`EoirError` chosen by its
status code; the classes follow the gapped status blocks of ``eoir.h``::

    EoirError
    +-- ArgumentError        (-100 block: the call's arguments)
    |   +-- NullArgumentError, StructSizeError, OutOfRangeError,
    |       UnknownNameError, TypeMismatchError, BufferTooSmallError
    +-- UniverseError        (-200 block: the modeled universe)
    |   +-- LimitExceededError, AlreadyExistsError, NotAllowedError,
    |       NoStateError
    +-- FileError            (-300 block: files)
    |   +-- FileIOError, CorruptFileError, FileVersionError
    +-- PluginError          (-400 block)
    |   +-- AbiMismatchError
    +-- HostRequestError     (-500 block)
    |   +-- CancelledError
    +-- InternalError        (-900 block)
"""

from __future__ import annotations

__all__ = [
    "EoirError",
    "ArgumentError",
    "NullArgumentError",
    "StructSizeError",
    "OutOfRangeError",
    "UnknownNameError",
    "TypeMismatchError",
    "BufferTooSmallError",
    "UniverseError",
    "LimitExceededError",
    "AlreadyExistsError",
    "NotAllowedError",
    "NoStateError",
    "FileError",
    "FileIOError",
    "CorruptFileError",
    "FileVersionError",
    "PluginError",
    "AbiMismatchError",
    "HostRequestError",
    "CancelledError",
    "InternalError",
    "error_class",
]


class EoirError(Exception):
    """A failing EOIR C call.

    Attributes:
        status: the negative ``eoir_status`` code (e.g. -102).
        status_name: its symbolic name (e.g. ``"EOIR_ERR_OUT_OF_RANGE"``).
        message: ``eoir_last_error()`` right after the failing call.
    """

    def __init__(self, status: int, status_name: str, message: str):
        super().__init__(status, status_name, message)
        self.status = int(status)
        self.status_name = str(status_name)
        self.message = str(message)

    def __str__(self) -> str:
        text = self.message
        # The library may already start its message with the status name.
        if text.startswith(self.status_name + ":"):
            text = text[len(self.status_name) + 1:].lstrip()
        if text:
            return f"{self.status_name} ({self.status}): {text}"
        return f"{self.status_name} ({self.status})"


class ArgumentError(EoirError):
    """-100 block: the call's arguments."""


class NullArgumentError(ArgumentError):
    """EOIR_ERR_NULL_ARGUMENT: a required pointer is NULL."""


class StructSizeError(ArgumentError):
    """EOIR_ERR_STRUCT_SIZE: struct_size too small or zero."""


class OutOfRangeError(ArgumentError, ValueError):
    """EOIR_ERR_OUT_OF_RANGE: NaN, infinite, negative, reversed..."""


class UnknownNameError(ArgumentError, LookupError):
    """EOIR_ERR_UNKNOWN_NAME: unknown object, property, group, element..."""

    # LookupError/KeyError would otherwise quote the message oddly.
    __str__ = EoirError.__str__


class TypeMismatchError(ArgumentError, TypeError):
    """EOIR_ERR_TYPE_MISMATCH: property read or written with the wrong type."""


class BufferTooSmallError(ArgumentError):
    """EOIR_ERR_BUFFER_TOO_SMALL (normally handled inside the bindings)."""


class UniverseError(EoirError):
    """-200 block: the modeled universe."""


class LimitExceededError(UniverseError):
    """EOIR_ERR_LIMIT_EXCEEDED: compile-time object limit reached."""


class AlreadyExistsError(UniverseError):
    """EOIR_ERR_ALREADY_EXISTS: an object of that name exists."""


class NotAllowedError(UniverseError):
    """EOIR_ERR_NOT_ALLOWED: e.g. removing the Sun."""


class NoStateError(UniverseError):
    """EOIR_ERR_NO_STATE: the object has no state at the engine time."""


class FileError(EoirError):
    """-300 block: files."""


class FileIOError(FileError):
    """EOIR_ERR_IO: cannot open, write or rename."""


class CorruptFileError(FileError):
    """EOIR_ERR_CORRUPT_FILE: not JSON, truncated, wrong field type..."""


class FileVersionError(FileError):
    """EOIR_ERR_FILE_VERSION: written by a newer format version."""


class PluginError(EoirError):
    """-400 block: plugin negotiation."""


class AbiMismatchError(PluginError):
    """EOIR_ERR_ABI_MISMATCH."""


class HostRequestError(EoirError):
    """-500 block: the host's requests."""


class CancelledError(HostRequestError):
    """EOIR_ERR_CANCELLED: the host's progress callback asked to stop."""


class InternalError(EoirError):
    """EOIR_ERR_INTERNAL: a bug in the library; please report it."""


_BY_STATUS = {
    -100: NullArgumentError,
    -101: StructSizeError,
    -102: OutOfRangeError,
    -103: UnknownNameError,
    -104: TypeMismatchError,
    -105: BufferTooSmallError,
    -200: LimitExceededError,
    -201: AlreadyExistsError,
    -202: NotAllowedError,
    -203: NoStateError,
    -300: FileIOError,
    -301: CorruptFileError,
    -302: FileVersionError,
    -400: AbiMismatchError,
    -500: CancelledError,
    -900: InternalError,
}

_BY_BLOCK = {
    -100: ArgumentError,
    -200: UniverseError,
    -300: FileError,
    -400: PluginError,
    -500: HostRequestError,
    -900: InternalError,
}


def error_class(status: int) -> type:
    """The exception class for a status code (block class for unknown codes)."""
    status = int(status)
    cls = _BY_STATUS.get(status)
    if cls is not None:
        return cls
    # Codes added later in a known block map to that block's class.
    block = -((-status) // 100 * 100) if status < 0 else 0
    return _BY_BLOCK.get(block, EoirError)
