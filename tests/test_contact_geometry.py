"""SceneResult.contact_geometry (pccd_contact_geometry_compute / _exact): the contact point
and normal of a reported first contact.

Oracles: cases built so the answer is known (a vertex meeting a face at t = 1/2, two
balls); a rotating vertex whose first time 2 - sqrt(3) is irrational, with the point
computed by sympy at the exact root; and every reported contact of the corpus scenes
(corpus/bodies/) at an exact time, whose point must lie on both features at that time
(checked here with Fractions on positions from Motion.position), and whose normal must
match its definition (polyccd.h)."""
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import sympy

import polyccd
import polyccd.apps
from polyccd._contact import contact_geometry

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "bodies"
FILES = sorted(CORPUS.rglob("*.json"))


def test_vertex_meets_face_at_one_half():
    tri = polyccd.Body(polyccd.Mesh([[0, 0, 0], [4, 0, 0], [0, 4, 0]], [[0, 1, 2]]))
    pt = polyccd.Body(polyccd.Mesh([[1, 1, 1], [1, 1, 3], [2, 1, 3]], [[0, 1, 2]]),
                      polyccd.Motion.linear([0, 0, 0], [0, 0, -2]))
    r = polyccd.check([tri, pt])
    g = r.contact_geometry(0, 0)
    assert r.pairs[0].contacts[0].first_contact.exact == Fraction(1, 2)
    assert g.point == (1, 1, 0) and g.normal == (0, 0, 16)
    assert g.normal_state == "enclosed"
    assert np.all(g.point_lo <= [1, 1, 0]) and np.all([1, 1, 0] <= g.point_hi)
    assert np.all(g.normal_lo <= [0, 0, 1]) and np.all([0, 0, 1] <= g.normal_hi)


def test_balls_touch_at_a_known_point():
    a = polyccd.Body(polyccd.Spheres([[0, 0, 0]], [1]))
    b = polyccd.Body(polyccd.Spheres([[5, 0, 0]], [2]), polyccd.Motion.linear([0, 0, 0], [-4, 0, 0]))
    g = polyccd.check([a, b]).contact_geometry()
    assert g.point == (1, 0, 0) and g.normal == (3, 0, 0)
    # An index query's result holds its bodies too: the same geometry.
    h = polyccd.Index(a).query(b).contact_geometry()
    assert (h.point, h.normal) == (g.point, g.normal)


def rotating_vertex(tol):
    """Vertex (1, 0, 0) turning about z with half-angle tangent t (Motion.axis_rotation)
    meets the plate y = 1/2 when 2t / (1 + t^2) = 1/2: t* = 2 - sqrt(3)."""
    plate = polyccd.Body(polyccd.Mesh([[-10, "1/2", -10], [10, "1/2", -10], [0, "1/2", 10]],
                                      [[0, 1, 2]]))
    spinner = polyccd.Body(polyccd.Mesh([[1, 0, 0], [0, 0, 0], ["0.9", "-0.5", "0.1"]], [[0, 1, 2]]),
                           polyccd.Motion.axis_rotation([0, 0, 1], [0, 0, 0], 0, 1))
    return polyccd.check([plate, spinner], time_tolerance=tol)


def sympy_point():
    t = sympy.Symbol("t")
    roots = [x for x in sympy.solve(sympy.Eq(2 * t / (1 + t ** 2), sympy.Rational(1, 2)), t)
             if 0 <= x <= 1]
    assert len(roots) == 1
    ts = roots[0]
    return ts, [sympy.nsimplify((1 - ts ** 2) / (1 + ts ** 2)), sympy.Rational(1, 2), sympy.Integer(0)]


def test_irrational_time_encloses_the_sympy_point_and_shrinks():
    ts, point = sympy_point()
    widths = []
    for tol in ("1e-6", "1e-12"):
        r = rotating_vertex(tol)
        contacts = [(p, c) for p in r.pairs for c in p.contacts if c.b == ("vertex", 0)]
        assert contacts
        k = r.pairs[0].contacts.index(contacts[0][1])
        time = contacts[0][1].first_contact
        assert time.exact is None and sympy.Rational(time.lo) <= ts <= sympy.Rational(time.hi)
        g = r.contact_geometry(0, k)
        assert g.point is None and g.normal is None
        for lo, x, hi in zip(g.point_lo, point, g.point_hi):
            assert sympy.Rational(Fraction(lo)) <= x <= sympy.Rational(Fraction(hi))
        # The plate is stationary: its normal (20, 0, 20) x ... is (0, -1, 0) / 1 unit.
        n = np.cross(np.array([20, 0, 0]), np.array([10, 0, 20]))
        unit = n / np.linalg.norm(n)
        assert g.normal_state == "enclosed"
        assert np.all(g.normal_lo <= unit) and np.all(unit <= g.normal_hi)
        widths.append(max(g.point_hi - g.point_lo))
    assert widths[1] < widths[0] / 100


def world(body, p, t):
    """Exact world position of body point p at t (Fractions)."""
    return tuple(body.motion.position(p, t)) if body.motion is not None else tuple(map(Fraction, p))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def on_segment(p, a, b):
    d, w = sub(b, a), sub(p, a)
    if dot(d, d) == 0:
        return p == a
    return cross(w, d) == (0, 0, 0) and 0 <= dot(w, d) <= dot(d, d)


def on_triangle(p, t):
    n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
    if n == (0, 0, 0):
        return any(on_segment(p, t[k], t[(k + 1) % 3]) for k in range(3))
    if dot(n, sub(p, t[0])) != 0:
        return False
    return all(dot(cross(sub(t[(k + 1) % 3], t[k]), sub(p, t[k])), n) >= 0 for k in range(3))


def feature_points(body, feature, t):
    """The world points of a feature at t, and the radius for a ball."""
    kind, k = feature
    shape = body.shape
    if kind == "sphere":
        return [world(body, shape.exact_centers()[k], t)], Fraction(shape.exact_radii()[k])
    vs = shape.exact_vertices()
    idx = [k] if kind == "vertex" else list(shape.edges[k] if kind == "edge" else shape.triangles[k])
    return [world(body, vs[i], t) for i in idx], None


def on_feature(p, kind, pts, radius):
    if kind == "vertex":
        return p == pts[0]
    if kind == "edge":
        return on_segment(p, *pts)
    if kind == "triangle":
        return on_triangle(p, pts)
    return dot(sub(p, pts[0]), sub(p, pts[0])) <= radius * radius


def expected_normal(fa, pa, fb, pb, point):
    """The normal of polyccd.h's definitions (None: none defined), from the exact points."""
    kinds = (fa[0], fb[0])
    if sorted(kinds) == ["triangle", "vertex"]:
        t = pa if fa[0] == "triangle" else pb
        n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
    elif kinds == ("edge", "edge"):
        n = cross(sub(pa[1], pa[0]), sub(pb[1], pb[0]))
    elif kinds == ("sphere", "sphere"):
        n = sub(pb[0], pa[0])
    elif fa[0] == "sphere":
        n = sub(point, pa[0])
    elif fb[0] == "sphere":
        n = sub(pb[0], point)
    else:
        return None
    return None if n == (0, 0, 0) else n


EPS = Fraction(1, 2 ** 20)


def ge(x, c, n2):
    """x >= c sqrt(n2), exactly (n2 > 0)."""
    if c <= 0:
        return x >= 0 or x * x <= c * c * n2
    return x > 0 and x * x >= c * c * n2


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(CORPUS)))
def test_corpus_contacts_lie_on_both_features(path):
    bodies, _options, _expect = polyccd.apps.load_scene(str(path))
    r = polyccd.check(bodies, all_contacts=True)
    tight = None
    for i, p in enumerate(r.pairs):
        for k, c in enumerate(p.contacts):
            g = r.contact_geometry(i, k)
            assert np.all(g.point_lo <= g.point_hi)
            t = c.first_contact.exact
            if t is None:
                # Both enclosures hold the true point: one over a 1e-20 time enclosure
                # must meet this one.
                assert g.point is None
                tight = tight or polyccd.check(bodies, all_contacts=True, time_tolerance="1e-20")
                assert tight.pairs[i].contacts[k].a == c.a and tight.pairs[i].contacts[k].b == c.b
                h = tight.contact_geometry(i, k)
                assert np.all(np.maximum(g.point_lo, h.point_lo) <= np.minimum(g.point_hi, h.point_hi))
                continue
            a, b = bodies[p.bodies[0]], bodies[p.bodies[1]]
            pa, ra = feature_points(a, c.a, t)
            pb, rb = feature_points(b, c.b, t)
            assert on_feature(g.point, c.a[0], pa, ra), (c, g.point)
            assert on_feature(g.point, c.b[0], pb, rb), (c, g.point)
            assert all(Fraction(lo) <= x <= Fraction(hi)
                       for lo, x, hi in zip(g.point_lo, g.point, g.point_hi))
            assert g.normal == expected_normal(c.a, pa, c.b, pb, g.point)
            # The interval path: over a time enclosure around t the enclosures must hold
            # the exact point and unit normal.
            window = polyccd.ContactTime(max(t - EPS, Fraction(0)), min(t + EPS, Fraction(1)),
                                         None, float(t))
            h = contact_geometry(a, c.a, b, c.b, window)
            assert h.point is None and all(Fraction(lo) <= x <= Fraction(hi)
                                           for lo, x, hi in zip(h.point_lo, g.point, h.point_hi))
            assert (h.normal_state == "none") == (g.normal is None) or h.normal_state == "unknown"
            if h.normal_state == "enclosed":
                n2 = dot(g.normal, g.normal)
                assert all(ge(x, Fraction(lo), n2) and ge(-x, -Fraction(hi), n2)
                           for lo, x, hi in zip(h.normal_lo, g.normal, h.normal_hi))


def test_errors_name_the_argument():
    a = polyccd.Body(polyccd.Spheres([[0, 0, 0]], [1]))
    b = polyccd.Body(polyccd.Spheres([[5, 0, 0]], [2]), polyccd.Motion.linear([0, 0, 0], [-4, 0, 0]))
    r = polyccd.check([a, b])
    with pytest.raises(polyccd.InputError, match=r"^pair: expected an index from 0 to 0, got 1"):
        r.contact_geometry(1)
    with pytest.raises(polyccd.InputError, match=r"^contact: expected an index"):
        r.contact_geometry(0, 5)
    time = r.pairs[0].first_contact
    with pytest.raises(polyccd.InputError, match=r"^feature_b: triangle is not a feature of a sphere"):
        contact_geometry(a, ("sphere", 0), b, ("triangle", 0), time)
    with pytest.raises(polyccd.InputError, match=r"^index_a: 3 out of range \(1 sphere\)"):
        contact_geometry(a, ("sphere", 3), b, ("sphere", 0), time)
    with pytest.raises(polyccd.InputError, match=r'^feature_a\[0\]: expected "vertex"'):
        contact_geometry(a, ("ball", 0), b, ("sphere", 0), time)
    early = polyccd.ContactTime(Fraction(1, 4), Fraction(1, 4), Fraction(1, 4), 0.25)
    with pytest.raises(polyccd.InputError, match=r"^the features do not touch at t = 1/4"):
        contact_geometry(a, ("sphere", 0), b, ("sphere", 0), early)


def test_min_distance_contacts_apart_are_refused():
    """With min_distance the reported balls are within the distance, apart: no point."""
    a = polyccd.Body(polyccd.Spheres([[0, 0, 0]], [1]))
    b = polyccd.Body(polyccd.Spheres([[5, 0, 0]], [2]), polyccd.Motion.linear([0, 0, 0], [-4, 0, 0]))
    r = polyccd.check([a, b], min_distance="1")
    assert r.pairs[0].first_contact.exact == Fraction(1, 4)
    with pytest.raises(polyccd.InputError, match=r"do not touch at t = 1/4"):
        r.contact_geometry()
