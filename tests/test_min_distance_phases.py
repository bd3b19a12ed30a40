"""Minimum separation (issue 13, item 3) in every broad phase: with min_distance =
delta > 0, boxes, bvh and auto give brute force's answers (test_min_distance.py checks
the answers themselves against the distance oracle).
"""
import functools
import json
import random
from fractions import Fraction as F

import pytest

import polyccd as P
from helpers import box, summary
from test_min_distance import body_distance_within, corpus_cases
from test_range import grid_plate  # the square [0, n]^2 at z = 0, 2 n^2 triangles

# ------------------------------------------------- every broad phase at a minimum distance
#
# The box phases (boxes, bvh; auto is bvh) grow one body's swept boxes by delta (rounded
# up to a double, lib/boxes/boxes.h reach_of); brute force over every feature pair is the
# reference. Each check below compares every answer (collides, the first-contact
# enclosures, the pairs, the features, all contacts) on 1 and 3 threads. Disabling the
# growth (reach_of returning 0) fails the random, scaled, plate and molecule tests.

PHASES = ("boxes", "bvh", "auto")


def assert_phases_equal_brute(bodies, delta, what, all_modes=True, threads=(1, 3)):
    out = None
    for all_contacts in (False, True) if all_modes else (False,):
        brute = summary(P.check(bodies, broad_phase="brute", all_contacts=all_contacts,
                                min_distance=delta, time_tolerance="1e-9"))
        out = out or brute
        for phase in PHASES:
            for th in threads:
                got = summary(P.check(bodies, broad_phase=phase, all_contacts=all_contacts,
                                      threads=th, min_distance=delta, time_tolerance="1e-9"))
                assert got == brute, (what, str(delta), phase, th, all_contacts)
    return out


@pytest.mark.parametrize("k", range(12))
def test_random_scenes_every_phase_equals_brute_force(k):
    """The random scenes of test_scene_property at deltas from 1e-30 to 1/2."""
    from test_scene_property import random_scene
    rng = random.Random(77100 + k)  # (77300 + 8 at 1e-30 takes 4 s in the exact stage)
    bodies = random_scene(rng)
    delta = [F(1, 10 ** 30), F(1, 8), F(1, 4), F(1, 2)][k % 4]
    assert_phases_equal_brute(bodies, delta, ("random", k))


def scaled_motion(rng, s):
    """test_scene_property.random_motion with every length times s (angles unchanged)."""
    from test_scene_property import grid
    kind = rng.choice(["none", "linear", "quadratic", "rotation", "screw"])
    if kind == "none":
        return None
    g = lambda k=2: grid(rng, k) * s  # noqa: E731
    if kind == "linear":
        return P.Motion.linear([g() for _ in range(3)], [g() for _ in range(3)])
    if kind == "quadratic":
        return P.Motion.translation([[g(), g(), g()] for _ in range(3)])
    axis = [rng.randint(-1, 1) for _ in range(3)]
    if axis == [0, 0, 0]:
        axis = [0, 0, 1]
    center = [g() for _ in range(3)]
    tau0, tau1 = F(rng.randint(-2, 2), 2), F(rng.randint(-2, 2), 2)
    m = (P.Motion.axis_rotation(axis, center, tau0, tau1) if kind == "rotation"
         else P.Motion.screw(axis, center, tau0, tau1, g()))
    return m.compose([1, 0, 0, 0], [g() for _ in range(3)], side="world")


def scaled_scene(rng, s):
    """Two bodies of test_scene_property's shapes, every length times s."""
    from test_scene_property import random_mesh, random_spheres
    bodies = []
    for i in range(2):
        if rng.random() < 0.65:
            m = random_mesh(rng)
            shape = P.Mesh([[x * s for x in v] for v in m.exact_vertices()], m.triangles)
        else:
            b = random_spheres(rng)
            shape = P.Spheres([[x * s for x in c] for c in b.exact_centers()],
                              [r * s for r in b.exact_radii()])
        bodies.append(P.Body(shape, scaled_motion(rng, s), name=f"b{i}"))
    return bodies


@functools.lru_cache(maxsize=1)
def tiny_scenes(n=8):
    """n scaled scenes (1e-30 in size) whose answer delta decides: no contact, or a later
    one, at delta = 0 (chosen by brute force; the test compares the phases with it)."""
    s = F(1, 10 ** 30)
    seed, decided = 0, []
    while len(decided) < n:
        rng = random.Random(5150 + seed)
        seed += 1
        bodies = scaled_scene(rng, s)
        delta = s * F(rng.choice([1, 2]), 4)
        r0 = P.check(bodies, time_tolerance="1e-9", broad_phase="brute")
        r = P.check(bodies, min_distance=delta, time_tolerance="1e-9", broad_phase="brute")
        if r.collides and (not r0.collides or r0.first_contact.lo > r.first_contact.hi):
            decided.append((bodies, delta))
    return decided


@pytest.mark.parametrize("k", range(8))
def test_tiny_scenes_at_a_tiny_delta(k):
    """Scenes 1e-30 in size at delta = 1e-30 / 4 .. 1e-30 / 2: a delta far below 1 that
    the boxes' rounding slack (relative to the coordinates) does not hide."""
    bodies, delta = tiny_scenes()[k]
    assert_phases_equal_brute(bodies, delta, ("tiny", k))


def cube(c, h):
    """The cube of centre c and half side h (12 triangles)."""
    return box([x - h for x in c], [x + h for x in c])


GAP = F(1, 2 ** 20)


@pytest.mark.parametrize("delta,expect", [
    (F(0), None),                                  # the gap stays open: no contact
    (GAP - F(1, 10 ** 30), None),                  # misses delta by 1e-30
    (GAP, F(1)),                                   # within delta exactly at t = 1
    (F(1, 2), F(1, 2) / (1 - GAP)),                # 1 - (1 - GAP) t = 1/2 + 1/4 - 1/4
    (F(10) ** 400, F(0)),                          # a delta beyond the doubles: at t = 0
])
def test_mesh_near_miss_decided_by_delta(delta, expect):
    """A cube of half side 1/4 comes down onto a 6 x 6 plate of 72 triangles, its
    bottom face from z = 1 to z = GAP = 2^-20 (never touching): the first time within
    delta is where GAP + (1 - GAP)(1 - t) = delta (hand-derived, as listed); every phase
    equals brute force."""
    moving = P.Body(cube([F(13, 4), F(11, 4), F(5, 4)], F(1, 4)),
                    P.Motion.linear([0, 0, 0], [0, 0, GAP - 1]), name="cube")
    bodies = [P.Body(grid_plate(6), name="plate"), moving]
    r = assert_phases_equal_brute(bodies, delta, "plate", threads=(1, 3) if delta else (1,))
    assert r[0] == (expect is not None)
    if expect is not None:
        assert r[1][2] == expect, r[1]


@pytest.mark.parametrize("delta,expect", [
    (F(0), None),
    (GAP - F(1, 10 ** 30), None),
    (GAP, F(1)),
    (F(1, 2), F(7, 4) / (F(9, 4) - GAP)),          # 3 - (9/4 - GAP) t - 3/4 = 1/2
])
def test_molecule_near_miss_decided_by_delta(delta, expect):
    """A 6 x 6 x 2 block of balls (radius 1/2, centres on the integer grid, z = 0 and
    -1) and a three-ball molecule (radius 1/4) whose lowest ball comes down over the
    grid point (2, 3), from z = 3 to 3/4 + GAP: its distance to the ball below is
    z - 3/4, within delta when 3 - (9/4 - GAP) t - 3/4 <= delta (every other ball pair
    is farther); every phase equals brute force."""
    block = P.Spheres([[i, j, -k] for k in range(2) for j in range(6) for i in range(6)],
                      [F(1, 2)] * 72)
    mol = P.Spheres([[2, 3, 3], [2, 3, 4], [3, 3, 4]], [F(1, 4)] * 3)
    moving = P.Body(mol, P.Motion.linear([0, 0, 0], [0, 0, GAP - F(9, 4)]), name="mol")
    bodies = [P.Body(block, name="block"), moving]
    r = assert_phases_equal_brute(bodies, delta, "molecule")
    assert r[0] == (expect is not None)
    if expect is not None:
        assert r[1][2] == expect, r[1]


def corpus_as_bodies(case):
    """A min-distance corpus query as two bodies when each side's points move by one
    common translation: a vertex is a mesh of one degenerate triangle (v, v, v), a
    segment (a, b, b), a triangle itself; balls a sphere set. The closed sets, so the
    distance, are those of the query. None when a side does not move rigidly."""
    split = {"vertex-face": 1, "edge-edge": 2, "vertex-edge": 1, "vertex-vertex": 1,
             "sphere-sphere": 1}[case["kind"]]
    pts = [[[F(c) for c in axis] for axis in p] for p in case["points"]]
    bodies = []
    for side, group in enumerate((pts[:split], pts[split:])):
        deg = max(len(axis) for p in group for axis in p)
        pad = [[list(axis) + [F(0)] * (deg - len(axis)) for axis in p] for p in group]
        moves = [[axis[1:] for axis in p] for p in pad]
        if any(m != moves[0] for m in moves):
            return None
        base = [[axis[0] for axis in p] for p in pad]
        motion = P.Motion.translation([[F(0)] + m for m in moves[0]]) if deg > 1 else None
        if case["kind"] == "sphere-sphere":
            shape = P.Spheres(base, [F(case["radii"][side])])
        else:
            tri = {1: [0, 0, 0], 2: [0, 1, 1], 3: [0, 1, 2]}[len(base)]
            shape = P.Mesh(base, [tri])
        bodies.append(P.Body(shape, motion, name=f"side{side}"))
    return bodies


def test_the_corpus_through_every_phase():
    """Every corpus/min-distance case whose sides move rigidly (all of them today), as a
    two-body scene: the hand answer of its expect block, by every phase."""
    done = 0
    for path in corpus_cases():
        case = json.loads(path.read_text())
        bodies = corpus_as_bodies(case)
        if bodies is None:
            continue
        delta = F(case["options"]["min_distance"])
        r = assert_phases_equal_brute(bodies, delta, path.stem, threads=(1, 3))
        expect = case["expect"]
        assert r[0] == expect["collides"], path.stem
        if expect["collides"]:
            assert r[1][2] == F(expect["first_contact"]), (path.stem, r[1])
        done += 1
    assert done >= len(corpus_cases()) - 2, done


def test_delta_scaled_by_the_motion_denominator():
    """Bug (found with Robot.check at min_distance): the point kinds (vertex-face,
    edge-edge) of two bodies got the common-denominator trajectories D x(t) but no scale
    D, so delta was compared with D times the distance: a rotating body (W = 1 + tau^2
    != 1) was reported within delta too early or too late. A vertex at (1, 0, 0) turns
    about the z axis (tau = tan(angle / 2) from 0 to 1: y = 2 tau / (1 + tau^2)) towards
    the plane y = 1: within delta = 1/5 when y = 4/5, tau = 1/2, t = 1/2 exactly (x =
    3/5 is inside the wall triangle). Every phase, and the oracle at 1/2 and before."""
    spinner = P.Body(P.Mesh([[1, 0, 0], [0, 0, 0], [0, 0, F(1, 10)]], [[0, 1, 2]]),
                     P.Motion.axis_rotation([0, 0, 1], [0, 0, 0], 0, 1), name="spinner")
    wall = P.Body(P.Mesh([[-2, 1, -2], [2, 1, -2], [0, 1, 2]], [[0, 1, 2]]), name="wall")
    bodies = [spinner, wall]
    delta = F(1, 5)
    r = assert_phases_equal_brute(bodies, delta, "spinner")
    assert r[0] and r[1][2] == F(1, 2), r[1]
    assert (("vertex", 0), ("triangle", 0)) in [(c[0], c[1]) for c in r[2][0][3]]  # contacts (helpers.summary)
    assert body_distance_within(bodies, F(1, 2), delta)
    assert not any(body_distance_within(bodies, F(k, 64), delta) for k in range(32))
