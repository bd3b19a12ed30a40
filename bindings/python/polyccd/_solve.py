"""solve, solve_linear and collides_linear: convert the inputs, call C, raise or read.

No geometry here: every decision is the C library's. This module only checks shapes,
converts numbers exactly (see _numbers); the C library names the place of a bad number
(points[i][axis][coefficient], radii[which], p_t0[i][axis], config.time_tolerance).
"""
from __future__ import annotations

import threading

import numpy as np

from typing import TYPE_CHECKING, Optional, Sequence

from ._types import Coefficients, Number, Points

if TYPE_CHECKING:
    from ._limits import Limits
    from ._results import Result
from ._arrays import NotDouble, linear_coords, linear_trajectories
from . import _handles as handles
from . import _limits
from ._errors import InputError, check
from ._flags import flag
from ._numbers import number_text, show
from ._pccd import ffi, lib
from ._results import KINDS, read_result

_CODES = {kind: getattr(lib, "PCCD_" + kind.upper().replace("-", "_")) for kind in KINDS}


def _kind_points(code):
    count = ffi.new("size_t *")
    check(lib.pccd_kind_points(code, count))
    return count[0]


_NPOINTS = {kind: _kind_points(code) for kind, code in _CODES.items()}


def npoints(kind):
    """Number of points of a query of this kind (a name of KINDS)."""
    return _NPOINTS[kind]


def kind_points(kind: str) -> int:
    """Number of points of a query of this kind: 4 for "vertex-face" and "edge-edge",
    3 for "vertex-edge", 2 for "vertex-vertex" and "sphere-sphere" (pccd_kind_points).
    InputError for a name not in polyccd.KINDS."""
    kind_code(kind)  # InputError naming the kinds
    return _NPOINTS[kind]


def kind_code(kind):
    """The pccd_kind of a kind name, or InputError (a conversion: which kinds a call
    takes is the C library's rule, e.g. the linear calls refuse sphere-sphere)."""
    try:
        return _CODES[kind]
    except (KeyError, TypeError):
        raise InputError(f"kind: {show(kind)} is not one of {', '.join(_CODES)}") from None


def _items(value, place, what):
    """The items of a list-like value, or InputError."""
    if isinstance(value, (str, bytes, dict, set, frozenset)):  # a set has no order
        raise InputError(f"{place}: expected {what}, got {show(value)}")
    try:
        return list(value)
    except TypeError:
        raise InputError(f"{place}: expected {what}, got {show(value)}") from None


def _texts(texts):
    """A const char *[] of texts; the returned list keeps the strings alive."""
    keep = [ffi.new("char[]", t.encode("utf-8", "replace")) for t in texts]
    return ffi.new("const char *[]", keep) if keep else ffi.NULL, keep


class _Thread(threading.local):
    """Per-thread state of the linear entry points: configs cached by (tolerance,
    want_time, want_exact), the decide-only config of collides_linear, and one result
    handle that solve_linear and collides_linear reuse (each reads it completely before
    returning)."""

    def __init__(self):
        self.cache = {}
        self.res = handles.new("result")
        self.decide_cfg, _ = _config(None, False, True)
        self.out = ffi.new("int *")



def _cached_config(time_tolerance, want_time, want_exact, min_distance=None):
    try:
        key = (type(time_tolerance), time_tolerance, type(want_time), want_time, type(want_exact), want_exact,
               type(min_distance), min_distance)
        hit = _thread.cache.get(key)
    except TypeError:  # an unhashable argument: no caching (checked there)
        return _config(time_tolerance, want_time, want_exact, min_distance=min_distance)
    if hit is None:
        hit = _config(time_tolerance, want_time, want_exact, min_distance=min_distance)
        if len(_thread.cache) > 32:
            _thread.cache.clear()
        _thread.cache[key] = hit
    return hit


def _config(time_tolerance, want_time, want_exact, limits=None, min_distance=None):
    """(pccd_config, keep-alive) of the keyword arguments. The tolerance and the minimum
    distance are named by their C fields, config.time_tolerance and config.min_distance,
    here as in the library's messages."""
    cfg = ffi.new("pccd_config *")
    check(lib.pccd_config_init(cfg))
    _limits.apply(cfg, limits)
    keep = [limits]
    if min_distance is not None:
        text = number_text(min_distance, "config.min_distance")
        keep.append(ffi.new("char[]", text.encode("utf-8", "replace")))
        cfg.min_distance = keep[-1]
    if time_tolerance is not None:
        text = number_text(time_tolerance, "config.time_tolerance")
        keep.append(ffi.new("char[]", text.encode("utf-8", "replace")))
        cfg.time_tolerance = keep[-1]
    cfg.want_time = 1 if flag(want_time, "want_time") else 0
    cfg.want_exact = 1 if flag(want_exact, "want_exact") else 0
    return cfg, keep


_thread = _Thread()  # after _config, which its __init__ calls


def solve_query(kind, points, radii, time_tolerance, want_time, want_exact, limits=None,
                min_distance=None):
    """solve(), positional. Shapes are checked here; every number and index is checked
    by C, which names it as points[i][axis][coefficient] or radii[which]."""
    code = kind_code(kind)
    count = _NPOINTS[kind]
    query = handles.new("query", code)
    trajs = _items(points, "points", f"a list of {count} point trajectories")
    if len(trajs) != count:
        raise InputError(f"points: {kind} queries have {count} points, got {len(trajs)}")
    for i, traj in enumerate(trajs):
        axes = _items(traj, f"points[{i}]", "[xs, ys, zs] (3 coefficient lists)")
        if len(axes) != 3:
            raise InputError(f"points[{i}]: expected [xs, ys, zs] (3 coefficient lists), "
                             f"got {len(axes)} lists")
        for axis, coeffs in enumerate(axes):
            place = f"points[{i}][{axis}]"
            items = _items(coeffs, place, "a list of polynomial coefficients")
            array, _keep = _texts([number_text(c, f"{place}[{j}]") for j, c in enumerate(items)])
            check(lib.pccd_query_set_coord_s(query, i, axis, array, len(items)))
    if radii is not None:  # which kinds take radii, and that they are set: C's rules
        values = _items(radii, "radii", "(ra, rb)")
        if len(values) != 2:
            raise InputError(f"radii: expected 2 radii (ra, rb), got {len(values)}")
        for which, r in enumerate(values):
            text = number_text(r, f"radii[{which}]").encode("utf-8", "replace")
            check(lib.pccd_query_set_radius_s(query, which, text))
    cfg, keep = _config(time_tolerance, want_time, want_exact, limits, min_distance)
    res = handles.new("result")
    check(_limits.run(cfg, lib.pccd_query_solve, query, cfg, res))
    return read_result(res)


def solve(kind: str, points: Sequence[Sequence[Coefficients]],
          radii: Optional[Sequence[Number]] = None, *, time_tolerance: Number = "1e-12",
          want_time: bool = True, want_exact: bool = True, limits: Optional[Limits] = None,
          min_distance: Optional[Number] = None) -> Result:
    """Decides exactly whether the moving primitives touch during [0, 1]; see
    docs/python.md. points: one [xs, ys, zs] per point, ascending powers of t.
    limits: a polyccd.Limits (work limits, input limit) or None for the defaults.
    min_distance: delta >= 0: the first time the closed primitives are within delta."""
    return solve_query(kind, points, radii, time_tolerance, want_time, want_exact, limits,
                       min_distance)


def solve_linear(kind: str, p_t0: Points, p_t1: Points, *, time_tolerance: Number = "1e-12",
                 want_time: bool = True, want_exact: bool = True,
                 limits: Optional[Limits] = None, min_distance: Optional[Number] = None) -> Result:
    """solve() for points moving linearly from p_t0 (t = 0) to p_t1 (t = 1), arrays of
    shape (npoints, 3): float64 (exact binary values), integer or object arrays (int,
    Fraction, float) or nested lists; values that are not exactly doubles take the exact
    path (solve with the trajectories x0 + (x1 - x0) t), with the same answers."""
    code = kind_code(kind)
    try:
        a0 = linear_coords(p_t0, "p_t0", _NPOINTS[kind])
        a1 = linear_coords(p_t1, "p_t1", _NPOINTS[kind])
    except NotDouble:
        return solve_query(kind, linear_trajectories(p_t0, p_t1, _NPOINTS[kind]), None,
                           time_tolerance, want_time, want_exact, limits, min_distance)
    if limits is None:
        cfg, _keep = _cached_config(time_tolerance, want_time, want_exact, min_distance)
    else:
        cfg, _keep = _config(time_tolerance, want_time, want_exact, limits, min_distance)
    res = _thread.res
    check(lib.pccd_solve_linear_d(code, ffi.from_buffer("double[]", a0),
                                  ffi.from_buffer("double[]", a1), cfg, res))
    return read_result(res)


_ND, _F64 = np.ndarray, np.dtype(np.float64)
_FAST = {kind: (code, (_NPOINTS[kind], 3)) for kind, code in _CODES.items()}
_from_buffer, _solve_linear_d = ffi.from_buffer, lib.pccd_solve_linear_d


def collides_linear(kind: str, p_t0: Points, p_t1: Points) -> bool:
    """True when the primitives moving linearly from p_t0 to p_t1 touch during [0, 1].

    The low-overhead decide-only path for benchmarks: no Result is built, a per-thread
    result handle is reused, and C-contiguous float64 arrays of the right shape go to C
    without any copy (anything else goes through linear_coords, as in solve_linear)."""
    state = _thread
    try:
        code, shape = _FAST[kind]
    except (KeyError, TypeError):
        kind_code(kind)  # raises the right message
    try:
        if not (type(p_t0) is _ND and p_t0.dtype is _F64 and p_t0.shape == shape
                and p_t0.flags.c_contiguous):
            p_t0 = linear_coords(p_t0, "p_t0", shape[0])
        if not (type(p_t1) is _ND and p_t1.dtype is _F64 and p_t1.shape == shape
                and p_t1.flags.c_contiguous):
            p_t1 = linear_coords(p_t1, "p_t1", shape[0])
    except NotDouble:  # exact rationals: the exact path, decide only
        return solve_query(kind, linear_trajectories(p_t0, p_t1, shape[0]), None, None,
                           False, False).collides
    rc = _solve_linear_d(code, _from_buffer("double[]", p_t0), _from_buffer("double[]", p_t1),
                         state.decide_cfg, state.res)
    if rc != 0:
        check(rc)
    check(lib.pccd_result_collides(state.res, state.out))
    return state.out[0] != 0
