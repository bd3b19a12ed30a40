"""Mesh and Spheres: rigid bodies in body coordinates (formats.md, BODY), thin wrappers
of pccd_body.

Numbers are converted exactly: a numpy float array (float16/32/64) goes to the C
library as doubles (their exact binary values, pccd_body_new_*_d); anything else (nested
lists of int, Fraction, str, float; integer or object arrays; long double arrays) goes
as exact number texts (pccd_body_new_*_s). Validation (index range, radii > 0, finite
numbers) and the edge list come from the C library; errors name the place in the
caller's terms ("vertices[4][2]", "triangles[3][1]", "radii[2]"): the C message is
raised as it is (_errors.check). Bodies never change.
"""
import numbers

import numpy as np

from . import _handles as handles
from ._errors import InputError, check
from ._numbers import number_text, show
from ._pccd import ffi, lib
from ._solve import _items, _texts

_UINT_MAX = 2 ** 32 - 1  # unsigned int of the C API (checked at build time, see below)
assert ffi.sizeof("unsigned int") == 4


def _points(value, place, width=3):
    """(count, doubles or None, texts or None) of a list of points of `width` numbers
    (width None: a flat list of numbers). Exactly one of doubles / texts is set."""
    what = f"an array of shape (n, {width})" if width else "a list of numbers"
    shape = (width,) if width else ()
    if isinstance(value, np.ndarray):
        if value.ndim != len(shape) + 1 or value.shape[1:] != shape:
            raise InputError(f"{place}: expected {what}, got shape {value.shape}")
        if value.dtype.kind == "f" and value.dtype.itemsize <= 8:  # exact in float64
            a = np.ascontiguousarray(value, dtype=np.float64)
            return len(a), a, None
        value = value.tolist() if value.dtype.kind in "iub" else list(value)
    rows = _items(value, place, what)
    texts = []
    for i, row in enumerate(rows):
        if not width:
            if isinstance(row, (list, tuple, dict, np.ndarray)):
                raise InputError(f"{place}[{i}]: expected a number, got {show(row)}")
            texts.append(number_text(row, f"{place}[{i}]"))
            continue
        items = _items(row, f"{place}[{i}]", f"{width} numbers")
        if len(items) != width:
            raise InputError(f"{place}[{i}]: expected {width} numbers, got {len(items)}")
        texts.extend(number_text(x, f"{place}[{i}][{k}]") for k, x in enumerate(items))
    return len(rows), None, texts


def _indices(value):
    """The triangles as a C-contiguous uint32 array of shape (nt, 3), or InputError."""
    if isinstance(value, np.ndarray):
        if value.ndim != 2 or value.shape[1] != 3:
            raise InputError(f"triangles: expected an array of shape (n, 3), got shape "
                             f"{value.shape}")
        if value.dtype.kind not in "iu":
            raise InputError(f"triangles: expected integer indices, got dtype {value.dtype}")
        # Fast path (body builds of big meshes): every index in range, converted at once;
        # otherwise the per-entry loop below names the first bad entry.
        if value.size == 0 or (int(value.min()) >= 0 and int(value.max()) <= _UINT_MAX):
            return len(value), np.ascontiguousarray(value, dtype=np.uint32).ravel()
        value = value.tolist()
    rows = _items(value, "triangles", "a list of [i, j, k] index triples")
    flat = []
    for t, row in enumerate(rows):
        items = _items(row, f"triangles[{t}]", "3 vertex indices")
        if len(items) != 3:
            raise InputError(f"triangles[{t}]: expected 3 vertex indices, got {len(items)}")
        for k, x in enumerate(items):
            place = f"triangles[{t}][{k}]"
            if isinstance(x, (bool, np.bool_)) or not isinstance(x, numbers.Integral):
                raise InputError(f"{place}: {show(x)} is not an integer vertex index")
            if not 0 <= x <= _UINT_MAX:
                raise InputError(f"{place}: index {int(x)} is not a valid 0-based index")
            flat.append(int(x))
    return len(rows), np.array(flat, dtype=np.uint32)


class _Body:
    __slots__ = ("_handle",)

    def __setattr__(self, name, value):
        raise AttributeError(f"a {type(self).__name__} cannot be changed")

    def __copy__(self):
        return self  # immutable

    def __deepcopy__(self, memo):
        return self

    def _counts(self):
        counts = ffi.new("size_t[3]")
        check(lib.pccd_body_counts(self._handle, counts, counts + 1, counts + 2))
        return tuple(counts)


class Mesh(_Body):
    """A triangle mesh: vertices (n, 3) and triangles (m, 3) of 0-based indices.
    Degenerate triangles (repeated indices, collinear points) are accepted as given."""

    __slots__ = ()

    def __init__(self, vertices, triangles):
        nv, doubles, texts = _points(vertices, "vertices")
        nt, tris = _indices(triangles)
        t = ffi.from_buffer("unsigned int[]", tris)
        if doubles is not None:
            handle = handles.new("body", ffi.from_buffer("double[]", doubles), nv, t, nt,
                                 via="new_mesh_d")
        else:
            array, _keep = _texts(texts)
            handle = handles.new("body", array, nv, t, nt, via="new_mesh_s")
        object.__setattr__(self, "_handle", handle)

    @property
    def n_vertices(self):
        return self._counts()[0]

    @property
    def n_edges(self):
        return self._counts()[1]

    @property
    def n_triangles(self):
        return self._counts()[2]

    @property
    def edges(self):
        """The edges as an (E, 2) int64 array: each unordered side {a, b} (a != b) of a
        triangle once, as a < b, sorted by (a, b)."""
        n = self.n_edges
        out = np.empty((n, 2), dtype=np.int64)
        v = ffi.new("size_t[2]")
        for i in range(n):
            check(lib.pccd_body_edge(self._handle, i, v))
            out[i] = v[0], v[1]
        return out

    def edge_triangles(self, i):
        """The indices of the triangles incident to edge i, ascending, as a tuple."""
        if isinstance(i, (bool, np.bool_)) or not isinstance(i, numbers.Integral) or i < 0:
            raise InputError(f"i: {show(i)} is not an edge index")
        count = ffi.new("size_t *")
        rc = lib.pccd_body_edge_triangles(self._handle, i, ffi.NULL, 0, count)
        if rc != lib.PCCD_ERANGE:
            check(rc)
        tris = ffi.new("size_t[]", count[0])
        check(lib.pccd_body_edge_triangles(self._handle, i, tris, count[0], count))
        return tuple(tris)

    def __repr__(self):
        nv, ne, nt = self._counts()
        return f"<polyccd.Mesh: {nv} vertices, {ne} edges, {nt} triangles>"


class Spheres(_Body):
    """A set of closed balls: centers (n, 3) and radii (n,), every radius > 0."""

    __slots__ = ()

    def __init__(self, centers, radii):
        n, c_doubles, c_texts = _points(centers, "centers")
        nr, r_doubles, r_texts = _points(radii, "radii", width=None)
        if nr != n:
            raise InputError(f"radii: expected {n} radii (one per center), got {nr}")
        if c_doubles is not None and r_doubles is not None:
            handle = handles.new("body", ffi.from_buffer("double[]", c_doubles),
                                 ffi.from_buffer("double[]", r_doubles), n, via="new_spheres_d")
        else:  # mixed inputs: both as exact texts (a double's text is its binary value)
            if c_texts is None:
                c_texts = [number_text(float(x), f"centers[{i // 3}][{i % 3}]")
                           for i, x in enumerate(c_doubles.ravel())]
            if r_texts is None:
                r_texts = [number_text(float(x), f"radii[{i}]") for i, x in enumerate(r_doubles)]
            c, _kc = _texts(c_texts)
            r, _kr = _texts(r_texts)
            handle = handles.new("body", c, r, n, via="new_spheres_s")
        object.__setattr__(self, "_handle", handle)

    @property
    def n_spheres(self):
        return self._counts()[0]

    def __repr__(self):
        return f"<polyccd.Spheres: {self.n_spheres} balls>"
