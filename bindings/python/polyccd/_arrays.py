"""float64 coordinate arrays for the linear entry points (exact: nothing is rounded).

Float arrays go as they are (float16/32/64 are exactly float64); integer arrays and
object arrays (of int, Fraction, float) go as float64 when every value is exactly a
double, checked here value by value. Otherwise NotDouble (an InputError) is raised,
and solve_linear / collides_linear take the exact path instead (linear_trajectories:
the points' exact number texts, x(t) = x0 + (x1 - x0) t).
"""
import numbers
from fractions import Fraction

import numpy as np

from ._errors import InputError
from ._numbers import exact_fraction, number_text, ratio_text

_F64 = np.dtype(np.float64)


class NotDouble(InputError):
    """A coordinate that is a number but not exactly a float64."""


def _exact_value(x):
    """The Fraction of one array value (int, Fraction, float, numpy number), or None."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (numbers.Number, np.generic)):
        return None
    try:
        return Fraction(x) if not isinstance(x, numbers.Integral) else Fraction(int(x))
    except (TypeError, ValueError, OverflowError):
        return None


def _exact_float64(a, place):
    """a converted to float64 when every value converts exactly, else InputError
    (NotDouble for a number that is not exactly a double)."""
    if a.dtype.kind not in "fiuO":
        raise InputError(f"{place}: expected real numbers (float64 values), got dtype "
                         f"{a.dtype}")
    b = np.empty(a.shape, dtype=np.float64)
    for index in np.ndindex(a.shape):  # rare path (not float64 input): check each value
        x = a[index]
        where = "".join(f"[{k}]" for k in index)
        if a.dtype.kind == "f":
            b[index] = x  # float16/32: exact; long double: checked below
            if b[index] == x or x != x:
                continue
        value = _exact_value(x)
        if value is None:
            raise InputError(f"{place}{where}: {x!r} is not a number")
        try:
            y = float(value)
        except OverflowError:
            y = None
        if y is None or Fraction(y) != value:
            raise NotDouble(f"{place}{where}: {x} is not exactly a float64 "
                            "(exact rationals go through polyccd.solve)")
        b[index] = y
    return b


def _no_bools(x, shape, place):
    """InputError naming the first bool of the nested sequence x (True is not a number)."""
    flat = np.empty(shape, dtype=object)
    flat[...] = x if shape else np.asarray(x, dtype=object)
    for i, v in enumerate(flat.ravel().tolist()):
        if isinstance(v, (bool, np.bool_)):
            where = "".join(f"[{k}]" for k in np.unravel_index(i, shape)) if shape else ""
            raise InputError(f"{place}{where}: {v!r} is not a number")


def _float64_array(x, place, shape_text, fits):
    """A C-contiguous float64 array of x when fits(shape), or InputError naming place and
    the expected shape_text."""
    a = x if type(x) is np.ndarray else None
    if a is None:
        try:
            a = np.asarray(x)
        except (ValueError, TypeError) as e:
            raise InputError(f"{place}: not an array of shape {shape_text}: {e}") from None
        if a.dtype.kind in "iubf":  # numpy reads True as 1 in a list of numbers: refused
            _no_bools(x, a.shape, place)
    if a.dtype != _F64:
        a = _exact_float64(a, place)
    if not fits(a.shape):
        raise InputError(f"{place}: expected shape {shape_text}, got {a.shape}")
    return a if a.flags.c_contiguous else np.ascontiguousarray(a)


def linear_coords(x, place, npoints):
    """A C-contiguous float64 array of shape (npoints, 3), or InputError naming place."""
    return _float64_array(x, place, f"({npoints}, 3)", lambda s: s == (npoints, 3))


def linear_batch(x, place, npoints):
    """A C-contiguous float64 array of shape (n, npoints, 3), or InputError naming place."""
    return _float64_array(x, place, f"(n, {npoints}, 3)",
                          lambda s: len(s) == 3 and s[1:] == (npoints, 3))


def linear_trajectories(p_t0, p_t1, npoints):
    """The exact trajectories [[x0, x1 - x0], [y0, ...], [z0, ...]] (number texts) of
    points moving linearly from p_t0 to p_t1 (arrays or nested lists of any exact
    numbers), for solve(); InputError naming p_t0[i][a] / p_t1[i][a]."""
    ends = []
    for p, place in ((p_t0, "p_t0"), (p_t1, "p_t1")):
        try:
            a = np.asarray(p, dtype=object)
        except (ValueError, TypeError) as e:
            raise InputError(f"{place}: not an array of shape ({npoints}, 3): {e}") from None
        if a.shape != (npoints, 3):
            raise InputError(f"{place}: expected shape ({npoints}, 3), got {a.shape}")
        ends.append([[exact_fraction(number_text(a[i, k], f"{place}[{i}][{k}]"),
                                     f"{place}[{i}][{k}]") for k in range(3)]
                     for i in range(npoints)])
    return [[[ratio_text(x0.numerator, x0.denominator),
              ratio_text((x1 - x0).numerator, (x1 - x0).denominator)]
             for x0, x1 in zip(ends[0][i], ends[1][i])] for i in range(npoints)]
