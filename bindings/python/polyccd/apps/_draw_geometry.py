"""The float geometry that the pictures draw (_render: PNG, _export: trimesh): each
body's pose at t taken exactly from its Motion and rounded once (_float_pose), a
shape's float arrays (_arrays), a result's touching features by body (_contacts), a
mesh's edges, decimation and clipping of large meshes, and shading. Drawing only:
nothing here decides a contact."""
from fractions import Fraction

import numpy as np

from .. import InputError

BODY_COLORS = ("#4f7fbf", "#e0a040", "#5fae6e", "#a070c0", "#8c8c8c", "#c0c060")
HIGHLIGHT = "#e8001c"
_LIGHT = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])


def _time(t):
    """An exact time (Fraction) from a number, a str, or a ContactTime (its exact value,
    else the middle of its enclosure)."""
    if hasattr(t, "lo") and hasattr(t, "hi"):
        return t.exact if getattr(t, "exact", None) is not None else (t.lo + t.hi) / 2
    if isinstance(t, float):
        return Fraction(t)
    try:
        return Fraction(t)
    except (TypeError, ValueError):
        raise InputError(f"t: {t!r} is not a time") from None


def _float_pose(motion, t):
    """(R, o) in float64 with x(t) = R p + o for every body point p: the exact positions
    of the origin and of the unit points at t (Motion.position), rounded once."""
    if motion is None:
        return np.eye(3), np.zeros(3)
    t = _time(t)
    origin = motion.position([0, 0, 0], t)
    columns = []
    for axis in range(3):
        unit = [0, 0, 0]
        unit[axis] = 1
        p = motion.position(unit, t)
        columns.append([float(p[k] - origin[k]) for k in range(3)])
    return np.array(columns).T, np.array([float(x) for x in origin])


def _parts(body, index):
    """(shape, motion, name) of a Body-like object or a (shape, motion[, name]) tuple."""
    if isinstance(body, (tuple, list)):
        shape, motion = body[0], body[1] if len(body) > 1 else None
        name = body[2] if len(body) > 2 else None
    else:
        shape, motion = body.shape, getattr(body, "motion", None)
        name = getattr(body, "name", None)
    return shape, motion, name or f"body{index}"


def _arrays(shape, geometry, index):
    """("mesh", vertices, triangles) or ("spheres", centers, radii) in float."""
    given = geometry.get(index) if geometry else None
    if given is None:
        given = shape
    if isinstance(given, dict):
        get = given.get
    else:
        def get(name):
            return getattr(given, name, None)
    if get("triangles") is not None and get("vertices") is not None:
        return ("mesh", np.asarray(get("vertices"), dtype=np.float64),
                np.asarray(get("triangles"), dtype=np.int64))
    if get("centers") is not None and get("radii") is not None:
        return ("spheres", np.asarray(get("centers"), dtype=np.float64),
                np.asarray(get("radii"), dtype=np.float64))
    raise InputError(f"bodies[{index}]: no float geometry to draw (load the shape with "
                     "polyccd.data, or pass geometry={index: {'vertices': ..., "
                     "'triangles': ...}} or {'centers': ..., 'radii': ...})")


def _contacts(contacts, n_bodies):
    """[(body, kind, k)] from a SceneResult (the first pairs' contacts), PairResults,
    or (body index, (kind, k)) items. A ("solid", 0) feature (a solid holding the other
    body's vertex or ball) marks nothing: the point it holds is marked."""
    if contacts is None:
        return []
    if hasattr(contacts, "first") and hasattr(contacts, "pairs"):
        contacts = contacts.first or contacts.pairs
    if hasattr(contacts, "bodies") and hasattr(contacts, "contacts"):
        contacts = [contacts]
    out = []
    for item in contacts:
        if hasattr(item, "bodies") and hasattr(item, "contacts"):
            i, j = item.bodies
            for c in item.contacts:
                out.append((i, c.a[0], int(c.a[1])))
                out.append((j, c.b[0], int(c.b[1])))
            continue
        body, (kind, k) = item
        out.append((int(body), kind, int(k)))
    for body, kind, k in out:
        if not 0 <= body < n_bodies or kind not in ("vertex", "edge", "triangle", "sphere", "solid"):
            raise InputError(f"contacts: bad feature {(body, kind, k)!r}")
    return sorted(set(f for f in out if f[1] != "solid"))


def _edges_of(triangles):
    """The sorted unique edges (a < b, a != b) of the triangles, like Mesh.edges."""
    e = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    e = np.sort(e, axis=1)
    e = e[e[:, 0] != e[:, 1]]
    return np.unique(e, axis=0)


def _decimate(vertices, triangles, limit):
    """A display copy with at most about `limit` triangles, by vertex clustering on a
    grid (never used for any decision)."""
    if len(triangles) <= limit:
        return vertices, triangles
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    cells = max(8, int(np.sqrt(limit / 2.0)))  # a closed surface on an n^3 grid: ~2n^2 faces
    for _ in range(12):
        size = (hi - lo).max() / cells
        keys = np.floor((vertices - lo) / size).astype(np.int64)
        _, cluster, counts = np.unique(keys, axis=0, return_inverse=True, return_counts=True)
        cluster = cluster.ravel()
        sums = np.zeros((len(counts), 3))
        np.add.at(sums, cluster, vertices)
        tri = cluster[triangles]
        tri = tri[(tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 0] != tri[:, 2])]
        _, first = np.unique(np.sort(tri, axis=1), axis=0, return_index=True)
        tri = tri[np.sort(first)]
        if len(tri) <= limit or cells <= 8:
            return sums / counts[:, None], tri
        cells = int(cells * 0.8)
    return sums / counts[:, None], tri


def _clip_to_box(vertices, triangles, lo, hi, limit):
    """The triangles (as (k, 3, 3) corner arrays) of the surface inside the box [lo, hi],
    for display: triangles meeting the box are bisected on their longest side until
    small against the box, then the pieces whose centroid is outside are dropped (a
    ragged cut)."""
    p = vertices[triangles] if triangles is not None else vertices
    size = (hi - lo).max()
    margin = size / 16

    def near(q):
        return np.all((q.max(axis=1) >= lo - margin) & (q.min(axis=1) <= hi + margin), axis=1)

    p = p[near(p)]
    for _ in range(16):
        sides = np.linalg.norm(p - np.roll(p, -1, axis=1), axis=2)  # side i: corner i, i+1
        longest = sides.argmax(axis=1)
        big = sides.max(axis=1) > size / 16
        if not big.any() or len(p) + big.sum() > 4 * limit:
            break
        q, k = p[big], longest[big]
        rows = np.arange(len(q))
        a, b, c = q[rows, k], q[rows, (k + 1) % 3], q[rows, (k + 2) % 3]
        m = (a + b) / 2
        pieces = np.concatenate([np.stack((a, m, c), axis=1), np.stack((m, b, c), axis=1)])
        p = np.concatenate([p[~big], pieces[near(pieces)]])
    centroid = p.mean(axis=1)
    return p[np.all((centroid >= lo) & (centroid <= hi), axis=1)]


def _clip_segments(segments, lo, hi):
    """The parts of segments (k, 2, 3) inside the box (Liang-Barsky), as (k', 2, 3)."""
    out = []
    for a, b in segments:
        d = b - a
        t0, t1 = 0.0, 1.0
        for axis in range(3):
            if d[axis] == 0:
                if not lo[axis] <= a[axis] <= hi[axis]:
                    t0, t1 = 1.0, 0.0
                continue
            u, v = (lo[axis] - a[axis]) / d[axis], (hi[axis] - a[axis]) / d[axis]
            t0, t1 = max(t0, min(u, v)), min(t1, max(u, v))
        if t0 <= t1:
            out.append([a + t0 * d, a + t1 * d])
    return np.array(out).reshape(-1, 2, 3)


def _shade(rgb, normals):
    """Face colours: Lambert with one light plus ambient (two-sided)."""
    lengths = np.linalg.norm(normals, axis=1)
    lengths[lengths == 0] = 1
    cos = np.abs((normals / lengths[:, None]) @ _LIGHT)
    k = 0.35 + 0.65 * cos
    return np.clip(np.asarray(rgb)[None, :] * k[:, None], 0, 1)
