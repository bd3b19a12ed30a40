"""The range broad phase (linearized contact conditions, lifted points in CGAL kd-trees;
lib/range/LINEARIZATION.md) on constructed scenes whose answers are known: it must agree
with brute force and must actually filter (a test that every candidate passes would not
show the structure works)."""
from fractions import Fraction as F

import helpers
import polyccd as P


def cube(s=1):
    return helpers.cube([0, 0, 0], s)


def grid_plate(n):
    """An n x n grid of unit squares in z = 0 (2 n^2 triangles)."""
    v = [[i, j, 0] for j in range(n + 1) for i in range(n + 1)]
    t = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            t += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return P.Mesh(v, t)


def key(res):
    return [(p.bodies, p.first_contact.lo, p.first_contact.hi,
             [(c.a, c.b, c.first_contact.lo, c.first_contact.hi) for c in p.contacts]) for p in res.pairs]


def both(bodies, **kw):
    r = P.check(bodies, broad_phase="range", time_tolerance="1e-9", **kw)
    b = P.check(bodies, broad_phase="brute", time_tolerance="1e-9", **kw)
    return r, b


def test_near_miss_by_1e_30_has_no_candidates():
    # a unit cube slides over the plate, its bottom 1e-30 above it all the time
    gap = F(1, 10 ** 30)
    m = P.Motion.linear([F(1, 2), F(1, 2), gap], [F(13, 2), F(1, 2), gap])
    bodies = [P.Body(grid_plate(8), None), P.Body(cube(), m)]
    r, b = both(bodies)
    assert not r.collides and not b.collides
    assert r.stats["candidates"] == 0 and b.stats["solved"] > 1000


def test_landing_on_the_plate_exact_time_and_few_candidates():
    # the cube drops from z = 1 to z = -1: its bottom face lands at t = 1/2, on a grid
    # vertex (corner (3, 3, .)): vertex-vertex, edge-edge and face contacts at once
    m = P.Motion.linear([3, 3, 1], [3, 3, -1])
    bodies = [P.Body(grid_plate(8), None), P.Body(cube(), m)]
    r, b = both(bodies)
    assert r.collides and r.first_contact.exact == F(1, 2)
    assert [(c.a, c.b) for c in r.pairs[0].contacts] == [(c.a, c.b) for c in b.pairs[0].contacts]
    assert r.stats["solved"] < b.stats["solved"] / 20


def test_rotation_grazing_the_plate():
    # a cube 1/1000 above the plate turning a quarter turn about the line y = 0, z = 1
    # (body frame): turning one way its bottom edge y = 1 dips below z = 0 (first contact
    # early, irrational time), turning the other way it lifts off (no contact at all)
    for axis, hits in (([-1, 0, 0], True), ([1, 0, 0], False)):
        m = P.Motion.axis_rotation(axis, [0, 0, 1], 0, 1).compose([1, 0, 0, 0], [2, 2, F(1, 1000)],
                                                                  side="world")
        bodies = [P.Body(grid_plate(6), None), P.Body(cube(), m)]
        for all_contacts in (False, True):
            r, b = both(bodies, all_contacts=all_contacts)
            assert r.collides == b.collides == hits
            assert r.stats["solved"] < b.stats["solved"] / 10
            assert key(r) == key(b)


def test_molecules_balls_range_equals_brute():
    c = [[i, j, k] for i in range(3) for j in range(3) for k in range(3)]
    A = P.Spheres(c, [F(1, 3)] * len(c))
    # B approaches along x; balls of radius 1/3 touch when centres are 2/3 apart
    m = P.Motion.linear([5, F(1, 2), 0], [2, F(1, 2), 0])
    bodies = [P.Body(A, None), P.Body(P.Spheres([[0, 0, 0]], [F(1, 3)]), m)]
    r, b = both(bodies)
    assert r.collides and b.collides
    assert (r.first_contact.lo, r.first_contact.hi) == (b.first_contact.lo, b.first_contact.hi)
    assert r.stats["solved"] < b.stats["solved"]
