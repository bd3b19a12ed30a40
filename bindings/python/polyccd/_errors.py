"""Exceptions of polyccd and the one place that maps a C status to one of them.

The C library's messages read "pccd_function: PLACE: what is wrong" (polyccd.h, "Error
messages"), PLACE named as the Python arguments nest (points[1][0][2], radii[0],
translation[1][2], config.time_tolerance, ...). Every C error becomes an exception by
error_for(): the class from the status, the message the C message without its
"pccd_function: " prefix. Errors found in Python use the same "PLACE: what" form.
"""
from ._pccd import ffi, lib


class Error(Exception):
    """Base class of every error raised by polyccd."""


class InputError(Error, ValueError):
    """A bad input (PCCD_EINVAL): the message says what is wrong and where."""


class LimitError(InputError):
    """A documented size or degree limit was exceeded (PCCD_ELIMIT)."""


class InternalError(Error):
    """A bug in polyccd (PCCD_EINTERNAL, PCCD_ESTATE, an unexpected status).

    Please report it with the inputs that triggered it."""


def last_error():
    """The C library's message about the last failed call on this thread."""
    return ffi.string(lib.pccd_last_error()).decode("utf-8", "replace")


def error_for(rc, message):
    """The exception of status rc with the C message (its "pccd_function: " prefix
    dropped: Python callers know which call they made)."""
    function, sep, rest = message.partition(": ")
    text = rest if sep and function.startswith("pccd_") else message
    if rc == lib.PCCD_EINVAL:
        return InputError(text)
    if rc == lib.PCCD_ELIMIT:
        return LimitError(text)
    if rc == lib.PCCD_ENOMEM:
        return MemoryError(text)
    return InternalError(f"{text} (status {rc}; this is a bug in polyccd, please report it)")


def check(rc):
    """Raises the exception of a negative status; call right after the C call."""
    if rc != 0:
        raise error_for(rc, last_error())
