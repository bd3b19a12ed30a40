"""solve, solve_linear and collides_linear: convert the inputs, call C, raise or read.

No geometry here: every decision is the C library's. This module only checks shapes,
converts numbers exactly (see _numbers) and names the place of a bad input.
"""
import threading

import numpy as np

from ._arrays import linear_coords
from ._errors import InputError, check, error_for, last_error
from ._numbers import number_text, show
from ._pccd import ffi, lib
from ._results import KINDS, read_result

_CODES = {kind: getattr(lib, "PCCD_" + kind.upper().replace("-", "_")) for kind in KINDS}
_LINEAR = {kind: code for kind, code in _CODES.items() if kind != "sphere-sphere"}


def _kind_points(code):
    count = ffi.new("size_t *")
    check(lib.pccd_kind_points(code, count))
    return count[0]


_NPOINTS = {kind: _kind_points(code) for kind, code in _CODES.items()}


def npoints(kind):
    """Number of points of a query of this kind (a name of KINDS)."""
    return _NPOINTS[kind]


def kind_code(kind, linear=False):
    """The pccd_kind of a kind name, or InputError."""
    table = _LINEAR if linear else _CODES
    try:
        return table[kind]
    except (KeyError, TypeError):
        pass
    if linear and kind == "sphere-sphere":
        raise InputError("kind: sphere-sphere queries need radii: use polyccd.solve")
    raise InputError(f"kind: {show(kind)} is not one of {', '.join(table)}")


def _items(value, place, what):
    """The items of a list-like value, or InputError."""
    if isinstance(value, (str, bytes, dict)):
        raise InputError(f"{place}: expected {what}, got {show(value)}")
    try:
        return list(value)
    except TypeError:
        raise InputError(f"{place}: expected {what}, got {show(value)}") from None


def _new(kind_of_handle, *args):
    out = ffi.new(f"pccd_{kind_of_handle} **")
    check(getattr(lib, f"pccd_{kind_of_handle}_new")(out, *args))
    return ffi.gc(out[0], getattr(lib, f"pccd_{kind_of_handle}_free"))


def _texts(texts):
    """A const char *[] of texts; the returned list keeps the strings alive."""
    keep = [ffi.new("char[]", t.encode("utf-8", "replace")) for t in texts]
    return ffi.new("const char *[]", keep) if keep else ffi.NULL, keep


def _set_coord(query, code, i, axis, texts, place):
    array, keep = _texts(texts)
    rc = lib.pccd_query_set_coord_s(query, i, axis, array, len(texts))
    if rc == 0:
        return
    message = last_error()
    # Which coefficient? The shortest failing prefix, on a scratch query (error path only).
    scratch = _new("query", code)
    for m in range(1, min(len(texts), lib.PCCD_MAX_TRAJ_DEGREE + 1) + 1):
        array, keep = _texts(texts[:m])
        rc_m = lib.pccd_query_set_coord_s(scratch, i, axis, array, m)
        if rc_m != 0:
            raise error_for(rc_m, last_error(), f"{place}[{m - 1}]")
    raise error_for(rc, message, place)


class _Thread(threading.local):
    """Per-thread state of the linear entry points: configs cached by (tolerance,
    want_time, want_exact), the decide-only config of collides_linear, and one result
    handle that solve_linear and collides_linear reuse (each reads it completely before
    returning)."""

    def __init__(self):
        self.cache = {}
        self.res = _new("result")
        self.decide_cfg, _ = _config(None, False, True, "time_tolerance")
        self.out = ffi.new("int *")



def _cached_config(time_tolerance, want_time, want_exact, place):
    try:
        key = (type(time_tolerance), time_tolerance, bool(want_time), bool(want_exact))
        hit = _thread.cache.get(key)
    except TypeError:  # an unhashable tolerance: no caching
        return _config(time_tolerance, want_time, want_exact, place)
    if hit is None:
        hit = _config(time_tolerance, want_time, want_exact, place)
        if len(_thread.cache) > 32:
            _thread.cache.clear()
        _thread.cache[key] = hit
    return hit


def _config(time_tolerance, want_time, want_exact, place):
    cfg = ffi.new("pccd_config *")
    check(lib.pccd_config_init(cfg))
    keep = None
    if time_tolerance is not None:
        keep = ffi.new("char[]", number_text(time_tolerance, place).encode("utf-8", "replace"))
        cfg.time_tolerance = keep
    cfg.want_time = 1 if want_time else 0
    cfg.want_exact = 1 if want_exact else 0
    return cfg, keep


_thread = _Thread()  # after _config, which its __init__ calls


def _solve_error(rc, message, cfg, tolerance_place, radii=None):
    """Raises the error of a failed solve. The place of a bad time tolerance or radius
    is found by solving small valid queries that differ only in it (error path only)."""
    if rc == lib.PCCD_EINVAL and cfg.time_tolerance != ffi.NULL:
        probe = _new("query", lib.PCCD_VERTEX_VERTEX)
        if lib.pccd_query_solve(probe, cfg, _new("result")) != 0:
            raise error_for(rc, last_error(), tolerance_place)
    if rc == lib.PCCD_EINVAL and radii:
        for which, text in enumerate(radii):
            probe = _new("query", lib.PCCD_SPHERE_SPHERE)
            check(lib.pccd_query_set_radius_s(probe, 1 - which, b"1"))
            check(lib.pccd_query_set_radius_s(probe, which, text))
            if lib.pccd_query_solve(probe, ffi.NULL, _new("result")) != 0:
                raise error_for(rc, last_error(), f"radii[{which}]")
    raise error_for(rc, message)


def solve_query(kind, points, radii, time_tolerance, want_time, want_exact,
                tolerance_place="time_tolerance"):
    """solve(), with the name of the tolerance's place for error messages."""
    code = kind_code(kind)
    count = _NPOINTS[kind]
    query = _new("query", code)
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
            texts = [number_text(c, f"{place}[{j}]") for j, c in enumerate(items)]
            _set_coord(query, code, i, axis, texts, place)
    radius_texts = []
    if kind == "sphere-sphere":
        if radii is None:
            raise InputError("radii: a sphere-sphere query needs radii (ra, rb)")
        values = _items(radii, "radii", "(ra, rb)")
        if len(values) != 2:
            raise InputError(f"radii: expected 2 radii (ra, rb), got {len(values)}")
        for which, r in enumerate(values):
            text = number_text(r, f"radii[{which}]").encode("utf-8", "replace")
            check(lib.pccd_query_set_radius_s(query, which, text), f"radii[{which}]")
            radius_texts.append(text)
    elif radii is not None:
        raise InputError(f"radii: only sphere-sphere queries have radii, not {kind}")
    cfg, keep = _config(time_tolerance, want_time, want_exact, tolerance_place)
    res = _new("result")
    rc = lib.pccd_query_solve(query, cfg, res)
    if rc != 0:
        _solve_error(rc, last_error(), cfg, tolerance_place, radius_texts)
    return read_result(res)


def solve(kind, points, radii=None, *, time_tolerance="1e-12", want_time=True,
          want_exact=True):
    """Decides exactly whether the moving primitives touch during [0, 1]; see
    bindings/python/API.md. points: one [xs, ys, zs] per point, ascending powers of t."""
    return solve_query(kind, points, radii, time_tolerance, want_time, want_exact)


def solve_linear(kind, p_t0, p_t1, *, time_tolerance="1e-12", want_time=True,
                 want_exact=True):
    """solve() for points moving linearly from p_t0 (t = 0) to p_t1 (t = 1), float64
    arrays of shape (npoints, 3)."""
    code = kind_code(kind, linear=True)
    a0 = linear_coords(p_t0, "p_t0", _NPOINTS[kind])
    a1 = linear_coords(p_t1, "p_t1", _NPOINTS[kind])
    cfg, _keep = _cached_config(time_tolerance, want_time, want_exact, "time_tolerance")
    res = _thread.res
    rc = lib.pccd_solve_linear_d(code, ffi.from_buffer("double[]", a0),
                                 ffi.from_buffer("double[]", a1), cfg, res)
    if rc != 0:
        _linear_error(rc, a0, a1, cfg)
    return read_result(res)


def _linear_error(rc, a0, a1, cfg):
    """Raises the error of a failed pccd_solve_linear_d, naming a non-finite input."""
    message = last_error()
    for name, a in (("p_t0", a0), ("p_t1", a1)):
        bad = np.argwhere(~np.isfinite(a))
        if len(bad):
            i, axis = (int(k) for k in bad[0])
            raise InputError(f"{name}[{i}][{axis}]: {float(a[i, axis])} is not a finite number")
    _solve_error(rc, message, cfg, "time_tolerance")


_ND, _F64 = np.ndarray, np.dtype(np.float64)
_FAST = {kind: (code, (_NPOINTS[kind], 3)) for kind, code in _LINEAR.items()}
_from_buffer, _solve_linear_d = ffi.from_buffer, lib.pccd_solve_linear_d


def collides_linear(kind, p_t0, p_t1):
    """True when the primitives moving linearly from p_t0 to p_t1 touch during [0, 1].

    The low-overhead decide-only path for benchmarks: no Result is built, a per-thread
    result handle is reused, and C-contiguous float64 arrays of the right shape go to C
    without any copy (anything else goes through linear_coords, as in solve_linear)."""
    state = _thread
    try:
        code, shape = _FAST[kind]
    except (KeyError, TypeError):
        kind_code(kind, linear=True)  # raises the right message
    if not (type(p_t0) is _ND and p_t0.dtype is _F64 and p_t0.shape == shape
            and p_t0.flags.c_contiguous):
        p_t0 = linear_coords(p_t0, "p_t0", shape[0])
    if not (type(p_t1) is _ND and p_t1.dtype is _F64 and p_t1.shape == shape
            and p_t1.flags.c_contiguous):
        p_t1 = linear_coords(p_t1, "p_t1", shape[0])
    rc = _solve_linear_d(code, _from_buffer("double[]", p_t0), _from_buffer("double[]", p_t1),
                         state.decide_cfg, state.res)
    if rc != 0:
        _linear_error(rc, p_t0, p_t1, state.decide_cfg)
    check(lib.pccd_result_collides(state.res, state.out))
    return state.out[0] != 0
