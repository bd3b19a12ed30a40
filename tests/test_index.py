"""The on-line index (docs/python.md, "On-line index"): polyccd.Index(body) and
ix.query(body, ...) must give exactly the answers of brute force over every feature pair
of the two-body scene [stored, query] (P.check(..., broad_phase="brute")), with every
broad phase ("auto", "range", "boxes"), in first-contact and all-contacts modes:
collides, first contact (lo, hi, exact), pairs, names, touching features and their times.

- random scenes of three motion families: translations, fixed-axis rotations and
  screws, and general polynomial motions (quadratic translations with degree-2
  quaternions whose axis turns);
- one index queried many times (reuse must not change answers) and from two Python
  threads at once (the same answers as sequentially);
- every body-level corpus case: test_index_corpus.py;
- single query primitives (a one-triangle mesh, a one-ball sphere set) with answers
  derived by hand in the comments;
- error paths and their messages.

POLYCCD_INDEX_SEED and POLYCCD_INDEX_COUNT change the seed and the number of scenes.
"""
import os
import random
import threading
from fractions import Fraction as F

import pytest

import polyccd as P
from helpers import summary
from test_scene_property import grid, random_mesh, random_spheres

SEED = int(os.environ.get("POLYCCD_INDEX_SEED", "20261123"))
COUNT = int(os.environ.get("POLYCCD_INDEX_COUNT", "120"))
TOL = "1e-9"
FAMILIES = ("translation", "rotation", "general")


# ---------------------------------------------------------------- generators

def translation_motion(rng):
    """A linear path (positions at t = 0 and 1)."""
    return P.Motion.linear([grid(rng) for _ in range(3)], [grid(rng) for _ in range(3)])


def rotation_motion(rng):
    """A rotation about a fixed axis through a grid point, or a screw, moved by a grid
    offset (as tests/test_scene_property.py makes them)."""
    axis = [rng.randint(-1, 1) for _ in range(3)]
    if axis == [0, 0, 0]:
        axis = [0, 0, 1]
    center = [grid(rng) for _ in range(3)]
    tau0, tau1 = F(rng.randint(-2, 2), 2), F(rng.randint(-2, 2), 2)
    if rng.random() < 0.5:
        m = P.Motion.axis_rotation(axis, center, tau0, tau1)
    else:
        m = P.Motion.screw(axis, center, tau0, tau1, grid(rng))
    return m.compose([1, 0, 0, 0], [grid(rng) for _ in range(3)], side="world")


def _turning(vec_coeffs):
    """True when (x, y, z)(t) is not a fixed direction times a scalar polynomial: the
    coefficient vectors of t^0, t^1, t^2 span at least a plane."""
    cols = [[vec_coeffs[a][k] for a in range(3)] for k in range(3)]
    for i in range(3):
        for j in range(i + 1, 3):
            u, v = cols[i], cols[j]
            if (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) != (0, 0, 0):
                return True
    return False


def general_motion(rng):
    """A quadratic translation and a rotation quaternion of degree 2 (non-unit) whose axis
    turns over time. w(t) = a + b t + c t^2 with a >= 1, b >= -1, c >= 0 is >= 1 - t, so
    r(t) can only vanish at t = 1; validate() rejects those draws exactly."""
    while True:
        w = [rng.randint(1, 2), rng.randint(-1, 1), rng.randint(0, 1)]
        xyz = [[rng.randint(-1, 1) for _ in range(3)] for _ in range(3)]
        if not _turning(xyz):
            continue
        m = P.Motion(translation=[[grid(rng), grid(rng), grid(rng)] for _ in range(3)],
                     rotation=[w] + xyz)
        try:
            return m.validate()
        except P.InputError:
            continue


MOTIONS = {"translation": translation_motion, "rotation": rotation_motion, "general": general_motion}


def random_body(rng, family, name):
    shape = random_mesh(rng) if rng.random() < 0.65 else random_spheres(rng)
    motion = None if rng.random() < 0.25 else MOTIONS[family](rng)
    return P.Body(shape, motion, name=name)


def random_pair(k):
    """(family, stored, query) of scene k: both bodies move in the same family."""
    rng = random.Random(SEED * 1000 + k)
    family = FAMILIES[k % len(FAMILIES)]
    return family, random_body(rng, family, "S"), random_body(rng, family, "Q")


def brute(stored, query, **kw):
    return summary(P.check([stored, query], broad_phase="brute", **kw))


# ---------------------------------------------------------------- random scenes

@pytest.mark.parametrize("k", range(COUNT))
def test_index_equals_brute_force(k):
    family, stored, query = random_pair(k)
    ix = P.Index(stored)
    for all_contacts in (False, True):
        want = brute(stored, query, all_contacts=all_contacts, time_tolerance=TOL)
        for broad_phase in ("auto", "range", "boxes"):
            got = summary(ix.query(query, broad_phase=broad_phase, all_contacts=all_contacts,
                                   time_tolerance=TOL, threads=1 + k % 2))
            assert got == want, (k, family, broad_phase, all_contacts)


def test_random_scenes_collide_often_enough():
    """The comparison means something only if contacts (exact ones too) are common in
    every motion family."""
    hits = {f: 0 for f in FAMILIES}
    exact_hits = {f: 0 for f in FAMILIES}
    for k in range(COUNT):
        family, stored, query = random_pair(k)
        r = P.Index(stored).query(query, time_tolerance=TOL)
        hits[family] += r.collides
        exact_hits[family] += r.collides and r.first_contact.exact is not None
    per = COUNT // len(FAMILIES)
    for f in FAMILIES:
        assert hits[f] >= per // 5 and exact_hits[f] >= per // 10, (hits, exact_hits)


# ---------------------------------------------------------------- reuse and threads

def _queries(seed, n):
    rng = random.Random(seed)
    return [random_body(rng, FAMILIES[i % 3], f"q{i}") for i in range(n)]


def _stored_bodies():
    rng = random.Random(SEED + 7)
    box = P.Mesh([[F(i & 1), F((i >> 1) & 1), F(i >> 2)] for i in range(8)],
                 [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    balls = P.Spheres([[0, 0, 0], [1, 0, 0], [F(1, 2), 1, F(1, 2)]], [F(1, 2), F(3, 4), F(1, 4)])
    return [P.Body(box, rotation_motion(rng), name="box"),
            P.Body(balls, general_motion(rng), name="balls")]


@pytest.mark.parametrize("which", [0, 1], ids=["mesh", "spheres"])
def test_one_index_many_queries(which):
    stored = _stored_bodies()[which]
    ix = P.Index(stored)
    queries = _queries(SEED + which, 30)
    first = [summary(ix.query(q, time_tolerance=TOL)) for q in queries]
    for q, got in zip(queries, first):
        assert got == brute(stored, q, time_tolerance=TOL), q.name
    # The same queries again, in reverse order, interleaved with all-contacts queries:
    # the index is only read, so nothing changes.
    for q, want in reversed(list(zip(queries, first))):
        ix.query(q, all_contacts=True, time_tolerance=TOL, broad_phase="range")
        assert summary(ix.query(q, time_tolerance=TOL)) == want, q.name
    # A fresh index of the same body answers the same.
    fresh = P.Index(stored)
    assert [summary(fresh.query(q, time_tolerance=TOL)) for q in queries] == first
    assert sum(s[0] for s in first) >= 5  # enough of them touch to mean something


def test_two_python_threads_query_one_index():
    """Two threads query one index at once (the C call releases the GIL), each with its
    own queries in its own order; every answer equals the sequential one."""
    stored = _stored_bodies()[0]
    ix = P.Index(stored)
    queries = _queries(SEED + 11, 24)
    modes = [dict(all_contacts=ac, broad_phase=bp) for ac in (False, True) for bp in ("auto", "range")]
    want = {(i, m): summary(ix.query(q, time_tolerance=TOL, **modes[m]))
            for i, q in enumerate(queries) for m in range(len(modes))}
    got, errors = {}, []
    barrier = threading.Barrier(2)

    def worker(order):
        try:
            barrier.wait()
            for _ in range(2):
                for i, m in order:
                    got.setdefault((i, m), []).append(
                        summary(ix.query(queries[i], time_tolerance=TOL, **modes[m])))
        except BaseException as e:  # reported by the main thread
            errors.append(e)

    keys = sorted(want)
    threads = [threading.Thread(target=worker, args=(keys,)),
               threading.Thread(target=worker, args=(keys[::-1],))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for key, w in want.items():
        assert got[key] == [w] * 4, key


def test_threads_build_indexes_of_one_shape_at_once():
    """Indexes of the same shape built concurrently (the stored trees are made once per
    shape and shared) answer like brute force."""
    rng = random.Random(SEED + 3)
    shape = random_mesh(random.Random(SEED + 4))
    stored = [P.Body(shape, rotation_motion(rng), name="S") for _ in range(4)]
    queries = _queries(SEED + 5, 4)
    out, errors = [None] * 4, []
    barrier = threading.Barrier(4)

    def worker(i):
        try:
            barrier.wait()
            out[i] = summary(P.Index(stored[i]).query(queries[i], time_tolerance=TOL))
        except BaseException as e:
            errors.append(e)

    threads = [threading.Thread(target=worker, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for i in range(4):
        assert out[i] == brute(stored[i], queries[i], time_tolerance=TOL), i


def test_query_threads_give_identical_answers():
    stored = _stored_bodies()[0]
    ix = P.Index(stored)
    for q in _queries(SEED + 13, 8):
        base = summary(ix.query(q, all_contacts=True, time_tolerance=TOL))
        for threads in (2, 3):
            assert summary(ix.query(q, all_contacts=True, threads=threads, time_tolerance=TOL)) == base


# ---------------------------------------------------------------- single query primitives

# The plate: the square [-1, 1]^2 in z = 0, vertices 0 (-1,-1), 1 (1,-1), 2 (1,1),
# 3 (-1,1); triangle 0 = (0, 1, 2) is y < x, triangle 1 = (0, 2, 3) is y > x.
# Edges (Mesh.edges order): 0 (0,1) y = -1, 1 (0,2) the diagonal x = y, 2 (0,3) x = -1,
# 3 (1,2) x = 1, 4 (2,3) y = 1.
PLATE = P.Mesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], [[0, 1, 2], [0, 2, 3]])
# A tilted triangle: v0 (1/2, -1/4, 1), v1 (3/2, -1/4, 2), v2 (1/2, 3/4, 2); its edges
# 0 (v0,v1), 1 (v0,v2), 2 (v1,v2).
TRIANGLE = P.Mesh([["1/2", "-1/4", 1], ["3/2", "-1/4", 2], ["1/2", "3/4", 2]], [[0, 1, 2]])
DOWN2 = P.Motion.linear([0, 0, 0], [0, 0, -2])


def contacts(r):
    assert len(r.pairs) == 1
    return [(c.a, c.b, c.first_contact.exact) for c in r.pairs[0].contacts]


@pytest.mark.parametrize("broad_phase", ["auto", "range", "boxes", "brute"])
def test_triangle_falls_onto_plate(broad_phase):
    """The triangle falls by 2t: v0 at z = 1 - 2t lands at t = 1/2 on (1/2, -1/4, 0),
    inside plate triangle 0 (y < x); v1, v2 are still at z = 1 then. All contacts, the
    triangle's points at height z = (1 - 2t) + (x - 1/2) + (y + 1/4):
      edge 0 (y = -1/4) crosses plate edge 3 (x = 1) when 3/2 - 2t = 0: t = 3/4;
      edge 1 (x = 1/2) crosses the diagonal at (1/2, 1/2) when 7/4 - 2t = 0: t = 7/8;
      at t = 1, v1 and v2 reach z = 0: edge 2 (x + y = 5/4) lies in the plate's plane and
      meets the diagonal at (5/8, 5/8) and edge 3 at (1, 1/4); v2 (1/2, 3/4) lies in
      plate triangle 1 (y > x); v1 (3/2, -1/4) is off the plate. No plate vertex is in
      the triangle (its points have x >= 1/2, y >= -1/4, x + y <= 5/4 + ...)."""
    ix = P.Index(P.Body(PLATE, name="plate"))
    q = P.Body(TRIANGLE, DOWN2, name="tri")
    r = ix.query(q, broad_phase=broad_phase)
    assert r.collides and r.first_contact.exact == F(1, 2)
    assert r.pairs[0].names == ("plate", "tri") and r.pairs[0].bodies == (0, 1)
    assert contacts(r) == [(("triangle", 0), ("vertex", 0), F(1, 2))]
    r = ix.query(q, broad_phase=broad_phase, all_contacts=True)
    got = contacts(r)
    assert [t for _, _, t in got] == sorted(t for _, _, t in got)
    assert sorted(got) == sorted([
        (("triangle", 0), ("vertex", 0), F(1, 2)),
        (("edge", 3), ("edge", 0), F(3, 4)),
        (("edge", 1), ("edge", 1), F(7, 8)),
        (("edge", 1), ("edge", 2), F(1)),
        (("edge", 3), ("edge", 2), F(1)),
        (("triangle", 1), ("vertex", 2), F(1)),
    ])
    # Falling by 1 - 1/10^30 only, v0 (the lowest point) stops 1/10^30 above the plate.
    short = P.Motion.linear([0, 0, 0], [0, 0, "-0.999999999999999999999999999999"])
    assert not ix.query(P.Body(TRIANGLE, short), broad_phase=broad_phase).collides


@pytest.mark.parametrize("broad_phase", ["auto", "range", "boxes", "brute"])
def test_single_ball_queries(broad_phase):
    # A ball of radius 1/2 at (1/2, -1/4, 2) falling by 3t touches the plate when its
    # centre is at height 1/2: 2 - 3t = 1/2, t = 1/2, at (1/2, -1/4, 0) inside triangle 0.
    ball = P.Spheres([["1/2", "-1/4", 2]], ["1/2"])
    fall3 = P.Motion.linear([0, 0, 0], [0, 0, -3])
    r = P.Index(P.Body(PLATE)).query(P.Body(ball, fall3), broad_phase=broad_phase)
    assert r.collides and r.first_contact.exact == F(1, 2)
    assert r.pairs[0].names == ("body0", "body1")
    assert contacts(r) == [(("triangle", 0), ("sphere", 0), F(1, 2))]
    # The same ball against a stored molecule: balls 0 (0, 0, 0) r 1, 1 (3, 0, 0) r 1,
    # 2 (0, 0, -2) r 1. A ball of radius 1/2 at (0, 0, 3) falling by 3t touches ball 0
    # when 3 - 3t = 1 + 1/2: t = 1/2 (ball 1 is 3 away sideways: their distance
    # sqrt(9 + (3-3t)^2) >= 3 > 3/2 always; ball 2 lies below ball 0).
    mol = P.Spheres([[0, 0, 0], [3, 0, 0], [0, 0, -2]], [1, 1, 1])
    top = P.Spheres([[0, 0, 3]], ["1/2"])
    ix = P.Index(P.Body(mol, name="mol"))
    r = ix.query(P.Body(top, fall3, name="ball"), broad_phase=broad_phase)
    assert r.collides and r.first_contact.exact == F(1, 2)
    assert contacts(r) == [(("sphere", 0), ("sphere", 0), F(1, 2))]
    # A one-triangle query: the horizontal triangle (-1,-1,h), (2,-1,h), (-1,2,h) over the
    # origin (inside it: x, y > -1, x + y < 1) at h = 3 - 4t meets the top of ball 0
    # (0, 0, 1) when h = 1: t = 1/2; ball 1 at (3, 0, 0) is 1 + ... away: the triangle's
    # nearest point to (3, 0) in the plane is on its edge x + y = 1, at distance
    # 2/sqrt(2) = sqrt(2) > 1, so ball 1 never touches it.
    flat = P.Mesh([[-1, -1, 3], [2, -1, 3], [-1, 2, 3]], [[0, 1, 2]])
    fall4 = P.Motion.linear([0, 0, 0], [0, 0, -4])
    r = ix.query(P.Body(flat, fall4), broad_phase=broad_phase)
    assert r.collides and r.first_contact.exact == F(1, 2)
    assert contacts(r) == [(("sphere", 0), ("triangle", 0), F(1, 2))]


def test_stored_body_moves_too():
    """The stored plate rises by t while the triangle falls by 2t (the test above): v0 at
    z = 1 - 2t meets the plate at z = t when t = 1/3."""
    ix = P.Index(P.Body(PLATE, P.Motion.linear([0, 0, 0], [0, 0, 1])))
    r = ix.query(P.Body(TRIANGLE, DOWN2))
    assert r.first_contact.exact == F(1, 3)
    assert contacts(r) == [(("triangle", 0), ("vertex", 0), F(1, 3))]


# ---------------------------------------------------------------- errors

VANISHING = P.Motion(rotation=[[1, -2], [0], [0], [0]])  # r(t) = 1 - 2t: zero at t = 1/2


def test_errors():
    stored = P.Body(PLATE, name="plate")
    ix = P.Index(stored)
    q = P.Body(TRIANGLE, DOWN2)
    with pytest.raises(P.InputError, match=r"^body: expected a polyccd.Body, got 3$"):
        P.Index(3)
    with pytest.raises(P.InputError, match=r"^body: expected a polyccd.Body, got "):
        P.Index(PLATE)  # a shape, not a Body
    with pytest.raises(P.InputError, match=r'^body: expected a polyccd.Body, got "x"$'):
        ix.query("x")
    with pytest.raises(P.InputError, match=r"^body: expected a polyccd.Body"):
        ix.query(TRIANGLE)
    with pytest.raises(P.InputError, match=r'^broad_phase: expected "auto", "boxes", "brute", "bvh" or "range", got "kd"$'):
        ix.query(q, broad_phase="kd")
    with pytest.raises(P.InputError, match=r"^broad_phase: "):
        ix.query(q, broad_phase=None)
    for bad in (0, -1, 1025, 2 ** 40):  # the library's rule and words
        with pytest.raises(P.InputError, match=rf"^opt\.threads: {bad} is outside 1\.\.1024$"):
            ix.query(q, threads=bad)
    for bad in (1.5, True, "2"):
        with pytest.raises(P.InputError, match=r"^opt\.threads: expected an integer, got"):
            ix.query(q, threads=bad)
    with pytest.raises(P.InputError, match=r"^all_contacts: expected True or False"):
        ix.query(q, all_contacts="yes")
    with pytest.raises(P.InputError, match=r"time_tolerance: \"0\" must be greater than 0"):
        ix.query(q, time_tolerance=0)
    with pytest.raises(P.InputError, match=r"^motion: .*vanishes at t = 1/2") as e:
        ix.query(P.Body(TRIANGLE, VANISHING))
    assert "pccd_index_query" not in str(e.value)
    with pytest.raises(P.InputError, match=r"^motion: .*vanishes at t = 1/2"):
        P.Index(P.Body(PLATE, VANISHING))
    # After the errors the index still answers.
    assert ix.query(q).first_contact.exact == F(1, 2)
    with pytest.raises(AttributeError):
        ix.body = q
    assert ix.body is stored and "plate" in repr(ix)


def test_query_many_equals_query():
    stored = _stored_bodies()[1]
    ix = P.Index(stored)
    queries = _queries(SEED + 17, 12)
    for all_contacts in (False, True):
        want = [summary(ix.query(q, all_contacts=all_contacts, time_tolerance=TOL)) for q in queries]
        for threads in (1, 3):
            got = ix.query_many(queries, all_contacts=all_contacts, threads=threads, time_tolerance=TOL)
            assert [summary(r) for r in got] == want, (all_contacts, threads)
    assert ix.query_many([]) == []
    with pytest.raises(P.InputError, match=r"^bodies\[2\]\.motion: .*vanishes at t = 1/2"):
        ix.query_many(queries[:2] + [P.Body(TRIANGLE, VANISHING)] + queries[2:])
    with pytest.raises(P.InputError, match=r"^bodies\[1\]: expected a polyccd.Body"):
        ix.query_many([queries[0], TRIANGLE])


def test_bad_tolerance_is_named_by_its_keyword():
    b = P.Body(P.Spheres([[0, 0, 0]], [1]))
    for call in (lambda **kw: P.check([b, b], **kw), lambda **kw: P.Index(b).query(b, **kw),
                 lambda **kw: P.Index(b).query_many([b], **kw)):
        with pytest.raises(P.InputError, match=r'^config\.time_tolerance: "abc" is not a number'):
            call(time_tolerance="abc")
        with pytest.raises(P.InputError, match=r'^config\.time_tolerance: "-1" must be greater than 0'):
            call(time_tolerance=-1)
