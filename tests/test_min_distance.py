"""Minimum separation (issue 13, item 3): with min_distance = delta > 0 a query's answer
is the first time the closed primitives are within distance delta.

Checked against an independent exact oracle (tests/oracle/oracle_distance.py: squared
distances of closed primitives in Fractions, from the closest-point constructions, not
from polyccd's feature systems), on random queries and on the hand-written corpus cases
of corpus/min-distance/ (their answers derived by hand in their "source" lines):
  - before the reported enclosure, the distance is > delta at every sampled time;
  - a rational first time t* has distance exactly delta (or <= delta at t* = 0), and
    so do the reported features at t*;
  - without a contact, the distance is > delta at every sampled time;
  - delta = 0 gives the answers of a query without a minimum distance.
"""
import json
import random
from fractions import Fraction as F
from pathlib import Path

import pytest

import oracle_distance as OD
import polyccd as P

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "min-distance"
KINDS = ("vertex-face", "edge-edge", "vertex-edge", "vertex-vertex")
NPOINTS = {"vertex-face": 4, "edge-edge": 4, "vertex-edge": 3, "vertex-vertex": 2}
SAMPLES = [F(k, 256) for k in range(257)]


def feature_distance2(feature, points, t):
    """The squared distance of the features a result names, at t."""
    idx = feature.points
    sub = [points[i] for i in idx]
    return OD.distance2(feature.kind, sub, t)


def check_answer(kind, points, delta, r):
    d2 = delta * delta
    dist2 = lambda t: OD.distance2(kind, points, t)  # noqa: E731
    if not r.collides:
        assert all(dist2(t) > d2 for t in SAMPLES), "a sampled time is within delta"
        return "miss"
    fc = r.first_contact
    assert all(dist2(t) > d2 for t in SAMPLES if t < fc.lo), "within delta before the answer"
    if fc.exact is not None:
        t = fc.exact
        assert dist2(t) <= d2
        if t > 0:
            assert dist2(t) == d2, "a first time after 0 is at distance exactly delta"
            assert any(feature_distance2(f, points, t) == d2 for f in r.features), r.features
        return "exact"
    # an irrational first time: just after it (at hi, for a transversal crossing) the
    # distance is <= delta; a grazing one touches delta only at t*, inside the enclosure
    if dist2(fc.hi) <= d2:
        return "irrational"
    assert min(dist2(fc.lo + (fc.hi - fc.lo) * F(k, 64)) for k in range(65)) - d2 < F(1, 10 ** 6)
    return "grazing"


def grid(rng):
    return F(rng.randint(-4, 4), 2)


def random_query(rng):
    kind = rng.choice(KINDS)
    points = []
    for _ in range(NPOINTS[kind]):
        x0 = [grid(rng) for _ in range(3)]
        x1 = [grid(rng) for _ in range(3)] if rng.random() < 0.6 else x0
        points.append([[a, b - a] for a, b in zip(x0, x1)])
    return kind, points, F(rng.choice([1, 2, 3, 4]), 4)


@pytest.mark.parametrize("seed", range(6))
def test_random_queries_against_the_distance_oracle(seed):
    rng = random.Random(20261124 + seed)
    seen = {}
    for _ in range(60):
        kind, points, delta = random_query(rng)
        r = P.solve(kind, points, min_distance=delta, time_tolerance="1e-9")
        what = check_answer(kind, points, delta, r)
        seen[what] = seen.get(what, 0) + 1
        assert P.solve(kind, points, min_distance=0) == P.solve(kind, points)
    assert seen.get("exact", 0) + seen.get("irrational", 0) >= 10, seen  # contacts are common


def test_linear_paths_and_batches_agree_with_solve():
    rng = random.Random(7)
    import numpy as np
    for kind in KINDS:
        t0 = np.array([[[rng.randint(-4, 4) / 2 for _ in range(3)] for _ in range(NPOINTS[kind])]
                       for _ in range(20)])
        t1 = np.array([[[rng.randint(-4, 4) / 2 for _ in range(3)] for _ in range(NPOINTS[kind])]
                       for _ in range(20)])
        batch = P.solve_linear_many(kind, t0, t1, min_distance="1/2", threads=2)
        for k in range(20):
            traj = [[[F(a), F(b) - F(a)] for a, b in zip(p0, p1)] for p0, p1 in zip(t0[k], t1[k])]
            want = P.solve(kind, traj, min_distance="1/2")
            got = P.solve_linear(kind, t0[k], t1[k], min_distance="1/2")
            assert got == want
            assert bool(batch.collides[k]) == want.collides


def test_errors():
    pts = [[[0], [0], [0]], [[1], [0], [0]]]
    with pytest.raises(P.InputError, match=r'^config.min_distance: "-1/2" must be >= 0'):
        P.solve("vertex-vertex", pts, min_distance="-1/2")
    with pytest.raises(P.InputError, match="config.min_distance: .*not a number"):
        P.solve("vertex-vertex", pts, min_distance="abc")
    # the range broad phase refuses it (tests/c/test_limits.c, min_distance; below).


def corpus_cases():
    return sorted(CORPUS.glob("*.json"))


def test_the_corpus_has_the_cases_the_issue_asks_for():
    names = {p.stem for p in corpus_cases()}
    for word in ("exactly-delta", "parallel", "at-t0", "at-t1", "miss-1e-30"):
        assert any(word in n for n in names), word
    kinds = {json.loads(p.read_text())["kind"] for p in corpus_cases()}
    assert kinds == set(KINDS) | {"sphere-sphere"}


@pytest.mark.parametrize("path", corpus_cases(), ids=lambda p: p.stem)
def test_corpus_case(path):
    """polyccd meets the hand answer, and the hand answer meets the distance oracle."""
    from polyccd.apps import _corpus
    case = json.loads(path.read_text())
    if case["kind"] == "sphere-sphere":  # balls: centres within ra + rb + delta
        r = _corpus.solve_case(_corpus.read_case(path)[1])
        reach = sum(F(x) for x in case["radii"]) + F(case["options"]["min_distance"])
        cpts = [[[F(c) for c in axis] for axis in p] for p in case["points"]]
        d2 = lambda t: OD.distance2("vertex-vertex", cpts, t)  # noqa: E731
        t = F(case["expect"]["first_contact"])
        assert r.first_contact.exact == t and d2(t) == reach ** 2
        assert all(d2(s) > reach ** 2 for s in SAMPLES if s < t)
        return
    delta = F(case["options"]["min_distance"])
    points = [[[F(c) for c in axis] for axis in p] for p in case["points"]]
    what, qcase = _corpus.read_case(path)
    r = _corpus.solve_case(qcase)
    expect = case["expect"]
    assert r.collides == expect["collides"]
    if expect["collides"]:
        assert r.first_contact.exact == F(expect["first_contact"])
    check_answer(case["kind"], points, delta, r)
    # the oracle alone: within delta exactly at the hand time, never before it
    d2 = delta * delta
    if expect["collides"]:
        t = F(expect["first_contact"])
        assert OD.distance2(case["kind"], points, t) <= d2
        assert all(OD.distance2(case["kind"], points, s) > d2 for s in SAMPLES if s < t)
    else:
        assert all(OD.distance2(case["kind"], points, s) > d2 for s in SAMPLES)


def body_distance_within(bodies, t, delta):
    """Whether two bodies of a scene (exact positions at t through Motion.position) are
    within delta, by the oracle: meshes by every vertex-triangle and edge-edge pair (the
    closest points of two closed triangles form one of those), balls by their centres'
    distance to the other body minus the radii."""
    def placed(body):
        m = body.motion
        pos = (lambda p: [F(x) for x in p]) if m is None else (lambda p: list(m.position(p, t)))
        s = body.shape
        if isinstance(s, P.Mesh):
            v = [pos(p) for p in s.exact_vertices()]
            return "mesh", [[v[i] for i in tri] for tri in s.triangles]
        return "balls", [(pos(c), F(r)) for c, r in zip(s.exact_centers(), s.exact_radii())]
    (ka, a), (kb, b) = placed(bodies[0]), placed(bodies[1])
    if ka == "balls" and kb == "mesh":
        (ka, a), (kb, b) = (kb, b), (ka, a)
    if ka == "mesh" and kb == "mesh":
        for ta in a:
            for tb in b:
                if any(OD.point_triangle(p, *tb) <= delta ** 2 for p in ta):
                    return True
                if any(OD.point_triangle(p, *ta) <= delta ** 2 for p in tb):
                    return True
                for i in range(3):
                    for j in range(3):
                        if OD.segment_segment(ta[i], ta[(i + 1) % 3], tb[j], tb[(j + 1) % 3]) <= delta ** 2:
                            return True
        return False
    if ka == "mesh":  # b: balls
        return any(OD.point_triangle(c, *tri) <= (r + delta) ** 2 for c, r in b for tri in a)
    return any(OD.point_point(ca, cb) <= (ra + rb + delta) ** 2 for ca, ra in a for cb, rb in b)


def scene_cases():
    """Two-body random scenes at a minimum distance, chosen for variety: 7 whose first
    time within delta is after 0, 3 at t = 0 and 3 without (the selection uses polyccd's
    answer; the checks below do not)."""
    from test_scene_property import random_scene
    want = {"later": 7, "zero": 3, "miss": 3}
    out = []
    for k in range(400):
        rng = random.Random(4242 + k)
        bodies = random_scene(rng)[:2]
        delta = F(rng.choice([1, 2]), 4)
        r = P.check(bodies, min_distance=delta, time_tolerance="1e-9")
        what = "miss" if not r.collides else "zero" if r.first_contact.exact == 0 else "later"
        if want[what] > 0:
            want[what] -= 1
            out.append((bodies, delta, r))
    return out


@pytest.fixture(scope="module")
def scenes():
    return scene_cases()


@pytest.mark.parametrize("k", range(13))
def test_scenes_against_the_distance_oracle(scenes, k):
    """Nothing within delta at a sampled time before the scene's first contact, within
    delta at a rational first time; brute force, boxes, bvh and auto agree, on 1 and 3
    threads, and the index gives the same answer (auto: bvh); range refuses delta."""
    from helpers import summary
    bodies, delta, r = scenes[k]
    for phase in ("brute", "boxes", "bvh"):
        for threads in (1, 3):
            assert summary(P.check(bodies, min_distance=delta, broad_phase=phase, threads=threads,
                                   time_tolerance="1e-9")) == summary(r), (k, phase, threads)
    with pytest.raises(P.InputError, match=r"2 \(PCCD_BROAD_RANGE\) does not take config.min_distance"):
        P.check(bodies, min_distance=delta, broad_phase="range")
    ix = P.Index(bodies[0])
    for phase in ("auto", "bvh", "brute"):
        assert summary(ix.query(bodies[1], min_distance=delta, time_tolerance="1e-9",
                                broad_phase=phase)) == summary(r), (k, phase)
    with pytest.raises(P.InputError, match="does not take config.min_distance"):
        ix.query(bodies[1], min_distance=delta, broad_phase="range")
    samples = [F(j, 16) for j in range(17)]
    if not r.collides:
        assert not any(body_distance_within(bodies, t, delta) for t in samples)
        return
    fc = r.first_contact
    assert not any(body_distance_within(bodies, t, delta) for t in samples if t < fc.lo)
    if fc.exact is not None:
        assert body_distance_within(bodies, fc.exact, delta)
    else:  # t* irrational: lo < t*, and nothing is within delta before t*
        assert not body_distance_within(bodies, fc.lo, delta), (k, fc)
    # delta grows the contacts: the answer at delta = 0 is never earlier
    r0 = P.check(bodies, time_tolerance="1e-9")
    assert not r0.collides or r0.first_contact.hi >= fc.lo
