"""Adversarial two-body families for the broad phases (issue 26): inputs where nearly every
pair of bounding boxes overlaps while almost no pair of features is near, so boxes and bvh
report Theta(N^2) candidates and only the range structure's linearized contact conditions
(paper section 3) can separate them. Used by tests/bench/bench_adversarial.py (timings) and
tests/test_adversarial.py (every broad phase gives the brute-force answer at small sizes).

make(family, n, hit=False) returns two polyccd.Body objects with about n primitives in all
(N = |B1| + |B2|, the paper's two-body problem), body 0 static, body 1 moving. With
hit=False no feature pair touches on [0, 1] (by construction, stated per family); with
hit=True the motion is changed so that some pair does (at a time the family states or the
exact solver finds), which the tests use to compare first contacts. Every coordinate is a
small integer or a dyadic rational (exact in binary), so the inputs are exactly what is
described.

Families (k = the number of primitives per body):
  slivers  k long thin triangles on the parallel planes z = x + 2i (body 0) and
           z = x + 2i + 1 (body 1), each (0, 0, c) (L, 0, L + c) (0, 1/2, c) with
           L = 2k + 8: every box meets every other. Body 1 runs along y (in its planes):
           the planes stay 1 apart / 1/sqrt(2) in distance. hit: it runs 1/4 along y and drops
           by 3/2 in z (crossing the plane below at t = 2/3).
  plates   k/2 square plates (two triangles sharing a diagonal) on the planes
           z = (x + y) / 2 + 2i / body 1 + 2i + 1, side L = 2k + 8; body 1 runs along
           (1, -1, 0) within its planes. hit: it also drops by 3/2 in z.
  fans     k triangles (0, 0, 0) (0, 0, 1) (R cos a, R sin a, 1 + R) around the z axis
           (vertical half-planes at angles a = 2 pi j / 2k), body 1 the same at the odd
           angles lifted by 3/2 (its axis edge at z in [3/2, 5/2]); R = 4. Half-planes at
           different angles meet only on the axis, where the bodies' axis edges are 1/2
           apart: body 1 rises by 1 (apart). hit: it drops by 1 instead (the axis edges
           touch at t = 1/2). Every box holds the axis: all meet. The rim points are on
           the 2^-16 grid (the angles are approximate, the planes exact).
  needles  k thin triangles (p - h d, p + h d, p - h d + e / 8) along d = (1, 1, 1)
           (body 0) or d = (1, -1, 1) (body 1), e = (0, 1, 0) / (1, 0, 1) across, p on an
           integer grid with x - z = 2a (body 0) or 2a + 1 (body 1): each triangle lies in
           its plane x - z = const, even for body 0 and odd for body 1 (d and e have
           x - z = 0), so the bodies stay >= 1/sqrt(2) apart; h = 2 sqrt(k) + 4 makes every
           box meet. Body 1 runs along its own direction, (4, -4, 4). hit: it also moves by
           (1, 0, -1) (x - z grows by 2: the crossing needles meet).
  balls    k balls of radius R = 64 per body, centres on a jittered grid of the plane
           x + y + z = 0 (body 0) and of the same plane shifted by 154 / sqrt(3) along
           (1, 1, 1) (body 1), in a square of side 32: distance between centres
           >= 154 > 2R, while every box meets. Body 1 runs within its plane. hit: it also
           moves by -(40, 40, 40) towards body 0.
"""

import math

import numpy as np

FAMILIES = ("slivers", "plates", "fans", "needles", "balls")


def _grid(x):
    """x rounded to the 2^-16 grid (exact doubles)."""
    return np.round(np.asarray(x, dtype=float) * 65536.0) / 65536.0


# The planes' normal (slivers, plates, needles) or the slab's (balls): rotations about
# it, through the origin, keep every body-1 feature in its own plane (MOTIONS).
NORMAL = {"slivers": (-1, 0, 1), "plates": (-1, -1, 2), "needles": (1, 0, -1), "balls": (1, 1, 1)}
MOTIONS = ("translation", "axis", "general")
_motion = {"kind": "translation", "axis": None}


def _body(polyccd, shape, translation=None):
    """Body 1's motion: the family's translation ("translation"), or r(t) = (1, t a / 4)
    about the family's normal a through the origin alone ("axis": a rotation about a
    fixed axis, range's exact rotation conditions) or with the translation ("general":
    the axis travels, range's general clauses)."""
    if translation is None:
        return polyccd.Body(shape)
    kind, a = _motion["kind"], _motion["axis"]
    trans = [[0.0, 0.0 if kind == "axis" else float(c)] for c in translation]
    if kind == "translation":
        return polyccd.Body(shape, polyccd.Motion(translation=trans))
    rot = [[1.0, 0.0]] + [[0.0, c / 4] for c in a]
    return polyccd.Body(shape, polyccd.Motion(translation=trans, rotation=rot))


def _mesh(polyccd, V, F):
    return polyccd.Mesh(np.asarray(V, dtype=float), np.asarray(F, dtype=np.int64))


def _stacks(polyccd, k, layer):
    """Two meshes of k layers each, layer(c) -> (vertices, triangles) at offset c = 2i
    (body 0) or 2i + 1 (body 1): interleaved parallel planes."""
    bodies = []
    for side in range(2):
        V, F = [], []
        for i in range(k):
            v, f = layer(2 * i + side)
            F += [[len(V) + j for j in t] for t in f]
            V += v
        bodies.append(_mesh(polyccd, V, F))
    return bodies


def slivers(polyccd, n, hit):
    k = max(1, n // 2)
    L = 2 * k + 8
    bodies = _stacks(polyccd, k, lambda c: ([[0, 0, c], [L, 0, L + c], [0, 0.5, c]], [[0, 1, 2]]))
    return [_body(polyccd, bodies[0]), _body(polyccd, bodies[1], [0, 1 / 4, -1.5] if hit else [0, 4, 0])]


def plates(polyccd, n, hit):
    k = max(1, n // 4)
    L = 2 * k + 8
    corners = [[0, 0], [L, 0], [L, L], [0, L]]
    bodies = _stacks(polyccd, k, lambda c: ([[x, y, (x + y) / 2 + c] for x, y in corners],
                                            [[0, 1, 2], [0, 2, 3]]))
    return [_body(polyccd, bodies[0]), _body(polyccd, bodies[1], [3, -3, -1.5 if hit else 0])]


def fans(polyccd, n, hit):
    k = max(1, n // 2)
    R = 4.0
    bodies = []
    for side in range(2):
        z0 = 1.5 * side
        V = [[0, 0, z0], [0, 0, z0 + 1]]
        F = []
        for j in range(k):
            a = 2 * math.pi * (2 * j + side) / (2 * k)
            V.append([R * math.cos(a), R * math.sin(a), z0 + 1 + R])
            F.append([0, 1, 2 + j])
        bodies.append(_mesh(polyccd, _grid(V), F))
    return [_body(polyccd, bodies[0]), _body(polyccd, bodies[1], [0, 0, -1 if hit else 1])]


def needles(polyccd, n, hit):
    k = max(1, n // 2)
    m = max(1, math.ceil(math.sqrt(k)))
    h = 2 * m + 4                                        # half length, in units of d
    bodies = []
    for side in range(2):
        d = np.array([1, 1 - 2 * side, 1])
        u = np.array([1, 0, -1])                         # x - z = 2 per step
        v = np.cross(d, u)                               # x - z = 0
        e = np.array([0, 1, 0]) if side == 0 else np.array([1, 0, 1])   # across, x - z = 0
        V, F = [], []
        for j in range(k):
            a, b = j % m - m // 2, j // m - m // 2
            p = a * u + b * v + np.array([side, 0, 0])   # x - z = 2a + side
            V += [p - h * d, p + h * d, p - h * d + e / 8]
            F.append([3 * j, 3 * j + 1, 3 * j + 2])
        bodies.append(_mesh(polyccd, np.array(V, dtype=float), F))
    move = np.array([4, -4, 4]) + (np.array([1, 0, -1]) if hit else 0)
    return [_body(polyccd, bodies[0]), _body(polyccd, bodies[1], move)]


def balls(polyccd, n, hit, rng=None):
    k = max(1, n // 2)
    rng = np.random.default_rng(26) if rng is None else rng
    m = max(1, math.ceil(math.sqrt(k)))
    u = np.array([1, -1, 0]) / math.sqrt(2)
    v = np.array([1, 1, -2]) / math.sqrt(6)
    w = np.array([1, 1, 1]) / math.sqrt(3)
    bodies = []
    for side in range(2):
        ij = np.array([(j % m, j // m) for j in range(k)], dtype=float)
        st = 32.0 / m
        ij = (ij - (m - 1) / 2) * st + rng.uniform(-0.25, 0.25, (k, 2)) * st
        C = ij[:, :1] * u + ij[:, 1:] * v + side * 154.0 * w
        bodies.append(polyccd.Spheres(_grid(C), np.full(k, 64.0)))
    move = 8 * u + (np.array([-40, -40, -40]) if hit else 0)
    return [_body(polyccd, bodies[0]), _body(polyccd, bodies[1], _grid(move))]


def make(polyccd, family, n, hit=False, motion="translation"):
    """Two bodies of family with about n primitives in all (module docstring); motion:
    one of MOTIONS (_body; the rotations only for the families of NORMAL, apart)."""
    if motion != "translation" and (family not in NORMAL or hit):
        raise ValueError(f"{family}: no {motion} motion (hit={hit})")
    _motion.update(kind=motion, axis=NORMAL.get(family))
    try:
        return globals()[family](polyccd, n, hit)
    finally:
        _motion.update(kind="translation", axis=None)
