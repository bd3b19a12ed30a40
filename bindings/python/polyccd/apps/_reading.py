"""The command line's --max-seconds over reading a file and building its bodies, not only
over the solve (issue 23: a 38 MB scene read for 63 s under --max-seconds 5).

deadline(seconds) opens a time limit for this thread; the readers call tick() for every
number, point and triangle they convert (the clock is read once per 4,096 ticks, so
reading stays as fast), and LimitError ends the reading with the C library's wording;
left() is the time the solve may still take.

read_bytes(path) reads a whole file within the reading limit on its size: a JSON file
takes about 48 times its size in memory once read (a 46 MB scene of 1.5 million
numbers peaked at 2.24 GB in `polyccd check`; issue 23: 1.78 GB for 38 MB), so the
default of 32 MiB bounds a reading near 1.6 GB (--max-file-mb raises it)."""
import os
import threading
import time
from contextlib import contextmanager

from .. import InputError, LimitError, Limits

DEFAULT_MAX_FILE_MB = 32
max_file_bytes = DEFAULT_MAX_FILE_MB << 20  # the command line's --max-file-mb (0: none)


def read_bytes(path):
    """The bytes of the file at path; InputError when it is unreadable or larger than
    max_file_bytes (never read whole then: a pipe without a size is read up to it)."""
    limit = max_file_bytes
    try:
        with open(path, "rb") as f:
            size = os.fstat(f.fileno()).st_size
            data = b"" if limit and size > limit else f.read(limit + 1 if limit else -1)
    except OSError as e:
        raise InputError(f"cannot read the file: {e.strerror}") from None
    if limit and max(size, len(data)) > limit:
        what = f"{size:,} bytes, more" if size > limit else "more"
        raise InputError(f"the file has {what} than the reading limit of {limit:,} bytes "
                         f"(--max-file-mb {limit >> 20}: reading takes about 48 times a "
                         f"file's size in memory); raise it to read this file")
    return data

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
