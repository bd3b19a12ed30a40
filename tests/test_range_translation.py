"""The exact translation linearization of the range phase (lib/range/LINEARIZATION.md,
"Linear translations"): when both bodies translate linearly (constant rotations), each
query point moves on a segment relative to the stored body and the Plücker side
conditions (vertex-triangle both ways, edge-parallelogram) join the query.

Checked here: on scenes built to make those conditions matter (vertices passing just
beside triangles and edges inside their boxes, coplanar sliding, parallel edges, contacts
at t = 0 and t = 1, constant rotated poses), the range phase equals brute force over all
feature pairs, in first-contact and all-contacts modes; and the conditions filter: the
same geometry with a constant rotation written as a degree-1 quaternion (which takes the
general linearization) gets at least as many candidates, and strictly more in a case
built for it.
"""
import random
from fractions import Fraction as F

import pytest

import polyccd as P

from helpers import summary


def grid(rng, k=4):
    return F(rng.randint(-k, k), 4)


def random_mesh(rng):
    n = rng.randint(1, 5)
    v = [[grid(rng) for _ in range(3)] for _ in range(n + 2)]
    if rng.random() < 0.3:  # coplanar sets: sliding contacts
        for p in v:
            p[2] = F(0)
    t = [[rng.randrange(n + 2) for _ in range(3)] for _ in range(n)]
    return P.Mesh(v, t)


def random_translation(rng, rotated):
    if rng.random() < 0.15:
        m = None if not rotated else P.Motion()
    else:
        p0 = [grid(rng) for _ in range(3)]
        p1 = [c + grid(rng, 6) if rng.random() < 0.8 else c for c in p0]
        m = P.Motion.linear(p0, p1)
    if rotated:  # a constant rotation of the body (rational quaternion, any length)
        q = [rng.randint(-2, 2) for _ in range(4)]
        if q == [0, 0, 0, 0]:
            q = [1, 0, 0, 0]
        m = m.compose(q, [0, 0, 0], side="body")
    return m


@pytest.mark.parametrize("k", range(120))
def test_translation_range_equals_brute(k):
    rng = random.Random(20261123 + k)
    rotated = k % 3 == 0
    bodies = [P.Body(random_mesh(rng), random_translation(rng, rotated), f"b{i}") for i in range(2)]
    for all_contacts in (False, True):
        brute = summary(P.check(bodies, broad_phase="brute", all_contacts=all_contacts,
                                time_tolerance="1e-9"))
        got = summary(P.check(bodies, broad_phase="range", all_contacts=all_contacts,
                              time_tolerance="1e-9"))
        assert got == brute, (k, all_contacts)
        ix = P.Index(bodies[0])
        assert summary(ix.query(bodies[1], all_contacts=all_contacts, time_tolerance="1e-9")) == brute


def test_generator_makes_contacts():
    hits = sum(P.check([P.Body(random_mesh(r), random_translation(r, False)) for _ in range(2)]).collides
               for r in (random.Random(20261123 + k) for k in range(120)))
    assert hits >= 20, hits


def _degree_one_constant_rotation():
    """r(t) = (1 + t) * 1: the identity rotation, written with degree 1."""
    return [[1, 1], [0], [0], [0]]


def test_side_conditions_filter():
    # A fan of four triangles around the origin in z = 0 (stored); a small query
    # triangle falls straight down through z = 0 at (3/2, 3/2) + [0, 1/10]^2: inside the
    # box [0, 2]^2 of the fan's triangle (0,0) (2,0) (0,2) but outside it (x + y >= 3 > 2),
    # so only the side conditions can drop that triangle.
    fan = P.Mesh([[0, 0, 0], [2, 0, 0], [0, 2, 0], [-2, 0, 0], [0, -2, 0]],
                 [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]])
    tri = P.Mesh([[0, 0, 0], [F(1, 10), 0, 0], [0, F(1, 10), 0]], [[0, 1, 2]])
    path = ([F(3, 2), F(3, 2), 1], [F(3, 2), F(3, 2), -1])
    plain = P.Motion.linear(*path)
    general = P.Motion([[F(3, 2)], [F(3, 2)], [1, -2]], _degree_one_constant_rotation())
    stored = P.Body(fan, None, "fan")
    a = P.check([stored, P.Body(tri, plain, "q")], broad_phase="range", all_contacts=True)
    b = P.check([stored, P.Body(tri, general, "q")], broad_phase="range", all_contacts=True)
    brute = P.check([stored, P.Body(tri, plain, "q")], broad_phase="brute", all_contacts=True)
    assert not a.collides and not b.collides and not brute.collides
    assert a.stats["candidates"] < b.stats["candidates"], (a.stats, b.stats)


def test_translation_and_general_linearization_agree_on_counts():
    """Same geometry through both linearizations: the translation one never reports more."""
    rng = random.Random(7)
    more = 0
    for k in range(60):
        m0, m1 = random_mesh(rng), random_mesh(rng)
        p0 = [grid(rng) for _ in range(3)]
        p1 = [grid(rng, 6) for _ in range(3)]
        lin = P.Motion.linear(p0, p1)
        gen = P.Motion([[a, b - a] for a, b in zip(p0, p1)], _degree_one_constant_rotation())
        for a, b in ((lin, gen),):
            ra = P.check([P.Body(m0), P.Body(m1, a)], broad_phase="range", all_contacts=True)
            rb = P.check([P.Body(m0), P.Body(m1, b)], broad_phase="range", all_contacts=True)
            assert summary(ra) == summary(rb)
            assert ra.stats["candidates"] <= rb.stats["candidates"]
            more += ra.stats["candidates"] < rb.stats["candidates"]
    assert more > 0
