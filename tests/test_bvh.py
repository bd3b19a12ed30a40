"""The hierarchy broad phase (broad_phase="bvh", lib/bvh): its node boxes must hold the
exact elements and its swept boxes the exact motion, so it must give exactly brute
force's answers also where the doubles it bounds are not the coordinates (thirds,
tenths), at extreme scales (1e-30 .. 1e30, where the rounding terms of the error bounds
matter), and on touching contacts; a far-apart pair ends at the roots; and the work
(not only the answer) does not depend on the number of threads.

POLYCCD_BVH_SEED and POLYCCD_BVH_COUNT change the seed and the number of scenes.
"""
import math
import os
import random
from fractions import Fraction as F

import numpy as np
import pytest

import polyccd as P
from helpers import cube, summary
from test_scene_property import scene_call

SEED = int(os.environ.get("POLYCCD_BVH_SEED", "20261124"))
COUNT = int(os.environ.get("POLYCCD_BVH_COUNT", "30"))
ODD_SCALES = [F(1, 3), F(7, 10), F(1), F(10, 3)]  # random scenes (radii are not scaled)
SCALES = [F(1, 10 ** 30), F(1, 3), F(7, 10), F(1), F(10 ** 30, 3)]


def brute_and_bvh(bodies, all_contacts, threads=1):
    brute = summary(P.check(bodies, broad_phase="brute", all_contacts=all_contacts, time_tolerance="1e-9"))
    got = summary(P.check(bodies, broad_phase="bvh", all_contacts=all_contacts, threads=threads,
                          time_tolerance="1e-9"))
    return brute, got


@pytest.mark.parametrize("s", SCALES, ids=[f"scale{k}" for k in range(len(SCALES))])
def test_touching_cubes_at_every_scale(s):
    # Cube B = [2, 3] x [0, 1]^2 (times s, plus s/3) slides by -s along x: its face
    # x = 2s reaches A's face x = s at t = 1 exactly (a touch at the last instant),
    # and with a path 1/10^6 shorter it stays apart (gap s / 10^6).
    shift = s / 3
    A = P.Body(cube([shift, shift, shift], s), name="A")
    for end, hit in ((-s, True), (-s + s / 10 ** 6, False)):
        B = P.Body(cube([2 * s + shift, shift, shift], s), P.Motion.linear([0, 0, 0], [end, 0, 0]), name="B")
        for bp in ("bvh", "brute"):
            r = P.check([A, B], broad_phase=bp)
            assert r.collides == hit, (s, end, bp)
            if hit:
                assert r.first_contact.exact == 1, (s, bp)


@pytest.mark.parametrize("k", range(COUNT))
def test_bvh_equals_brute_force_on_odd_coordinates(k):
    """Random scenes of test_scene_property.py drawn with every grid value x replaced by
    s x + s / 3, s from 1/3 to 10/3 (radii as drawn): the doubles the hierarchy
    bounds are off the exact coordinates, by amounts its pt_err and slack terms must
    cover, and touching contacts stay common (the grid is still coarse)."""
    import test_scene_property as T
    s = ODD_SCALES[k % len(ODD_SCALES)]
    orig = T.grid
    T.grid = lambda rng, kk=2: orig(rng, kk) * s + s / 3
    try:
        bodies = T.random_scene(random.Random(SEED * 1000 + k))
    finally:
        T.grid = orig
    for all_contacts in (False, True):
        brute, got = brute_and_bvh(bodies, all_contacts, threads=1 + k % 3)
        assert got == brute, (k, s, all_contacts)


def icosphere_like(n_lat, n_lon, r, c):
    """A closed UV sphere of 2 n_lon (n_lat - 1) triangles, radius r, centre c."""
    V = [[c[0], c[1], c[2] + r]]
    for i in range(1, n_lat):
        th = math.pi * i / n_lat
        for j in range(n_lon):
            ph = 2 * math.pi * j / n_lon
            V.append([c[0] + r * math.sin(th) * math.cos(ph), c[1] + r * math.sin(th) * math.sin(ph),
                      c[2] + r * math.cos(th)])
    V.append([c[0], c[1], c[2] - r])
    T = []
    for j in range(n_lon):
        T.append([0, 1 + j, 1 + (j + 1) % n_lon])
    for i in range(n_lat - 2):
        for j in range(n_lon):
            a, b = 1 + i * n_lon + j, 1 + i * n_lon + (j + 1) % n_lon
            T += [[a, a + n_lon, b], [b, a + n_lon, b + n_lon]]
    last = len(V) - 1
    for j in range(n_lon):
        a, b = 1 + (n_lat - 2) * n_lon + j, 1 + (n_lat - 2) * n_lon + (j + 1) % n_lon
        T.append([a, last, b])
    return P.Mesh(np.array(V), T)


def test_far_apart_pair_ends_at_the_roots():
    s = icosphere_like(40, 60, 1.0, (0, 0, 0))
    assert s.n_triangles > 4000
    B = P.Body(s, P.Motion.linear([10, 0, 0], [8, 0, 0]), name="B")
    r = P.check([P.Body(s, name="A"), B], broad_phase="bvh")
    assert not r.collides
    assert r.stats["pieces"] == 1 and r.stats["leaves"] == 0 and r.stats["candidates"] == 0, r.stats


def test_work_does_not_depend_on_threads():
    """Two dense spheres, one sliding into the other: fronts of thousands of node pairs
    (several parallel chunks). Answers and every counter equal for 1, 2 and 3 threads."""
    s = icosphere_like(40, 60, 1.0, (0, 0, 0))
    B = P.Body(s, P.Motion.linear([F(5, 2), F(1, 7), 0], [F(1, 2), F(1, 7), 0]), name="B")
    bodies = [P.Body(s, name="A"), B]
    base = P.check(bodies, broad_phase="bvh", threads=1)
    assert base.collides and base.stats["candidates"] > 2048, base.stats
    for th in (2, 3):
        r = P.check(bodies, broad_phase="bvh", threads=th)
        assert summary(r) == summary(base) and dict(r.stats) == dict(base.stats), th


@pytest.mark.parametrize("k", range(COUNT))
def test_pair_call_equals_scene_call(k):
    """check() of two bodies is one pccd_pair_solve call (no pccd_scene): the answer and
    the work counters equal those of the same two bodies solved as a pccd_scene, for 1-3
    threads, every broad phase, first-contact and all-contacts modes; and they equal
    brute force."""
    import test_scene_property as T
    rng = random.Random(SEED * 1000 + 500 + k)
    bodies = T.random_scene(rng)[:2]
    for all_contacts in (False, True):
        kw = dict(all_contacts=all_contacts, time_tolerance="1e-9")
        brute = summary(P.check(bodies, broad_phase="brute", **kw))
        for bp in ("auto", "bvh", "boxes", "brute", "range"):
            for threads in ((1, 2, 3) if bp in ("auto", "bvh") else (1,)):
                got = P.check(bodies, broad_phase=bp, threads=threads, **kw)
                via = scene_call(bodies, broad_phase=bp, threads=threads, **kw)
                assert summary(got) == summary(via) == brute, (k, all_contacts, bp, threads)
                assert got.stats == via.stats, (k, all_contacts, bp, threads)


def test_motion_changes_after_a_solve_are_seen():
    """A motion handle keeps its derived data from the first solve; the Python Motion
    never changes, so the C setters are driven directly: after a valid solve, making the
    motion invalid must fail the next solve, and changing the path must change the
    answer (lib/api/motion_handle.h: every setter drops the kept data)."""
    from polyccd._pccd import ffi, lib
    A = P.Body(cube([0, 0, 0], 1), name="A")
    m = P.Motion.linear([3, 0, 0], [0, 0, 0])   # B's face x = 3 - 3t meets x = 1 at 2/3
    B = P.Body(cube([0, 0, 0], 1), m, name="B")
    assert P.check([A, B]).first_contact.exact == F(2, 3)
    h = m._handle
    try:
        assert lib.pccd_motion_set_linear_translation_d(h, [3.0, 0, 0], [-1.0, 0, 0]) == 0
        assert P.check([A, B]).first_contact.exact == F(1, 2)   # 3 - 4t = 1
        w = [ffi.new("char[]", b"1"), ffi.new("char[]", b"-2")]
        assert lib.pccd_motion_set_rotation_s(h, 0, ffi.new("char *[]", w), 2) == 0   # r(1/2) = 0
        with pytest.raises(P.InputError, match=r"bodies\[1\]\.motion: .*1/2"):
            P.check([A, B])
        one = [ffi.new("char[]", b"1")]
        assert lib.pccd_motion_set_rotation_s(h, 0, ffi.new("char *[]", one), 1) == 0
        assert P.check([A, B]).first_contact.exact == F(1, 2)
    finally:  # the Motion object is shared by nothing else here, but leave it as it was
        assert lib.pccd_motion_set_linear_translation_d(h, [3.0, 0, 0], [0.0, 0, 0]) == 0
