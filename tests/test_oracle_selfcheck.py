"""The oracle's own tests (tests/oracle/oracle.py), independent of polyccd.

1. Hand-constructed cases whose answer follows from reasoning (stated per case).
2. A pointwise cross-check against a different formulation (tests/oracle/oracle_hull.py,
   Caratheodory subsets) at rational times: t = 0, 1, every rational critical time,
   random rationals, and just below the first contact time.
3. Invariances (vertex order of a triangle, edge order and direction, swapping the two
   primitives, a common affine map) and reductions between kinds (a zero-length edge is
   a vertex, a degenerate triangle is a segment).
"""
import random
from fractions import Fraction as F

import pytest

import oracle
import oracle_degen
import oracle_gen as G
from oracle_hull import contact_at_rational

E30 = F(1, 10 ** 30)


def P(x, y, z):
    """A trajectory; each coordinate a number (constant) or a coefficient list."""
    return [list(c) if isinstance(c, (list, tuple)) else [c] for c in (x, y, z)]


TRI = [P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)]        # static unit right triangle in z = 0
SEG = [P(-1, 0, 0), P(1, 0, 0)]                   # static segment on the x axis

# (name, kind, points, radii, expected first contact: None | Fraction | (minpoly, approx))
HAND = [
    # vertex-face
    ("vf falls through: z = 1 - 2t", "vertex-face", [P(F(1, 5), F(1, 5), [1, -2])] + TRI, None, F(1, 2)),
    ("vf z = 1 - 2t^2 hits at 1/sqrt(2)", "vertex-face", [P(F(1, 5), F(1, 5), [1, 0, -2])] + TRI, None,
     ([-1, 0, 2], 0.7071067811865476)),
    ("vf grazes: z = (t-1/2)^2", "vertex-face", [P(F(1, 5), F(1, 5), [F(1, 4), -1, 1])] + TRI, None, F(1, 2)),
    ("vf misses by 1e-30: z = (t-1/2)^2 + 1e-30", "vertex-face",
     [P(F(1, 5), F(1, 5), [F(1, 4) + E30, -1, 1])] + TRI, None, None),
    ("vf slides in plane, enters at x + y = 1", "vertex-face", [P([2, -3], F(1, 5), 0)] + TRI, None, F(2, 5)),
    ("vf slides in plane outside", "vertex-face", [P([2, -3], 2, 0)] + TRI, None, None),
    ("vf on vertex at t=0", "vertex-face", [P([0, 1], 0, [0, 1])] + TRI, None, F(0)),
    ("vf reaches plane at t=1", "vertex-face", [P(F(1, 4), F(1, 4), [1, -1])] + TRI, None, F(1)),
    ("vf through plane outside", "vertex-face", [P(1, 1, [1, -2])] + TRI, None, None),
    ("vf through the hypotenuse", "vertex-face", [P(F(1, 2), F(1, 2), [1, -2])] + TRI, None, F(1, 2)),
    ("vf through corner, 1e-30 outside", "vertex-face", [P(-E30, 0, [1, -2])] + TRI, None, None),
    ("vf collinear triangle hit", "vertex-face", [P(F(3, 2), [1, -2], 0), P(0, 0, 0), P(1, 0, 0), P(2, 0, 0)],
     None, F(1, 2)),
    ("vf collinear triangle missed", "vertex-face", [P(F(5, 2), [1, -2], 0), P(0, 0, 0), P(2, 0, 0), P(1, 0, 0)],
     None, None),
    ("vf point triangle", "vertex-face", [P([1, -2], 0, 0), P(0, 0, 0), P(0, 0, 0), P(0, 0, 0)], None, F(1, 2)),
    ("vf point triangle missed", "vertex-face", [P([1, -2], 1, 0), P(0, 0, 0), P(0, 0, 0), P(0, 0, 0)], None, None),
    ("vf face falls on point", "vertex-face",
     [P(F(1, 4), F(1, 4), 0), P(0, 0, [1, -4]), P(1, 0, [1, -4]), P(0, 1, [1, -4])], None, F(1, 4)),
    ("vf degree 5, rational root", "vertex-face", [P(F(1, 5), F(1, 5), [F(1, 32), 0, 0, 0, 0, -1])] + TRI,
     None, F(1, 2)),
    ("vf degree 5, 2^(-1/5)", "vertex-face", [P(F(1, 5), F(1, 5), [F(1, 2), 0, 0, 0, 0, -1])] + TRI, None,
     ([-1, 0, 0, 0, 0, 2], 0.8705505632961241)),
    ("vf degenerate at t=1/2 only", "vertex-face",
     [P(F(1, 2), 0, 0), P(0, 0, 0), P(1, 0, 0), P(0, [1, -2], 0)], None, F(0)),
    # edge-edge
    ("ee crossing at z = 1 - 2t", "edge-edge", SEG + [P(0, -1, [1, -2]), P(0, 1, [1, -2])], None, F(1, 2)),
    ("ee parallel, apart", "edge-edge", SEG + [P(-1, 1, [0, 1]), P(1, 1, [0, 1])], None, None),
    ("ee collinear, B slides onto A", "edge-edge", [P(0, 0, 0), P(1, 0, 0), P([3, -3], 0, 0), P([4, -3], 0, 0)],
     None, F(2, 3)),
    ("ee shared endpoint", "edge-edge", [P(0, 0, 0), P([1, 1], 0, 0), P(0, 0, 0), P(0, [1, 5], 0)], None, F(0)),
    ("ee endpoints meet at t=1", "edge-edge", [P(0, 0, 0), P(1, 0, 0), P(1, 0, [1, -1]), P(1, 1, [1, -1])],
     None, F(1)),
    ("ee grazing crossing z = (t-1/3)^2", "edge-edge",
     SEG + [P(0, -1, [F(1, 9), F(-2, 3), 1]), P(0, 1, [F(1, 9), F(-2, 3), 1])], None, F(1, 3)),
    ("ee near miss 1e-30", "edge-edge",
     SEG + [P(0, -1, [F(1, 9) + E30, F(-2, 3), 1]), P(0, 1, [F(1, 9) + E30, F(-2, 3), 1])], None, None),
    ("ee skew, lines cross outside B", "edge-edge", SEG + [P(0, 1, [1, -2]), P(0, 2, [1, -2])], None, None),
    ("ee zero-length A hits B at t=1/4", "edge-edge", [P(F(1, 2), 0, [1, -4])] * 2 + SEG, None, F(1, 4)),
    ("ee both zero-length, meet at sqrt(1/3)", "edge-edge",
     [P([-1, 0, 3], 0, 0)] * 2 + [P(0, 0, 0)] * 2, None, ([-1, 0, 3], 0.5773502691896258)),
    # vertex-edge
    ("ve through interior", "vertex-edge", [P(F(1, 3), [1, -3], 0)] + SEG, None, F(1, 3)),
    ("ve through endpoint", "vertex-edge", [P(1, [2, -3], 0)] + SEG, None, F(2, 3)),
    ("ve misses endpoint by 1e-30", "vertex-edge", [P(1 + E30, [2, -3], 0)] + SEG, None, None),
    ("ve collinear sliding", "vertex-edge", [P([3, -4], 0, 0)] + SEG, None, F(1, 2)),
    ("ve zero-length edge", "vertex-edge", [P([1, -1], 0, 0), P(F(1, 2), 0, 0), P(F(1, 2), 0, 0)], None, F(1, 2)),
    ("ve grazes at t=1 (double root)", "vertex-edge", [P(0, [1, -2, 1], 0)] + SEG, None, F(1)),
    # vertex-vertex
    ("vv meet at 1/3", "vertex-vertex", [P([1, -3], 2, 0), P(0, 2, 0)], None, F(1, 3)),
    ("vv never", "vertex-vertex", [P([1, -3], 2, 0), P(0, 2, E30)], None, None),
    ("vv meet at 1/sqrt(2)", "vertex-vertex", [P([1, 0, -2], 0, 0), P(0, 0, 0)], None,
     ([-1, 0, 2], 0.7071067811865476)),
    ("vv coincident", "vertex-vertex", [P([1, 2], 3, [0, 0, 7])] * 2, None, F(0)),
    ("vv x meets at 1/2, y at 1/3", "vertex-vertex", [P([1, -2], [1, -3], 0), P(0, 0, 0)], None, None),
    # sphere-sphere
    ("ss approach: |d| = 10 - 10t <= 2", "sphere-sphere", [P(0, 0, 0), P([10, -10], 0, 0)], [1, 1], F(4, 5)),
    ("ss touching at t=0", "sphere-sphere", [P(0, 0, 0), P([3, 1], 4, 0)], [2, 3], F(0)),
    ("ss grazing |d|^2 = 4 + (t-1/2)^4", "sphere-sphere", [P(0, 0, 0), P(2, [F(1, 4), -1, 1], 0)], [1, 1],
     F(1, 2)),
    ("ss near miss 1e-30", "sphere-sphere", [P(0, 0, 0), P(2 + E30, [F(1, 4), -1, 1], 0)], [1, 1], None),
    ("ss |d| = 3 - 2t^2 = 2 at 1/sqrt(2)", "sphere-sphere", [P(0, 0, 0), P([3, 0, -2], 0, 0)], [1, 1],
     ([-1, 0, 2], 0.7071067811865476)),
    ("ss touching at t=1", "sphere-sphere", [P(0, 0, 0), P([5, -1], 0, 0)], [2, 2], F(1)),
]


@pytest.mark.parametrize("case", HAND, ids=[c[0] for c in HAND])
def test_hand_case(case):
    name, kind, pts, radii, want = case
    res = oracle.solve(kind, pts, radii)
    assert res.collides == (want is not None), oracle.query_json(kind, pts, radii)
    if want is None:
        assert res.first is None
    elif isinstance(want, F):
        assert res.first == want
    else:
        coeffs, approx = want
        t = res.first
        assert not oracle.is_rational(t)
        assert G.trim([int(c) for c in t.f.coeffs()]) == coeffs
        lo, hi = t.enclosure(F(1, 10 ** 15))
        assert lo <= F(approx) + F(1, 10 ** 15) and F(approx) - F(1, 10 ** 15) <= hi
    # the hand answer agrees with the pointwise formulation at rational witnesses
    if isinstance(want, F):
        assert contact_at_rational(kind, pts, radii, want)


def cross_check(kind, pts, radii, rng):
    """Oracle answer vs the Caratheodory test at rational times."""
    res = oracle.solve(kind, pts, radii)
    where = oracle.query_json(kind, pts, radii)
    for x, c in zip(res.critical, res.point_contact):
        if oracle.is_rational(x):
            assert contact_at_rational(kind, pts, radii, x) == c, (where, x)
    first = res.first
    upto = F(1) if first is None else (first if oracle.is_rational(first) else first.lo)
    for _ in range(6):
        t = F(rng.randint(0, 997), 997) * upto
        if t != first:
            assert not contact_at_rational(kind, pts, radii, t), (where, t)
    if first is not None and not oracle.is_rational(first):
        lo, _ = first.enclosure(F(1, 10 ** 25))
        assert not contact_at_rational(kind, pts, radii, lo), (where, lo)
    # each gap: the answer at a random rational inside equals the gap's value
    for i, g in enumerate(res.gap_contact):
        a, b = res.critical[i], res.critical[i + 1]
        lo_ = a if oracle.is_rational(a) else a.hi
        hi_ = b if oracle.is_rational(b) else b.lo
        if lo_ < hi_:
            t = lo_ + (hi_ - lo_) * F(rng.randint(1, 96), 97)
            assert contact_at_rational(kind, pts, radii, t) == g, (where, t)
    return res


@pytest.mark.parametrize("kind", oracle.KINDS)
def test_cross_check_pointwise(kind):
    rng = random.Random(20240)
    for i in range(120):
        gen = G.random_query if i % 2 else oracle_degen.degenerate_query
        k, pts, radii, label = gen(rng, kind)
        cross_check(k, pts, radii, rng)


def same_time(a, b):
    if a is None or b is None or oracle.is_rational(a) or oracle.is_rational(b):
        return a == b
    return a.key == b.key


def variants(kind, pts, radii, rng):
    """(points, radii) of queries with the same answer: reorderings, swapping the two
    primitives, a common affine map (a common translation for balls)."""
    if kind == "vertex-face":
        f = pts[1:]
        out = [([pts[0]] + [f[i] for i in perm], radii)
               for perm in ((1, 0, 2), (2, 1, 0), (1, 2, 0))]
    elif kind == "edge-edge":
        a, b = pts[:2], pts[2:]
        out = [(b + a, radii), (a[::-1] + b, radii), (a + b[::-1], radii)]
    elif kind == "vertex-edge":
        out = [([pts[0], pts[2], pts[1]], radii)]
    else:
        out = [(pts[::-1], radii[::-1] if radii else radii)]
    if kind == "sphere-sphere":
        shift = G.rtraj(rng)
        out.append(([G.tadd(p, shift) for p in pts], radii))
    else:
        out.append((G.affine(rng, pts), radii))
    return out


@pytest.mark.parametrize("kind", oracle.KINDS)
def test_invariances(kind):
    rng = random.Random(777)
    for i in range(60):
        gen = G.random_query if i % 2 else oracle_degen.degenerate_query
        k, pts, radii, label = gen(rng, kind)
        ref = oracle.solve(k, pts, radii)
        for v, r in variants(k, pts, radii, rng):
            res = oracle.solve(k, v, r)
            assert res.collides == ref.collides, (label, oracle.query_json(k, pts, radii))
            assert same_time(res.first, ref.first), (label, oracle.query_json(k, pts, radii))


def test_kind_reductions():
    """Zero-length edges and degenerate triangles reduce to the smaller kinds."""
    rng = random.Random(99)
    for _ in range(150):
        q = [G.rtraj(rng) for _ in range(4)]
        if rng.random() < 0.5:      # make contacts happen: plant q0 at a convex combo
            _, q, _, _ = G.planted(rng, "vertex-face")
        pairs = [
            (("vertex-face", [q[0], q[1], q[2], q[2]]), ("vertex-edge", [q[0], q[1], q[2]])),
            (("vertex-face", [q[0], q[1], q[1], q[1]]), ("vertex-vertex", [q[0], q[1]])),
            (("edge-edge", [q[0], q[0], q[1], q[2]]), ("vertex-edge", [q[0], q[1], q[2]])),
            (("edge-edge", [q[0], q[0], q[1], q[1]]), ("vertex-vertex", [q[0], q[1]])),
            (("vertex-edge", [q[0], q[1], q[1]]), ("vertex-vertex", [q[0], q[1]])),
        ]
        for (k1, p1), (k2, p2) in pairs:
            r1, r2 = oracle.solve(k1, p1), oracle.solve(k2, p2)
            assert r1.collides == r2.collides, oracle.query_json(k1, p1)
            assert same_time(r1.first, r2.first), oracle.query_json(k1, p1)
