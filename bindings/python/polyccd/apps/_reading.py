"""The command line's --max-seconds over reading a file and building its bodies, not only
over the solve (issue 23: a 38 MB scene read for 63 s under --max-seconds 5).

deadline(seconds) opens a time limit for this thread; the readers call tick() for every
number, point and triangle they convert (the clock is read once per 4,096 ticks, so
reading stays as fast), and LimitError ends the reading with the C library's wording;
left() is the time the solve may still take."""
import threading
import time
from contextlib import contextmanager

from .. import LimitError, Limits

_EVERY = 4096
_state = threading.local()


@contextmanager
def deadline(seconds):
    """A time limit of `seconds` (None or 0: none) for the reading in this block."""
    _state.limit = seconds or None
    _state.start = time.monotonic()
    _state.count = 0
    try:
        yield
    finally:
        _state.limit = None


def tick():
    """One unit of reading; LimitError when the time limit is over."""
    limit = getattr(_state, "limit", None)
    if limit is None:
        return
    _state.count += 1
    if _state.count % _EVERY == 0:
        spent = time.monotonic() - _state.start
        if spent >= limit:
            raise LimitError(f"config.max_seconds: the time limit of {limit:g} s was reached "
                             f"while reading the file (after {spent:.3g} s); no answer")


def left(seconds):
    """What remains of `seconds` for the solve (at least a millisecond, so that a limit
    stays a limit); `seconds` itself outside a deadline."""
    limit = getattr(_state, "limit", None)
    if not seconds or limit is None:
        return seconds
    return max(seconds - (time.monotonic() - _state.start), 1e-3)


def read_within(read, path, limits):
    """(read(path), the limits left for the solve): limits.max_seconds (a polyccd.Limits,
    or None) covers the reading and the solve together."""
    seconds = limits.max_seconds if limits is not None else None
    with deadline(seconds):
        value = read(path)
        if seconds:
            limits = Limits(max_seconds=left(seconds), max_work=limits.max_work,
                            max_number_bits=limits.max_number_bits)
    return value, limits
