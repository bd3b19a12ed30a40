"""Poses in: Motion.between (pccd_motion_set_between_*) and the Mesh.box / Mesh.cylinder
helpers, checked against exact Fraction arithmetic written here from the rotation formula
of docs/formats.md, R(r) = ((w^2 - |v|^2) I + 2 v v^T + 2 w [v]x) / (w^2 + |v|^2)."""
import math
import random
from fractions import Fraction as F

import numpy as np
import pytest

import polyccd


def rotate(q, p):
    """R(q) p exactly, q = (w, x, y, z) Fractions (any nonzero length)."""
    w, v = q[0], q[1:]
    n = w * w + sum(c * c for c in v)
    vv = sum(a * b for a, b in zip(v, p))
    cross = (v[1] * p[2] - v[2] * p[1], v[2] * p[0] - v[0] * p[2], v[0] * p[1] - v[1] * p[0])
    vn = sum(c * c for c in v)
    return tuple(((w * w - vn) * p[i] + 2 * v[i] * vv + 2 * w * cross[i]) / n for i in range(3))


def expected(p0, q0, p1, q1, p, t):
    """The documented path: o = (1 - t) p0 + t p1, r = (1 - t) q0 + t q1', q0 . q1' >= 0."""
    s = -1 if sum(a * b for a, b in zip(q0, q1)) < 0 else 1
    r = [(1 - t) * a + t * s * b for a, b in zip(q0, q1)]
    x = rotate(r, p)
    return tuple(x[i] + (1 - t) * p0[i] + t * p1[i] for i in range(3))


def fr(v):
    return tuple(F(x) for x in v)


@pytest.mark.parametrize("seed", range(6))
def test_between_pairs_follow_the_stated_path_exactly(seed):
    rng = random.Random(seed)
    p0, p1 = [[rng.uniform(-2, 2) for _ in range(3)] for _ in range(2)]
    q0, q1 = [[rng.uniform(-1, 1) for _ in range(4)] for _ in range(2)]
    m = polyccd.Motion.between((p0, q0), (p1, q1)).validate()
    p = [rng.uniform(-1, 1) for _ in range(3)]
    for t in (F(0), F(1), F(1, 3), F(1, 2), F(7, 9)):
        assert m.position(p, t) == expected(fr(p0), fr(q0), fr(p1), fr(q1), fr(p), t)
    # The end poses are exactly the given ones.
    assert m.position(p, 0) == tuple(a + b for a, b in zip(rotate(fr(q0), fr(p)), fr(p0)))
    assert m.position(p, 1) == tuple(a + b for a, b in zip(rotate(fr(q1), fr(p)), fr(p1)))


def test_between_takes_the_shorter_way_round():
    """q1 and -q1 are the same rotation: both give the same motion, which at t = 1/2 is
    the interpolation with the sign that makes q0 . q1' >= 0 (not the other one)."""
    q0, q1 = (1, 0, 0, 0), (-1, 0, 0, -2)         # q0 . q1 < 0
    a = polyccd.Motion.between(((0, 0, 0), q0), ((0, 0, 0), q1))
    b = polyccd.Motion.between(((0, 0, 0), q0), ((0, 0, 0), [-x for x in q1]))
    p, half = (1, 0, 0), F(1, 2)
    assert a.position(p, half) == b.position(p, half) == rotate(fr((1, 0, 0, 1)), fr(p))
    assert a.position(p, half) != rotate(fr((0, 0, 0, -1)), fr(p))


def test_between_exact_numbers_and_strings():
    m = polyccd.Motion.between(((F(1, 3), "0.1", 0), (1, 0, 0, 0)), (("2/7", 1, 0), ("1", "1", 0, 0)))
    assert m.position((0, 0, 0), 0) == (F(1, 3), F(1, 10), 0)
    assert m.position((0, 0, 0), 1) == (F(2, 7), 1, 0)
    assert m.position((0, 1, 0), 1) == (F(2, 7), 1, 1)   # a quarter turn about x


def quaternion_matrix(q, p):
    """The 4x4 float pose matrix of the unit quaternion q and position p."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    M = np.eye(4)
    M[:3, :3], M[:3, 3] = R, p
    return M


@pytest.mark.parametrize("seed", range(6))
def test_between_matrices(seed):
    """Translations exact; rotations within 1e-12 of the matrices (the documented ~1e-15)."""
    rng = np.random.default_rng(seed)
    M0, M1 = (quaternion_matrix(rng.normal(size=4), rng.normal(size=3)) for _ in range(2))
    m = polyccd.Motion.between(M0, M1).validate()
    p = rng.normal(size=3)
    for t, M in ((0, M0), (1, M1)):
        got = np.array([float(x) for x in m.position(p, t)])
        assert np.max(np.abs(got - (M[:3, :3] @ p + M[:3, 3]))) < 1e-12
        assert m.position((0, 0, 0), t) == fr(M[:3, 3])


def test_between_errors_name_the_bad_input():
    ok = ((0, 0, 0), (1, 0, 0, 0))
    with pytest.raises(polyccd.InputError, match=r"q1: the zero quaternion is no rotation"):
        polyccd.Motion.between(ok, ((0, 0, 0), (0, 0, 0, 0)))
    with pytest.raises(polyccd.InputError, match=r"p0\[1\]"):
        polyccd.Motion.between(((0, "abc", 0), (1, 0, 0, 0)), ok)
    with pytest.raises(polyccd.InputError, match=r"pose1\[1\]: expected 4 numbers"):
        polyccd.Motion.between(ok, ((0, 0, 0), (1, 0, 0)))
    with pytest.raises(polyccd.InputError, match=r"both as 4x4 matrices or both"):
        polyccd.Motion.between(np.eye(4), ok)
    bad_row = np.eye(4)
    bad_row[3, 0] = 1e-300
    with pytest.raises(polyccd.InputError, match=r"M0\[3\]\[0\]: the last row of a pose matrix"):
        polyccd.Motion.between(bad_row, np.eye(4))
    sheared = np.eye(4)
    sheared[0, 1] = 0.01
    with pytest.raises(polyccd.InputError, match=r"M1: the upper-left 3x3 block is not a rotation"):
        polyccd.Motion.between(np.eye(4), sheared)
    mirror = np.diag([1.0, 1.0, -1.0, 1.0])
    with pytest.raises(polyccd.InputError, match=r"det = -1"):
        polyccd.Motion.between(np.eye(4), mirror)
    nan = np.eye(4)
    nan[1, 2] = float("nan")
    with pytest.raises(polyccd.InputError, match=r"M0\[1\]\[2\]"):
        polyccd.Motion.between(nan, np.eye(4))


def test_between_pickles_as_its_recipe():
    import pickle
    for m in (polyccd.Motion.between(((0, 1, 2), (1, 2, 3, 4)), ((3, 2, 1), (4, 3, 2, 1))),
              polyccd.Motion.between(np.eye(4), quaternion_matrix((1, 1, 0, 0), (1, 2, 3)))):
        back = pickle.loads(pickle.dumps(m))
        assert back.position((1, 1, 1), F(2, 3)) == m.position((1, 1, 1), F(2, 3))


def test_a_box_moved_between_poses_hits_at_the_known_time():
    """A unit box moved from x = -3 to x = 3 against a unit box at the origin: without a
    turn the faces meet when the centres are 1 apart, at t = 1/3 exactly; turning about x
    keeps its x-extent, so the same time. Turning half a turn about y (which maps the box
    onto itself at both ends) makes it reach further in x while it turns: a contact
    strictly before 1/3, and no earlier than the bounding spheres (radius sqrt(3)/2 each)
    allow: -3 + 6t >= -sqrt(3)."""
    box = polyccd.Mesh.box((1, 1, 1))
    still = polyccd.Motion.between(((-3, 0, 0), (1, 0, 0, 0)), ((3, 0, 0), (1, 0, 0, 0)))
    r = polyccd.check([polyccd.Body(box, still), polyccd.Body(box)])
    assert r.collides and r.first_contact.exact == F(1, 3)
    about_x = polyccd.Motion.between(((-3, 0, 0), (1, 0, 0, 0)), ((3, 0, 0), (0, 1, 0, 0)))
    r = polyccd.check([polyccd.Body(box, about_x), polyccd.Body(box)])
    assert r.collides and r.first_contact.exact == F(1, 3)
    about_y = polyccd.Motion.between(((-3, 0, 0), (1, 0, 0, 0)), ((3, 0, 0), (0, 0, 1, 0)))
    r = polyccd.check([polyccd.Body(box, about_y), polyccd.Body(box)])
    assert r.collides and F(r.first_contact.hi) < F(1, 3)
    assert F(r.first_contact.lo) >= F((3 - math.sqrt(3)) / 6) - F(1, 10**9)


def test_box_corners_and_orientation():
    b = polyccd.Mesh.box((2, 4, 0.5))
    v = [fr(x) for x in b.exact_vertices()]
    assert sorted(v) == sorted((F(x), F(y), F(z)) for x in (-1, 1) for y in (-2, 2)
                               for z in (F(-1, 4), F(1, 4)))
    # Outward triangles: the signed volume is the box's, exactly.
    vol = sum(np.linalg.det(np.array([[float(c) for c in v[i]] for i in t])) for t in b.triangles) / 6
    assert vol == pytest.approx(4.0)
    with pytest.raises(polyccd.InputError, match="extents"):
        polyccd.Mesh.box((1, 0, 1))


@pytest.mark.parametrize("sections", [3, 7, 16, 64])
def test_cylinder_prism_contains_the_cylinder(sections):
    """Every side of the prism is at distance >= radius from the axis, checked exactly
    (distance^2 = cross^2 / |d|^2 >= r^2 in Fractions), and the caps are at +-height/2."""
    r, h = 0.3, 1.7
    c = polyccd.Mesh.cylinder(r, h, sections)
    v = [fr(x) for x in c.exact_vertices()]
    ring = v[:sections]
    for i in range(sections):
        a, b = ring[i], ring[(i + 1) % sections]
        d = (b[0] - a[0], b[1] - a[1])
        cross = a[0] * d[1] - a[1] * d[0]
        assert cross * cross >= F(r) ** 2 * (d[0] ** 2 + d[1] ** 2)
    assert {x[2] for x in v} == {F(-h / 2), F(h / 2)}
    assert len(c.triangles) == 4 * sections - 4
