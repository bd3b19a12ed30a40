"""float64 coordinate arrays for the linear entry points (exact: nothing is rounded)."""
import numpy as np

from ._errors import InputError

_F64 = np.dtype(np.float64)


def _exact_float64(a, place):
    """a converted to float64 when every value converts exactly, else InputError."""
    if a.dtype.kind not in "fiu":
        raise InputError(f"{place}: expected float64 coordinates, got dtype {a.dtype} "
                         "(exact rationals go through polyccd.solve)")
    b = a.astype(np.float64)
    for index in np.ndindex(a.shape):  # rare path (not float64 input): check each value
        x, y = a[index], b[index]
        exact = (int(x) == int(y)) if a.dtype.kind in "iu" else (x == y or x != x)
        if not exact:
            where = "".join(f"[{k}]" for k in index)
            raise InputError(f"{place}{where}: {x} is not exactly a float64 "
                             "(exact rationals go through polyccd.solve)")
    return b


def _float64_array(x, place, shape_text, fits):
    """A C-contiguous float64 array of x when fits(shape), or InputError naming place and
    the expected shape_text."""
    a = x if type(x) is np.ndarray else None
    if a is None:
        try:
            a = np.asarray(x)
        except (ValueError, TypeError) as e:
            raise InputError(f"{place}: not an array of shape {shape_text}: {e}") from None
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
