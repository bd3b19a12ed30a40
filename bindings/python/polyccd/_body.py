"""Mesh and Spheres: rigid bodies in body coordinates (formats.md, BODY), thin wrappers
of pccd_body.

Numbers are converted exactly: a numpy float array (float16/32/64) and an integer array
whose values are all within +-2^53 go to the C library as doubles (their exact binary
values, pccd_body_new_*_d); anything else (nested lists of int, Fraction, str, float;
larger integers; object arrays of Fraction, int or float; long double arrays) goes as
exact number texts (pccd_body_new_*_s). Validation (index range, radii > 0, finite
numbers) and the edge list come from the C library; errors name the place in the
caller's terms ("vertices[4][2]", "triangles[3][1]", "radii[2]"): the C message is
raised as it is (_errors.check). Bodies never change.

A body keeps a private copy of the exact inputs it was built from (the doubles or the
number texts, and the triangles), so that it pickles (it is rebuilt from them, e.g. on
a Dask worker: the C handle itself cannot travel) and can give its coordinates back as
numpy arrays (Mesh.vertices, Mesh.exact_vertices(), ...).
"""
from __future__ import annotations

import numbers
from fractions import Fraction

import numpy as np

from typing import Any, Optional, Sequence, Tuple

from ._types import Indices, Number, Points, Vector
from . import _handles as handles
from . import _limits
from ._limits import Limits
from ._errors import InputError, check
from ._flags import real
from ._numbers import exact_fraction, number_text, show
from ._pccd import ffi, lib
from ._solve import _items, _texts

_UINT_MAX = 2 ** 32 - 1  # unsigned int of the C API (checked at build time, see below)
_EXACT_INT = 2 ** 53  # every integer of magnitude <= 2^53 is a double exactly
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
            return len(value), _frozen(np.array(value, dtype=np.float64)), None
        if value.dtype.kind in "iu" and (value.size == 0 or (
                int(value.min()) >= -_EXACT_INT and int(value.max()) <= _EXACT_INT)):
            return len(value), _frozen(value.astype(np.float64)), None  # exact: |x| <= 2^53
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


def _frozen(a):
    """a (a private C-contiguous copy) made read-only."""
    a = np.ascontiguousarray(a)
    a.flags.writeable = False
    return a


def _float_of_texts(texts, shape):
    """The nearest doubles of exact number texts (already accepted by the C library),
    for drawing and other float uses: float(Fraction) rounds correctly."""
    return np.array([float(exact_fraction(t, "value")) for t in texts],
                    dtype=np.float64).reshape(shape)


def _fractions(doubles, texts, shape):
    """An object array of the exact Fractions of the doubles or the number texts."""
    values = ([exact_fraction(t, "value") for t in texts] if doubles is None
              else [Fraction(x) for x in doubles.ravel().tolist()])
    out = np.empty(len(values), dtype=object)
    out[:] = values
    return out.reshape(shape)


def _indices(value, name="triangles", width=3):
    """The index rows of `name` (triangles, or a step's faces, edges) as a C-contiguous
    uint32 array of shape (n, width), flattened, with n; or InputError naming the entry."""
    if isinstance(value, np.ndarray):
        if value.ndim != 2 or value.shape[1] != width:
            raise InputError(f"{name}: expected an array of shape (n, {width}), got shape "
                             f"{value.shape}")
        if value.dtype.kind not in "iu":
            raise InputError(f"{name}: expected integer indices, got dtype {value.dtype}")
        # Fast path (body builds of big meshes): every index in range, converted at once;
        # otherwise the per-entry loop below names the first bad entry.
        if value.size == 0 or (int(value.min()) >= 0 and int(value.max()) <= _UINT_MAX):
            return len(value), np.ascontiguousarray(value, dtype=np.uint32).ravel()
        value = value.tolist()
    rows = _items(value, name, f"a list of rows of {width} vertex indices")
    flat = []
    for t, row in enumerate(rows):
        items = _items(row, f"{name}[{t}]", f"{width} vertex indices")
        if len(items) != width:
            raise InputError(f"{name}[{t}]: expected {width} vertex indices, got {len(items)}")
        for k, x in enumerate(items):
            place = f"{name}[{t}][{k}]"
            if isinstance(x, (bool, np.bool_)) or not isinstance(x, numbers.Integral):
                raise InputError(f"{place}: {show(x)} is not an integer vertex index")
            if not 0 <= x <= _UINT_MAX:
                raise InputError(f"{place}: index {show(int(x))} is not a valid 0-based index")
            flat.append(int(x))
    return len(rows), _frozen(np.array(flat, dtype=np.uint32))


class _Body:
    __slots__ = ("_handle", "_inputs")

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


# The 12 outward-facing triangles of a box whose corner i is (+-x, +-y, +-z) by the bits of i.
_BOX_TRIANGLES = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]


class Mesh(_Body):
    """A triangle mesh: vertices (n, 3) and triangles (m, 3) of 0-based indices.
    Degenerate triangles (repeated indices, collinear points) are accepted as given.

    solid=True: the mesh stands for the solid it bounds (pccd_body_new_solid): a body
    with a vertex or ball centre strictly inside it at t = 0 touches it at t = 0, the
    contact ("solid", 0) with ("vertex", i) or ("sphere", i). The mesh must be closed and
    consistently oriented (every edge a side of exactly two triangles, in opposite
    directions); else InputError naming the first open or flipped edge."""

    __slots__ = ()

    def __init__(self, vertices: Points, triangles: Indices, solid: bool = False, *,
                 limits: Optional[Limits] = None) -> None:
        """limits: a polyccd.Limits bounding the building (pccd_body_new_mesh_cfg_d:
        the conversion, the edges, the hierarchy), LimitError when reached; None: none."""
        nv, doubles, texts = _points(vertices, "vertices")
        nt, tris = _indices(triangles)
        if not isinstance(solid, (bool, np.bool_)):
            raise InputError(f"solid: expected True or False, got {show(solid)}")
        cfg = None if limits is None else _limits.config(limits)
        self._build(nv, doubles, None if texts is None else tuple(texts), tris, bool(solid), cfg)

    def _build(self, nv, doubles, texts, tris, solid=False, cfg=None):
        t = ffi.from_buffer("unsigned int[]", tris)
        tail, cfg_ = ("", ()) if cfg is None else ("cfg_", (cfg,))
        if doubles is not None:
            handle = handles.new("body", ffi.from_buffer("double[]", doubles), nv, t,
                                 len(tris) // 3, *cfg_, via=f"new_mesh_{tail}d")
        else:
            array, _keep = _texts(texts)
            handle = handles.new("body", array, nv, t, len(tris) // 3, *cfg_,
                                 via=f"new_mesh_{tail}s")
        if solid:
            handle = handles.new("body", handle, via="new_solid")
        object.__setattr__(self, "_handle", handle)
        object.__setattr__(self, "_inputs", (nv, doubles, texts, tris, solid))

    @property
    def solid(self) -> bool:
        """True when the mesh stands for the solid it bounds (Mesh(..., solid=True))."""
        out = ffi.new("int *")
        check(lib.pccd_body_solid(self._handle, out))
        return bool(out[0])

    def __reduce__(self):
        """Pickles as the exact inputs; unpickling builds a new Mesh from them."""
        return _rebuild, (Mesh, self._inputs)

    @classmethod
    def box(cls, extents: Vector, solid: bool = False) -> Mesh:
        """The closed box [-a/2, a/2] x [-b/2, b/2] x [-c/2, c/2] of extents (a, b, c) > 0,
        centred at the origin of its body frame (place it with a Motion or Body's pose),
        as 12 outward-facing triangles; halving a double is exact, so its corners are
        exactly +-extents/2. solid: as for Mesh (the box is closed)."""
        e = [real(x, f"extents[{k}]") for k, x in enumerate(_items(extents, "extents", "3 numbers"))]
        if len(e) != 3 or not all(np.isfinite(x) and x > 0 for x in e):
            raise InputError(f"extents: expected 3 positive finite numbers, got {show(extents)}")
        h = [x / 2 for x in e]
        v = [[h[0] * (1 if i & 1 else -1), h[1] * (1 if i & 2 else -1), h[2] * (1 if i & 4 else -1)]
             for i in range(8)]
        return cls(v, _BOX_TRIANGLES, solid=solid)

    @classmethod
    def cylinder(cls, radius: float, height: float, sections: int = 16, solid: bool = False) -> Mesh:
        """A closed prism around the cylinder of this radius and height (axis z, centred at
        the origin): the regular `sections`-gon whose inscribed circle has radius at least
        `radius` (vertices at radius / cos(pi / sections), enlarged by 1e-12 relative, which
        covers the rounding of the doubles, about 1e-16 relative), so the prism contains
        the cylinder; its distance from the cylinder is at most radius (1 / cos(pi /
        sections) - 1), 2 % for 16 sections. Collisions are those of the prism. solid: as
        for Mesh (the prism is closed)."""
        r, hgt = real(radius, "radius"), real(height, "height")
        for name, x in (("radius", r), ("height", hgt)):
            if not (np.isfinite(x) and x > 0):
                raise InputError(f"{name}: expected a positive finite number, got {show(x)}")
        if isinstance(sections, bool) or not isinstance(sections, numbers.Integral) or sections < 3:
            raise InputError(f"sections: expected an integer >= 3, got {show(sections)}")
        big = r / np.cos(np.pi / sections) * (1 + 1e-12)
        a = 2 * np.pi * (np.arange(sections) + 0.5) / sections
        ring = [[big * np.cos(x), big * np.sin(x)] for x in a]
        h = hgt / 2
        v = [[x, y, -h] for x, y in ring] + [[x, y, h] for x, y in ring]
        t = []
        for i in range(sections):
            j = (i + 1) % sections
            t += [[i, j, sections + j], [i, sections + j, sections + i]]
        for i in range(1, sections - 1):
            t += [[0, i + 1, i], [sections, sections + i, sections + i + 1]]
        return cls(v, t, solid=solid)

    @classmethod
    def from_trimesh(cls, mesh: Any, solid: Optional[bool] = None) -> Mesh:
        """The Mesh of a trimesh.Trimesh (or any object with .vertices (n, 3) and .faces
        (m, 3)): its float64 vertices taken at their exact binary values, its faces as
        the triangles, as they are (no processing, merging or reorientation). A
        trimesh.Scene is refused: pass scene.to_geometry() (trimesh applies the node
        transforms in floating point, so that is its rounding, not polyccd's).

        solid: None (default) makes it a solid exactly when its triangles are closed and
        consistently oriented (decided by the library on the triangles as given, not by
        trimesh's is_watertight, which merges vertices first); True requires it
        (InputError naming the first open or flipped edge), False keeps the surface."""
        vertices = getattr(mesh, "vertices", None)
        faces = getattr(mesh, "faces", None)
        if vertices is None or faces is None:
            hint = (" (a trimesh.Scene: pass scene.to_geometry())"
                    if hasattr(mesh, "geometry") else "")
            raise InputError(f"mesh: expected a trimesh.Trimesh (with .vertices and .faces), "
                             f"got {show(mesh)}{hint}")
        if solid is not None and not isinstance(solid, (bool, np.bool_)):
            raise InputError(f"solid: expected None, True or False, got {show(solid)}")
        surface = cls(np.asarray(vertices), np.asarray(faces))
        if solid is False:
            return surface
        return surface._as_solid(required=solid is True)

    def _as_solid(self, required: bool) -> Mesh:
        """This mesh as a solid; when it is not closed and consistently oriented: the
        InputError (required) or the mesh itself."""
        if self.solid:
            return self
        out = ffi.new("pccd_body **")
        rc = lib.pccd_body_new_solid(out, self._handle)
        if rc != lib.PCCD_OK and not required:
            return self
        check(rc)
        body = Mesh.__new__(Mesh)
        object.__setattr__(body, "_handle", ffi.gc(out[0], lib.pccd_body_free))
        object.__setattr__(body, "_inputs", self._inputs[:4] + (True,))
        return body

    @property
    def vertices(self):
        """The vertices as an (n, 3) float64 array (read-only): exactly the body's
        coordinates when exact_doubles, else their nearest doubles (for drawing)."""
        nv, doubles, texts = self._inputs[:3]
        return doubles.reshape(nv, 3) if doubles is not None else _float_of_texts(texts, (nv, 3))

    @property
    def exact_doubles(self):
        """True when the coordinates were given as doubles (Mesh.vertices is exact)."""
        return self._inputs[1] is not None

    def exact_vertices(self) -> np.ndarray:
        """The vertices as an (n, 3) object array of Fractions, exactly as the body uses
        them (a float given is its binary value, a decimal text its decimal value)."""
        nv, doubles, texts = self._inputs[:3]
        return _fractions(doubles, texts, (nv, 3))

    @property
    def triangles(self):
        """The triangles as an (m, 3) int64 array of 0-based vertex indices, as given."""
        return self._inputs[3].reshape(-1, 3).astype(np.int64)

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

    def edge_triangles(self, i: int) -> Tuple[int, ...]:
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
        solid = ", solid" if self._inputs[4] else ""
        return f"<polyccd.Mesh: {nv} vertices, {ne} edges, {nt} triangles{solid}>"


class Spheres(_Body):
    """A set of closed balls: centers (n, 3) and radii (n,), every radius > 0."""

    __slots__ = ()

    def __init__(self, centers: Points, radii: Sequence[Number]) -> None:
        n, c_doubles, c_texts = _points(centers, "centers")
        nr, r_doubles, r_texts = _points(radii, "radii", width=None)
        if nr != n:
            raise InputError(f"centers, radii: {n} centers but {nr} radii (one radius per center)")
        self._build(n, c_doubles, c_texts, r_doubles, r_texts)

    def _build(self, n, c_doubles, c_texts, r_doubles, r_texts):
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
            c_doubles = r_doubles = None
            c_texts, r_texts = tuple(c_texts), tuple(r_texts)
        object.__setattr__(self, "_handle", handle)
        object.__setattr__(self, "_inputs", (n, c_doubles, c_texts, r_doubles, r_texts))

    def __reduce__(self):
        """Pickles as the exact inputs; unpickling builds new Spheres from them."""
        return _rebuild, (Spheres, self._inputs)

    @property
    def centers(self):
        """The centres as an (n, 3) float64 array (read-only): exactly the body's when
        exact_doubles, else their nearest doubles (for drawing)."""
        n, c, ct, _, _ = self._inputs
        return c.reshape(n, 3) if c is not None else _float_of_texts(ct, (n, 3))

    @property
    def radii(self):
        """The radii as an (n,) float64 array: exact when exact_doubles, else nearest."""
        n, _, _, r, rt = self._inputs
        return r if r is not None else _float_of_texts(rt, (n,))

    @property
    def exact_doubles(self):
        """True when centres and radii were given as doubles (centers, radii are exact)."""
        return self._inputs[1] is not None

    def exact_centers(self) -> np.ndarray:
        """The centres as an (n, 3) object array of Fractions, exactly as the body uses them."""
        n, c, ct, _, _ = self._inputs
        return _fractions(c, ct, (n, 3))

    def exact_radii(self) -> np.ndarray:
        """The radii as an (n,) object array of Fractions, exactly as the body uses them."""
        n, _, _, r, rt = self._inputs
        return _fractions(r, rt, (n,))

    @property
    def n_spheres(self):
        return self._counts()[0]

    def __repr__(self):
        return f"<polyccd.Spheres: {self.n_spheres} balls>"


def _rebuild(cls, inputs):
    """A Mesh or Spheres rebuilt from the exact inputs of a pickled one (already checked
    by the C library once, so nothing is converted again)."""
    body = cls.__new__(cls)
    body._build(*inputs)
    return body
