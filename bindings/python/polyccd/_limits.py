"""Work limits of one call (polyccd.Limits, polyccd.Cancel) and Ctrl-C for long calls.

The library checks the limits (pccd_config's max_seconds, max_work, cancel and
max_number_bits, polyccd.h); this module only converts them. A call that reaches one
raises LimitError with the library's message (which limit, how far the call got).

Ctrl-C: cffi releases the GIL around every C call, but Python runs its SIGINT handler
only between bytecodes, so without help a KeyboardInterrupt would wait for a long
check to end. run() points the extension's SIGINT shim (build_ffi.py) at the call's
pccd_cancel when it is made from the main thread and SIGINT has Python's default
handler: Ctrl-C then sets the flag, the call ends at its next work step, and Python
raises KeyboardInterrupt as it returns. (A Cancel passed in limits is the one set.)
"""
from __future__ import annotations

import math
import numbers
import signal
import threading
import warnings

from typing import Optional
from ._errors import InputError, check
from ._numbers import show
from ._pccd import ffi, lib
from . import _handles as handles


class Cancel:
    """A cancellation flag for running calls: set() (from any thread) makes the calls
    given it (Limits(cancel=...)) end with LimitError "config.cancel: the call was
    cancelled ..."; it stays set, and calls started with it end at once, until reset()."""

    __slots__ = ("_handle",)

    def __init__(self) -> None:
        self._handle = handles.new("cancel")

    def set(self) -> None:
        lib.pccd_cancel_set(self._handle)

    def reset(self) -> None:
        check(lib.pccd_cancel_reset(self._handle))

    @property
    def is_set(self) -> bool:
        out = ffi.new("int *")
        check(lib.pccd_cancel_is_set(self._handle, out))
        return bool(out[0])

    def __repr__(self):
        return f"Cancel(is_set={self.is_set})"


DEFAULT_MAX_NUMBER_BITS = lib.PCCD_DEFAULT_MAX_NUMBER_BITS


class Limits:
    """The limits of one call (polyccd.h, pccd_config): max_seconds (wall clock, None: no
    limit), max_work (work steps, a count that depends only on the inputs; None: no
    limit), cancel (a Cancel or None) and max_number_bits (the largest input number as
    a fraction, bits of numerator plus denominator; None: no limit). Raise
    max_number_bits to solve inputs with larger numbers."""

    __slots__ = ("max_seconds", "max_work", "cancel", "max_number_bits")

    def __init__(self, max_seconds: Optional[float] = None, max_work: Optional[int] = None,
                 cancel: Optional[Cancel] = None,
                 max_number_bits: Optional[int] = DEFAULT_MAX_NUMBER_BITS) -> None:
        if max_seconds is not None and (isinstance(max_seconds, bool) or
                                        not isinstance(max_seconds, (int, float)) or
                                        not math.isfinite(max_seconds) or max_seconds <= 0):
            raise InputError("limits.max_seconds: expected a finite number of seconds > 0 or "
                             f"None, got {show(max_seconds)}")
        for name, value in (("max_work", max_work), ("max_number_bits", max_number_bits)):
            if value is not None and (isinstance(value, bool) or not isinstance(value, int)
                                      or not 1 <= value < 2 ** 63):
                raise InputError(f"limits.{name}: expected a positive integer or None, "
                                 f"got {show(value)}")
        if cancel is not None and not isinstance(cancel, Cancel):
            raise InputError(f"limits.cancel: expected a polyccd.Cancel or None, got {show(cancel)}")
        self.max_seconds = max_seconds
        self.max_work = max_work
        self.cancel = cancel
        self.max_number_bits = max_number_bits

    def __reduce__(self):
        """Pickles the numbers (for Dask workers); a Cancel is this process's flag."""
        if self.cancel is not None:
            raise InputError("limits.cancel: a polyccd.Cancel belongs to one process and "
                             "cannot be sent to another")
        return Limits, (self.max_seconds, self.max_work, None, self.max_number_bits)

    def __repr__(self):
        return (f"Limits(max_seconds={self.max_seconds!r}, max_work={self.max_work!r}, "
                f"cancel={self.cancel!r}, max_number_bits={self.max_number_bits!r})")


def apply(cfg, limits):
    """Writes limits (a Limits or None: the defaults) into the pccd_config cfg."""
    if limits is None:
        return
    if not isinstance(limits, Limits):
        raise InputError(f"limits: expected a polyccd.Limits or None, got {show(limits)}")
    cfg.max_seconds = float(limits.max_seconds or 0)
    cfg.max_work = limits.max_work or 0
    cfg.cancel = limits.cancel._handle if limits.cancel is not None else ffi.NULL
    cfg.max_number_bits = limits.max_number_bits or 0


def config(limits):
    """A pccd_config of limits for the calls that had none before (Index, Motion.position,
    Motion.validate): None is no limit at all, not even the input limit (one config per
    thread, made once: run() only lends it the thread's Ctrl-C flag during a call)."""
    if limits is None:
        cfg = getattr(_unlimited, "cfg", None)
        if cfg is not None:
            return cfg
    cfg = ffi.new("pccd_config *")
    check(lib.pccd_config_init(cfg))
    if limits is None:
        cfg.max_number_bits = 0
        _unlimited.cfg = cfg
    apply(cfg, limits)
    return cfg


_unlimited = threading.local()


# The most threads a call takes, from polyccd.h (PCCD_MAX_THREADS; 1024 in headers
# older than that constant). Only for the ints a C unsigned cannot hold (thread_count).
_MAX_THREADS = getattr(lib, "PCCD_MAX_THREADS", 1024)


def thread_count(threads, place="opt.threads"):
    """opt.threads (a C unsigned) of a Python int: a conversion. Which counts are valid
    is the C library's rule (1..PCCD_MAX_THREADS, "opt.threads: 0 is outside 1..1024");
    the ints an unsigned cannot hold (negative, >= 2^32) never reach C, so they are
    refused here in the same words."""
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral):
        raise InputError(f"{place}: expected an integer, got {show(threads)}")
    if not 0 <= threads <= 0xFFFFFFFF:
        raise InputError(f"{place}: {int(threads)} is outside 1..{_MAX_THREADS}")
    return int(threads)


def usable_threads(requested: int) -> int:
    """How many worker threads a call asking for `requested` starts on this machine:
    min(requested, the hardware's thread count), at least 1 (pccd_threads_usable; no
    answer depends on the count). InputError when requested is outside
    1..PCCD_MAX_THREADS (1024), in the C library's words."""
    out = ffi.new("unsigned *")
    check(lib.pccd_threads_usable(thread_count(requested, "requested"), out))
    return int(out[0])


def warn_threads(threads, place="threads"):
    """Warns (RuntimeWarning, once per count) when threads exceeds what the library
    starts on this machine (pccd_threads_usable): the answers are the same, and the
    caller learns why the extra threads do not help. A count the library refuses is
    not warned about: the call itself raises the library's error."""
    if threads <= 1 or threads in _warned:
        return
    out = ffi.new("unsigned *")
    if lib.pccd_threads_usable(threads, out) != 0:
        return
    if out[0] < threads:
        _warned.add(threads)
        warnings.warn(f"{place}={threads}: this machine runs {out[0]} threads at once, so "
                      f"{out[0]} are used (the answers do not depend on it)", RuntimeWarning,
                      stacklevel=4)


_warned = set()
_get_ident, _main_ident = threading.get_ident, threading.main_thread().ident
_NULL = ffi.NULL
_shim = []  # [own flag, SIGINTs seen] once the shim is in front of Python's SIGINT handler


def _install():
    if signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        return False  # the program handles SIGINT itself: its handler decides
    if not lib.polyccd_py_sigint_install():
        return False
    _shim[:] = [lib.polyccd_py_own_flag(), lib.polyccd_py_hit_count()]
    return True


def run(cfg, fn, *args, **kwargs):
    """fn(*args, **kwargs), a C call that takes cfg, interruptible by Ctrl-C (see the top). On the
    main thread the call gets the shim's flag in cfg.cancel (or, when the caller gave a
    Cancel, the shim sets that one too). The shim is installed on the first call made
    while SIGINT has Python's default handler; a handler the program installs later
    replaces it (Ctrl-C then waits for the call, as without polyccd's help)."""
    if _get_ident() != _main_ident or (not _shim and not _install()):
        return fn(*args, **kwargs)
    own, seen = _shim
    hits = lib.polyccd_py_hit_count()
    if hits != seen:  # a Ctrl-C since the last call: its KeyboardInterrupt has been raised
        lib.pccd_cancel_reset(own)
        _shim[1] = hits
    if cfg.cancel == _NULL:
        cfg.cancel = own
        try:
            return fn(*args, **kwargs)
        finally:
            cfg.cancel = _NULL
    lib.polyccd_py_target_set(ffi.cast("pccd_cancel *", cfg.cancel))
    try:
        return fn(*args, **kwargs)
    finally:
        lib.polyccd_py_target_set(_NULL)
