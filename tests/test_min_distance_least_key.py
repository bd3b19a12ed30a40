"""The feature pair a body pair reports within delta at t = 0 (issue 33): the driver's
witness pass solves the pair of least key (type VF < FV < EE, then the feature of A, then
of B) that is within delta at t = 0 (lib/scene/pair_search.cpp, within_at_zero), found by
a best-first search of the hierarchies at t = 0 (lib/bvh/least_at_zero.h) rather than by
listing and sorting every candidate. Checked against an independent oracle: every
feature pair's exact squared distance at t = 0 in Fractions (brute force, in key order),
on sheets with shuffled vertex and triangle numbers (so key order is not space order),
in decide mode (the witness pass reports that one pair) for every broad phase and thread
count; and on cases built so that only FV pairs, or only EE pairs, are within delta."""
import random
from fractions import Fraction as F

import pytest

import polyccd as P
from oracle_distance import point_triangle, segment_segment

DELTA = F(1, 16)


def edges(tris):
    return sorted({tuple(sorted((t[i], t[(i + 1) % 3]))) for t in tris for i in range(3)})


def least_within(va, ta, vb, tb):
    """The least-key feature pair within DELTA of (va, ta) and (vb, tb), as the features
    a contact reports, or None (exact, brute force over every pair in key order)."""
    d2 = DELTA * DELTA
    used_a, used_b = sorted({k for t in ta for k in t}), sorted({k for t in tb for k in t})
    for v in used_a:
        for f, t in enumerate(tb):
            if point_triangle(va[v], *[vb[k] for k in t]) <= d2:
                return ("vertex", v), ("triangle", f)
    for f, t in enumerate(ta):
        for v in used_b:
            if point_triangle(vb[v], *[va[k] for k in t]) <= d2:
                return ("triangle", f), ("vertex", v)
    for i, (p, q) in enumerate(edges(ta)):
        for j, (r, s) in enumerate(edges(tb)):
            if segment_segment(va[p], va[q], vb[r], vb[s]) <= d2:
                return ("edge", i), ("edge", j)
    return None


def sheet(rng, n, z, bump):
    """An n x n grid of squares of side 1/8 at height z, each vertex raised by a random
    dyadic in [0, bump] (bump signed), vertices and triangles shuffled."""
    order = list(range((n + 1) ** 2))
    rng.shuffle(order)  # order[k]: the new number of grid vertex k
    v = [None] * len(order)
    for j in range(n + 1):
        for i in range(n + 1):
            v[order[j * (n + 1) + i]] = [F(i, 8), F(j, 8), z + bump * F(rng.randrange(17), 16)]
    t = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            t += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    t = [[order[k] for k in tri] for tri in t]
    rng.shuffle(t)
    return v, t


def reported(bodies):
    """The contact of each broad phase and thread count in decide mode (all equal)."""
    out = set()
    for phase in ("bvh", "boxes", "brute"):
        for threads in (1, 2):
            r = P.check(bodies, min_distance=DELTA, first_contact=False, broad_phase=phase, threads=threads)
            if not r.collides:
                out.add(None)
                continue
            (pair,) = r.pairs
            assert len(pair.contacts) == 1, (phase, threads, pair.contacts)
            c = pair.contacts[0]
            out.add((c.a, c.b))
    assert len(out) == 1, out
    return out.pop()


@pytest.mark.parametrize("seed", range(12))
def test_sheets_report_the_least_key_within_delta(seed):
    """Two bumpy sheets facing each other across a gap of 0 to 3/2 delta (A below, bumps
    down; B above, bumps up), B sliding away: many feature pairs within delta at t = 0,
    the least key among them reported."""
    rng = random.Random(seed)
    gap = DELTA * F(rng.randrange(25), 16)
    va, ta = sheet(rng, 4, F(0), F(-1, 32))
    vb, tb = sheet(rng, 3, gap, F(1, 32))
    for x in vb:  # B shifted in x, y by a random dyadic, so its grid is not A's
        x[0] += F(rng.randrange(-8, 9), 64)
        x[1] += F(rng.randrange(-8, 9), 64)
    want = least_within(va, ta, vb, tb)
    a = P.Body(P.Mesh(va, ta), name="a")
    b = P.Body(P.Mesh(vb, tb), P.Motion.linear([0, 0, 0], [0, 0, 1]), name="b")
    assert reported([a, b]) == want, (seed, str(gap))


@pytest.mark.parametrize("gap", [DELTA / 2, DELTA, DELTA + F(1, 2 ** 40)])
def test_only_fv_within_delta(gap):
    """A large triangle (its vertices far from B) under a small sheet of B: only FV pairs
    can be within delta."""
    rng = random.Random(7)
    va, ta = [[F(-4), F(-4), F(0)], [F(4), F(-4), F(0)], [F(0), F(4), F(0)]], [[0, 1, 2]]
    vb, tb = sheet(rng, 2, gap, F(1, 32))
    want = least_within(va, ta, vb, tb)
    assert want is None or want[0][0] == "triangle"
    assert reported([P.Body(P.Mesh(va, ta), name="a"), P.Body(P.Mesh(vb, tb), name="b")]) == want


@pytest.mark.parametrize("gap", [DELTA / 2, DELTA, DELTA + F(1, 2 ** 40)])
def test_only_ee_within_delta(gap):
    """Two triangles whose long edges cross gap apart (A's along x at z = 0, B's along y
    at z = gap), their other vertices and faces farther: only an EE pair can be within
    delta."""
    va, ta = [[F(-1), F(0), F(0)], [F(1), F(0), F(0)], [F(0), F(0), F(-1)]], [[0, 1, 2]]
    vb, tb = [[F(0), F(-1), gap], [F(0), F(1), gap], [F(0), F(0), 1 + gap]], [[0, 1, 2]]
    want = least_within(va, ta, vb, tb)
    assert (want is None) == (gap > DELTA)
    assert want is None or want[0][0] == "edge"
    assert reported([P.Body(P.Mesh(va, ta), name="a"), P.Body(P.Mesh(vb, tb), name="b")]) == want
