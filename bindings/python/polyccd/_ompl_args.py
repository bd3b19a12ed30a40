"""Argument conversions of polyccd.ompl (issue 33): each public function and method of
RobotSpace converts its arguments here, so a wrong one is an InputError naming it
rather than a TypeError from numpy or OMPL's bindings. Only types and shapes: what the
values mean (joint limits, a segment's turn) is Robot.check's and the C library's."""
import math

import numpy as np

from ._arrays import _float64_array
from ._errors import InputError
from ._flags import real
from ._numbers import show
from ._solve import _items


def vector(value, place, n=None):
    """A float64 (n,) array of finite real numbers (n None: any length)."""
    a = _float64_array(value, place, f"({'n' if n is None else n},)",
                       lambda s: len(s) == 1 and (n is None or s[0] == n))
    bad = np.flatnonzero(~np.isfinite(a))
    if len(bad):
        raise InputError(f"{place}[{bad[0]}]: {a[bad[0]]!r} is not a finite number")
    return a


def mask(value, place):
    """A bool (n,) array (True / False values only)."""
    try:
        a = np.asarray(value) if not isinstance(value, (str, bytes, dict, set)) else None
    except (ValueError, TypeError):  # ragged
        a = None
    if a is None or a.ndim != 1 or (a.size and a.dtype.kind != "b"):
        raise InputError(f"{place}: expected a 1-D sequence of True / False, got {show(value)}")
    return a.astype(bool)


def times(value, place="t"):
    """t of joint_path: a number or a 1-D array of numbers in [0, 1]."""
    a = _float64_array(value, place, "a number or (m,)", lambda s: len(s) <= 1)
    if not np.all((a >= 0) & (a <= 1)):
        raise InputError(f"{place}: expected times in [0, 1], got {show(value)}")
    return a


def time(value, place="t"):
    """One time in [0, 1] (a real number)."""
    t = real(value, place)
    if not 0 <= t <= 1:
        raise InputError(f"{place}: expected a time in [0, 1], got {show(value)}")
    return t


def state(value, place, ob):
    """An OMPL state (ompl.base.State)."""
    if not isinstance(value, ob.State):
        raise InputError(f"{place}: expected an OMPL state (ompl.base.State), got {show(value)}")
    return value


def optional_state(value, place, ob):
    return None if value is None else state(value, place, ob)


def space(value, place, robot_space):
    """A polyccd.ompl.RobotSpace (what the OMPL validator classes are made for)."""
    if not isinstance(value, robot_space):
        raise InputError(f"{place}: expected a polyccd.ompl.RobotSpace, got {show(value)}")
    return value


def last_valid(value, place, ob):
    """OMPL's last-valid pair for MotionValidator.checkMotion: None, or a list
    [state or None, fraction] that the check fills in."""
    if value is None:
        return None
    if not isinstance(value, list) or len(value) != 2:
        raise InputError(f"{place}: expected None or a list [state or None, fraction], got {show(value)}")
    optional_state(value[0], f"{place}[0]", ob)
    return value


def names(value, place):
    """A list of joint names (strings)."""
    out = _items(value, place, "a list of joint names")
    for k, x in enumerate(out):
        if not isinstance(x, str):
            raise InputError(f"{place}[{k}]: expected a joint name, got {show(x)}")
    return out


def interval(value, place):
    """(lo, hi), finite reals with lo <= hi."""
    pair = _items(value, place, "a pair (lo, hi)")
    if len(pair) != 2:
        raise InputError(f"{place}: expected a pair (lo, hi), got {show(value)}")
    lo, hi = real(pair[0], f"{place}[0]"), real(pair[1], f"{place}[1]")
    if not (math.isfinite(lo) and math.isfinite(hi) and lo <= hi):
        raise InputError(f"{place}: expected finite lo <= hi, got {show(value)}")
    return lo, hi


def joint_map(value, place, convert):
    """{joint name: convert(value, place[name])} of a dict (None: empty)."""
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise InputError(f"{place}: expected a dict {{joint name: value}}, got {show(value)}")
    out = {}
    for k, x in value.items():
        if not isinstance(k, str):
            raise InputError(f"{place}: expected joint names as keys, got {show(k)}")
        out[k] = convert(x, f"{place}[{k!r}]")
    return out


def count(value, place, low=0):
    """An int >= low (not a bool)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        raise InputError(f"{place}: expected an integer >= {low}, got {show(value)}")
    return int(value)


def positive(value, place):
    x = real(value, place)
    if not (math.isfinite(x) and x > 0):
        raise InputError(f"{place}: expected a positive finite number, got {show(value)}")
    return x


def instance(value, place, cls, what):
    if not isinstance(value, cls):
        raise InputError(f"{place}: expected {what}, got {show(value)}")
    return value
