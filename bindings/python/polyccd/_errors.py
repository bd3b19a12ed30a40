"""Exceptions of polyccd and the one place that maps a C status to one of them."""
import re

from ._pccd import ffi, lib

# The C library writes "pccd_function: where: what". When the bindings know the place in
# the caller's own terms (points[1][2][0], radii[0], ...), they keep only "what".
_C_PLACE = re.compile(r"^pccd_\w+: (?:point \d+ [xyz] coefficient \d+: |point \d+ axis \d+: "
                      r"|radius \d+: |config\.time_tolerance: )?")


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


def error_for(rc, message, place=None):
    """The exception for status `rc`, its message prefixed with `place` when given."""
    text = f"{place}: {_C_PLACE.sub('', message, count=1)}" if place else message
    if rc == lib.PCCD_EINVAL:
        return InputError(text)
    if rc == lib.PCCD_ELIMIT:
        return LimitError(text)
    if rc == lib.PCCD_ENOMEM:
        return MemoryError(text)
    return InternalError(f"{text} (status {rc}; this is a bug in polyccd, please report it)")


def check(rc, place=None):
    """Raises the exception of a negative status; call right after the C call."""
    if rc != 0:
        raise error_for(rc, last_error(), place)
