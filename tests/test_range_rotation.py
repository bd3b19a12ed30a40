"""The exact linearization of the range phase for relative rotations about a fixed axis
(lib/range/LINEARIZATION.md, "Rotations about a fixed axis"): when the query body's
rotation in the stored body's frame, conj(r_S(t)) r_Q(t), has degree 1 and some point is
fixed (Motion.axis_rotation, possibly composed with constant poses, against a body at
rest or in a constant pose), every query point moves on a circular arc about one line.

Checked here: random scenes of small meshes on a rational grid (coplanar sets sliding in
a plane turning about its normal, constant poses on either side, tau crossing 0, reversed
and large turns, tau0 == tau1), of ball sets and of mixes: the range phase equals brute
force over every feature pair, both modes, through P.check and P.Index (either body
stored), also scaled by 1e-200 ... 2^1100 (beyond double range); constructed cases
with known answers (grazing, contacts at t = 0 and 1, an edge turning into another
edge's plane, balls tangent at t = 1, an arc crossing a triangle
twice); the conditions filter: the same motion with a degree-2 quaternion (times 1 + t:
the "twin", on the general linearization) gives the same answers with at least as many
candidates, strictly more on near misses built for it.
"""
import math
import random
from fractions import Fraction as F

import pytest

import polyccd as P

from helpers import summary

TOL = "1e-9"
ID = [1, 0, 0, 0]


def grid(rng, k=4):
    return F(rng.randint(-k, k), 4)


def random_mesh(rng, flat=False):
    n = rng.randint(1, 5)
    v = [[grid(rng) for _ in range(3)] for _ in range(n + 2)]
    if flat or rng.random() < 0.3:  # coplanar sets
        v = [[x, y, F(0)] for x, y, _ in v]
    return P.Mesh(v, [[rng.randrange(n + 2) for _ in range(3)] for _ in range(n)])


def random_spheres(rng, flat=False):
    n = rng.randint(1, 4)
    return P.Spheres([[grid(rng) for _ in range(3)] for _ in range(n)],
                     [F(rng.randint(1, 6), 8) for _ in range(n)])


def random_quat(rng):
    q = [rng.randint(-2, 2) for _ in range(4)]
    return ID if q == [0, 0, 0, 0] else q


def random_rotation(rng, flat=False):
    """(axis, center, tau0, tau1): |tau| |axis| <= 3 (turns up to 2 atan 3 = 143 degrees
    either way); flat: about a z axis through a point of z = 0."""
    axis = [0, 0, rng.choice([-2, -1, 1, 2])] if flat else [rng.randint(-2, 2) for _ in range(3)]
    if axis == [0, 0, 0]:
        axis = [1, 0, 0]
    center = [grid(rng) for _ in range(2)] + [F(0) if flat else grid(rng)]
    m = int(12 / math.sqrt(sum(a * a for a in axis)))  # quarters
    tau0 = F(rng.randint(-m, m), 4)
    tau1 = tau0 if rng.random() < 0.1 else F(rng.randint(-m, m), 4)
    return axis, center, tau0, tau1


def posed(m, rng):
    """m with constant rational poses composed on the body and/or world side."""
    for side in ("body", "world"):
        if rng.random() < 0.3:
            m = m.compose(random_quat(rng), [grid(rng) for _ in range(3)], side=side)
    return m


def constant_pose(rng):
    """At rest (None) or a constant rational pose."""
    return None if rng.random() < 0.4 else P.Motion().compose(random_quat(rng), [grid(rng) for _ in range(3)])


def rotating_scene(rng, k, shapes):
    """Two bodies of the given shapes; body k % 2 turns, the other rests or keeps a pose."""
    flat = rng.random() < 0.2
    s = [shapes[i](rng, flat) for i in range(2)]
    m = posed(P.Motion.axis_rotation(*random_rotation(rng, flat)), rng)
    motions = [constant_pose(rng), m] if k % 2 else [m, constant_pose(rng)]
    return [P.Body(s[i], motions[i], f"b{i}") for i in range(2)]


def agree(bodies):
    """range == brute through P.check and P.Index (each body stored), both modes; returns
    the brute results (first contact, all contacts) of [bodies[0], bodies[1]]."""
    out = []
    for all_contacts in (False, True):
        kw = dict(all_contacts=all_contacts, time_tolerance=TOL)
        for i, j in ((0, 1), (1, 0)):
            pair = [bodies[i], bodies[j]]
            want = P.check(pair, broad_phase="brute", **kw)
            assert summary(P.check(pair, broad_phase="range", **kw)) == summary(want), (i, all_contacts)
            assert summary(P.Index(pair[0]).query(pair[1], **kw)) == summary(want), (i, all_contacts)
            if i == 0:
                out.append(want)
    return out


@pytest.mark.parametrize("k", range(100))
def test_rotation_range_equals_brute(k):
    agree(rotating_scene(random.Random(20261124 + k), k, (random_mesh, random_mesh)))


CASES = [("balls", k) for k in range(40)] + [("mix", k) for k in range(12)]


@pytest.mark.parametrize("kind,k", CASES, ids=[f"{a}{k}" for a, k in CASES])
def test_rotation_spheres_range_equals_brute(kind, k):
    mix = (random_mesh, random_spheres) if k % 4 < 2 else (random_spheres, random_mesh)
    shapes = (random_spheres,) * 2 if kind == "balls" else mix
    agree(rotating_scene(random.Random(30261124 + k + 100 * (kind == "mix")), k, shapes))


SCALES = [F(10) ** -200, F(10) ** -12, F(10) ** 12, F(10) ** 200, F(2) ** 1100]


@pytest.mark.parametrize("scale", SCALES, ids=["1e-200", "1e-12", "1e12", "1e200", "2^1100"])
def test_rotation_extreme_scales(scale):
    """Grid scenes scaled by tiny and huge factors (2^1100 is beyond double range: the
    interval filters overflow and must fall back, never filter wrongly)."""
    rng = random.Random(4242)
    hits = 0
    for k in range(4):
        g = lambda: grid(rng) * scale  # noqa: E731
        mesh = lambda: P.Mesh([[g() for _ in range(3)] for _ in range(5)],  # noqa: E731
                              [[0, 1, 2], [1, 2, 3], [2, 3, 4]])
        axis, center, tau0, tau1 = random_rotation(rng)
        m = P.Motion.axis_rotation(axis, [c * scale for c in center], tau0, tau1)
        bodies = [P.Body(mesh(), None, "a"), P.Body(mesh(), m, "b")]
        hits += agree(bodies)[0].collides
    assert hits >= 1  # the scale-free generator (seed fixed) collides in some of them


def test_generator_makes_contacts():
    """Measured: 30 of the 100 mesh scenes collide (19 first after t = 0), 15 of the 40
    ball scenes (10 after t = 0)."""
    def hits(seed, n, shapes):
        rs = [P.check(rotating_scene(random.Random(seed + k), k, shapes), time_tolerance=TOL) for k in range(n)]
        return sum(r.collides for r in rs), sum(r.collides and r.first_contact.hi > 0 for r in rs)
    meshes = hits(20261124, 100, (random_mesh, random_mesh))
    balls = hits(30261124, 40, (random_spheres, random_spheres))
    assert meshes[0] >= 20 and meshes[1] >= 12 and balls[0] >= 10 and balls[1] >= 6, (meshes, balls)


# ---------------------------------------------------------------- known answers

Z = [0, 0, 1]
SPOKE = P.Mesh([[1, 0, 0], [F(1, 2), 0, 0], [F(1, 2), F(-1, 4), 0]], [[0, 1, 2]])  # radius 1 at vertex 0 only


def contacts(r):
    return [(c.a, c.b, c.first_contact.exact) for p in r.pairs for c in p.contacts]


def test_grazing_vertex():
    # Vertex 0 on the unit circle about the z axis, tau = 2t: y = 4t / (1 + 4t^2) = 1
    # only at t = 1/2, a double root; the point (0, 1, 0) is inside the triangle in y = 1.
    wall = P.Mesh([[-1, 1, -1], [1, 1, -1], [0, 1, 1]], [[0, 1, 2]])
    first, every = agree([P.Body(wall), P.Body(SPOKE, P.Motion.axis_rotation(Z, [0, 0, 0], 0, 2))])
    assert first.first_contact.exact == F(1, 2)
    assert contacts(every) == [(("triangle", 0), ("vertex", 0), F(1, 2))]


def test_contacts_at_start_and_end():
    # The triangle in y = 0 holds (1, 0, 0) (at z = 0 it spans 3/4 <= x <= 3/2); the
    # query triangle spans the angles [-45, 0] degrees: it turns clockwise away from the
    # touch at t = 0 (tau 0 -> -1), or counterclockwise into it at t = 1 (tau -1 -> 0).
    wall = P.Mesh([[F(1, 2), 0, -1], [2, 0, -1], [1, 0, 1]], [[0, 1, 2]])
    tri = P.Mesh([[1, 0, 0], [F(1, 2), F(-1, 2), 0], [1, F(-1, 2), 0]], [[0, 1, 2]])
    start, _ = agree([P.Body(wall), P.Body(tri, P.Motion.axis_rotation(Z, [0, 0, 0], 0, -1))])
    assert start.collides and start.first_contact.exact == 0
    end, every = agree([P.Body(wall), P.Body(tri, P.Motion.axis_rotation(Z, [0, 0, 0], -1, 0))])
    assert end.first_contact.exact == 1
    assert contacts(every) == [(("triangle", 0), ("vertex", 0), 1)]


def test_edge_turns_into_the_plane_of_an_edge():
    # The query triangle (x in [1/2, 1]) turns about the y axis, theta from -90 to 90
    # degrees: its points (x cos theta, y, -x sin theta) reach x >= 1 only at theta = 0
    # (t = 1/2), when it lies in z = 0 and its edge x = 1 passes through the endpoint
    # (1, 0, 0) of the stored edge (1,0,0)-(2,0,0), coplanar with it.
    stored = P.Mesh([[1, 0, 0], [2, 0, 0], [2, 0, -1]], [[0, 1, 2]])
    tri = P.Mesh([[1, -1, 0], [1, 1, 0], [F(1, 2), 0, 0]], [[0, 1, 2]])
    first, every = agree([P.Body(stored), P.Body(tri, P.Motion.axis_rotation([0, 1, 0], [0, 0, 0], -1, 1))])
    assert first.first_contact.exact == F(1, 2)
    # At t = 1/2: stored vertex 0 on the closed query triangle, and the stored edges
    # 0 (0,1) and 1 (0,2) through it against the query edge 0 (0,1), x = 1.
    assert sorted(contacts(every)) == [(("edge", 0), ("edge", 0), F(1, 2)), (("edge", 1), ("edge", 0), F(1, 2)),
                                       (("vertex", 0), ("triangle", 0), F(1, 2))]


def test_balls_tangent_at_the_end():
    # Centre (3/5, 4/5, 0) at t = 1 (distance 1 = 1/2 + 1/2); before, it turns
    # counterclockwise about (1, 0, 0) from 90 degrees back, farther from the origin.
    ball = P.Spheres([[0, 0, 0]], [F(1, 2)])
    other = P.Spheres([[F(3, 5), F(4, 5), 0]], [F(1, 2)])
    first, every = agree([P.Body(ball), P.Body(other, P.Motion.axis_rotation(Z, [1, 0, 0], -1, 0))])
    assert first.first_contact.exact == 1
    assert contacts(every) == [(("sphere", 0), ("sphere", 0), 1)]


@pytest.mark.parametrize("tau0,tau1,t", [(0, 4, F(1, 12)), (4, 0, F(1, 4))])
def test_arc_crosses_a_triangle_twice(tau0, tau1, t):
    # Vertex 0 at angle theta has y = sin theta = 3/5 at tan(theta/2) = 1/3 and 3; tau = 4t
    # or 4 - 4t: roots 1/12 and 3/4, or 1/4 and 11/12; the other vertices stay below
    # y = 3/5 (radius < 3/5). Both crossings lie inside the triangle in y = 3/5.
    wall = P.Mesh([[-2, F(3, 5), -1], [2, F(3, 5), -1], [0, F(3, 5), 2]], [[0, 1, 2]])
    first, every = agree([P.Body(wall), P.Body(SPOKE, P.Motion.axis_rotation(Z, [0, 0, 0], tau0, tau1))])
    assert first.first_contact.exact == t
    assert (("triangle", 0), ("vertex", 0), t) in contacts(every)


# ---------------------------------------------------------------- the conditions filter

def twin(axis, center, tau0, tau1):
    """axis_rotation(axis, center, tau0, tau1) with the quaternion times (1 + t)."""
    b = tau1 - tau0
    tau = [tau0, tau0 + b, b]  # (1 + t) tau(t), ascending powers
    m = P.Motion(translation=[[0], [0], [0]], rotation=[[1, 1]] + [[a * c for c in tau] for a in axis])
    return m.compose(ID, [-c for c in center], side="body").compose(ID, list(center), side="world")


def twins(axis, center, tau0, tau1):
    a, b = P.Motion.axis_rotation(axis, center, tau0, tau1), twin(axis, center, tau0, tau1)
    for t in (0, F(1, 3), F(1, 2), F(5, 7), 1):
        for p in ([0, 0, 0], [1, F(-2, 3), F(5, 4)], [F(-7, 2), 3, 1]):
            assert a.position(p, t) == b.position(p, t), (axis, center, tau0, tau1, p, t)
    return a, b


def same_answers(ra, rb):
    """Equal answers up to the enclosures of irrational times: the twin's contact
    polynomials differ (by powers of 1 + t), so they refine to other intervals of width
    <= the tolerance around the same t*."""
    def times(r):
        def t(ct):
            return None if ct is None else (ct.lo, ct.hi, ct.exact)
        return sorted([((), t(r.first_contact))] + [((p.bodies,), t(p.first_contact)) for p in r.pairs]
                      + [((p.bodies, c.a, c.b), t(c.first_contact)) for p in r.pairs for c in p.contacts],
                      key=lambda x: x[0])
    assert ra.collides == rb.collides and [p.bodies for p in ra.first] == [p.bodies for p in rb.first]
    ta, tb = times(ra), times(rb)
    assert [k for k, _ in ta] == [k for k, _ in tb]
    for (_, s), (_, t) in zip(ta, tb):
        assert s == t or (None not in (s, t) and s[2] is t[2] is None and s[0] <= t[1] and t[0] <= s[1]), (s, t)


NEAR_MISSES = {
    # A fan covering |x| + |y| <= 2 in z = 0; a small triangle at x in [3/2, 8/5] turns
    # about the line y = 3/2, z = 0 by up to 127 degrees either way: its vertices' circles
    # (radii 1/10, sqrt(2)/10) cross z = 0 at y = 3/2 +- 1/7 at most, inside the box
    # [0, 2]^2 of the triangle (0,0) (2,0) (0,2) but at x + y > 2.8, outside every triangle.
    "fan": (P.Mesh([[0, 0, 0], [2, 0, 0], [0, 2, 0], [-2, 0, 0], [0, -2, 0]],
                   [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]),
            P.Mesh([[F(3, 2), F(3, 2), F(1, 10)], [F(8, 5), F(3, 2), F(1, 10)], [F(3, 2), F(8, 5), F(1, 10)]],
                   [[0, 1, 2]]),
            ([1, 0, 0], [0, F(3, 2), 0], -2, 2)),
    # Vertex 0 at radius 1 about the z axis, turning +-53 degrees about its closest point
    # (1, 0, 0) to the plane x = 51/50, which it never reaches (nor does any point of the
    # triangle, all within radius 1). Both shapes are 20 or more across and the turn moves
    # points by <= 1.9: one time piece, on which the arc's plane polynomial changes sign
    # in Bernstein form.
    "near_plane": (P.Mesh([[F(51, 50), -20, -20], [F(51, 50), 20, -20], [F(51, 50), 0, 20]], [[0, 1, 2]]),
                   P.Mesh([[1, 0, 0], [0, 0, 10], [0, 0, -10]], [[0, 1, 2]]),
                   (Z, [0, 0, 0], F(-1, 2), F(1, 2))),
}


@pytest.mark.parametrize("case", sorted(NEAR_MISSES))
def test_rotation_conditions_filter(case):
    stored, query, rot = NEAR_MISSES[case]
    a, b = twins(*rot)
    ra, rb, brute = (P.check([P.Body(stored), P.Body(query, m)], broad_phase=bp, all_contacts=True)
                     for m, bp in ((a, "range"), (b, "range"), (a, "brute")))
    assert not ra.collides and not rb.collides and not brute.collides
    assert ra.stats["candidates"] < rb.stats["candidates"], (ra.stats, rb.stats)


def test_rotation_and_general_agree_on_counts():
    """Same geometry through both linearizations: the exact one never reports more
    (times compared by same_answers: the enclosures of irrational ones may differ)."""
    rng = random.Random(11)
    fewer = 0
    for k in range(40):
        m0, m1 = random_mesh(rng), random_mesh(rng)
        axis, center, tau0, tau1 = random_rotation(rng)
        if tau0 == tau1:
            tau1 = tau0 + 1
        a, b = twins(axis, center, tau0, tau1)
        state = rng.getstate()  # the same constant poses on both
        a = posed(a, rng)
        rng.setstate(state)
        b = posed(b, rng)
        pose, o = constant_pose(rng), slice(None, None, 1 - 2 * (k % 2))  # turning body first when k is odd
        ra = P.check([P.Body(m0, pose), P.Body(m1, a)][o], broad_phase="range", all_contacts=True)
        rb = P.check([P.Body(m0, pose), P.Body(m1, b)][o], broad_phase="range", all_contacts=True)
        same_answers(ra, rb)
        assert ra.stats["candidates"] <= rb.stats["candidates"], (k, ra.stats, rb.stats)
        fewer += ra.stats["candidates"] < rb.stats["candidates"]
    assert fewer > 0
