"""Two boxes meeting corner to corner within delta (issue 33): every feature pair that
holds both corners (the corner of A against each triangle at B's corner, each triangle
at A's corner against B's corner, each edge at one corner against each edge at the
other) touches first, at the one time the corners come within delta. A body pair keeps
which of those shared vertex-vertex and vertex-edge features it has proven to touch at
irrational times only (lib/narrow/irrational_memo.h), so that the later feature pairs
skip their exact rationality test; a rational time must still come out exact for every
one of them.

Oracle: the boxes are axis-aligned and apart in all three axes until the first time,
so their distance is that of the corners, |g(t)| with g(t) = (1 - a t, 1 - a t,
1 - b t); the first time is the smaller root of |g|^2 = delta^2, rational (1/3, from
the Pythagorean (2, 2, 1) / 30; not dyadic, so the interval stage only encloses it) or
irrational (a = b), checked in Fractions."""
from fractions import Fraction as F

import pytest

import polyccd as P

DELTA = F(1, 10)
PHASES = ("bvh", "boxes", "brute")  # range takes no minimum distance


def boxes(a, b):
    """A: the unit box at the origin. B: the unit box whose centre moves from (2, 2, 2)
    to (2 - a, 2 - a, 2 - b): its corner (-1/2, -1/2, -1/2) faces A's (1/2, 1/2, 1/2)."""
    A = P.Body(P.Mesh.box([1, 1, 1]), name="A")
    end = [str(2 - a), str(2 - a), str(2 - b)]
    B = P.Body(P.Mesh.box([1, 1, 1]), P.Motion.linear([2, 2, 2], end), name="B")
    return A, B


def corner(mesh, sign):
    (k,) = [i for i, v in enumerate(mesh.vertices) if all(x == sign * 0.5 for x in v)]
    return k


def tied(mesh):
    """The contacts expected: every feature pair holding both corners."""
    ca, cb = corner(mesh, 1), corner(mesh, -1)
    tri_a = [i for i, t in enumerate(mesh.triangles) if ca in t]
    tri_b = [i for i, t in enumerate(mesh.triangles) if cb in t]
    edge_a = [i for i, e in enumerate(mesh.edges) if ca in e]
    edge_b = [i for i, e in enumerate(mesh.edges) if cb in e]
    return sorted([(("vertex", ca), ("triangle", t)) for t in tri_b] +
                  [(("triangle", t), ("vertex", cb)) for t in tri_a] +
                  [(("edge", e), ("edge", f)) for e in edge_a for f in edge_b])


def gap2(a, b, t):
    return 2 * (1 - a * t) ** 2 + (1 - b * t) ** 2


def first_time_in(a, b, lo, hi):
    """The first time is in [lo, hi]: |g|^2 decreases on [0, t*] (its minimum is later),
    so > delta^2 at lo (unless lo is t*) and <= delta^2 at hi bracket it."""
    d2 = DELTA * DELTA
    return gap2(a, b, lo) >= d2 >= gap2(a, b, hi) and all(
        gap2(a, b, lo * k / 64) > d2 for k in range(64))


@pytest.mark.parametrize("a, b, rational", [(F(14, 5), F(29, 10), True), (F(19, 10), F(19, 10), False)])
@pytest.mark.parametrize("phase", PHASES)
@pytest.mark.parametrize("threads", (1, 2))
def test_every_tied_feature_pair_gets_the_first_time(a, b, rational, phase, threads):
    A, B = boxes(a, b)
    r = P.check([A, B], min_distance=DELTA, broad_phase=phase, threads=threads)
    assert r.collides
    (pair,) = r.pairs
    got = sorted((c.a, c.b) for c in pair.contacts)
    assert got == tied(A.shape) and len(got) >= 15  # 3 or more triangles and edges a corner
    for c in pair.contacts:
        fc = c.first_contact
        if rational:
            assert fc.exact == F(1, 3) and gap2(a, b, fc.exact) == DELTA * DELTA, c
        else:
            assert fc.exact is None and first_time_in(a, b, fc.lo, fc.hi), c
            assert fc.hi - fc.lo <= F(1, 10 ** 12)
    assert (r.first_contact.exact == F(1, 3)) == rational
