"""Robot checks through the certified filter (pccd_robot_check: link poses enclosed
straight from the joint path, exact link motions only for the pairs the filter cannot
separate) give the answers of the exact check of every pair, on random segments of two
real arms (Panda and UR5 of example-robot-data), obstacles placed where the links pass
(hits and near misses), self-collision off and on (adjacent and SRDF pairs allowed):

  - against brute force (filter off, broad_phase="brute"; with self-collision the
    unfiltered bvh, brute force of every link pair taking minutes): the same collides and first
    contact (exact times equal, enclosures overlapping), with the filter and without it
    (bvh), the same collides in decide mode, its witness pair touching when checked
    alone as a scene (pccd_scene_solve on the two bodies), free_until never above
    brute force's first contact (and equal to the first contact's lo);
  - against the exact check without the filter (bvh): the same first contact and
    decide answer on the arms' full meshes, robot versus obstacles and with
    self-collision (SRDF pairs allowed; some segments without obstacles);
  - built near misses and touches: a small box placed, in exact rationals, with a face
    at a gap of 0, +-1e-4 or +-1e-9 m ahead of a link's extreme vertex at t = 1 (so the
    link touches it exactly, or stops a hair from it, or dips into it), on the boxed
    arms against brute force and the unfiltered check, both modes.
(All contacts through the filter against brute force: tests/test_robot.py.)
Brute force takes every feature pair, so its arms are the links' bounding boxes in their
own frames (Robot.shapes replaced: 12 triangles a link); the full meshes are compared
with the unfiltered exact check. POLYCCD_FILTER_SEGMENTS: segments per arm (default 4).
"""
import copy
import os
import random
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_fk import ROBOTS, URDFS, needs_robots, random_segment  # noqa: E402

SEED = 20261125
SEGMENTS = int(os.environ.get("POLYCCD_FILTER_SEGMENTS", "4"))
SRDFS = {"panda": "panda_description/srdf/panda.srdf", "ur5": "ur_description/srdf/ur5.srdf"}
BOX_T = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
         [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]


def box_mesh(lo, hi):
    return P.Mesh([[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)], BOX_T)


def boxed(robot):
    """The robot with each geometry replaced by its bounding box (same link frame)."""
    out = copy.copy(robot)
    out.shapes = [(link, i, k, box_mesh(np.min(s.vertices, axis=0), np.max(s.vertices, axis=0)))
                  for link, i, k, s in robot.shapes]
    return out


def obstacles_near(robot, q0, q1, rng, n=3, spread=0.15):
    """Small boxes around points the links' vertices pass at random times (offset by up
    to spread: hits and near misses)."""
    motions = robot.motions(q0, q1)
    out = []
    for i in range(n):
        _, _, k, shape = rng.choice(robot.shapes)
        v = [float(x) for x in shape.vertices[rng.randrange(len(shape.vertices))]]
        x = [float(c) for c in motions[k].position(v, F(rng.randint(1, 9), 10))]
        lo = [x[a] + rng.uniform(-spread, spread) for a in range(3)]
        hi = [lo[a] + rng.uniform(0.005, 0.05) for a in range(3)]
        out.append(P.Body(box_mesh(lo, hi), name=f"box{i}"))
    return out


def same_first(got, ref, what):
    assert got.collides == ref.collides, what
    if not ref.collides:
        return
    a, b = got.first_contact, ref.first_contact
    if a.exact is not None or b.exact is not None:
        assert a.exact == b.exact, (what, a, b)
    else:
        assert a.lo <= b.hi and b.lo <= a.hi, (what, a, b)


def check_all_ways(robot, q0, q1, obstacles, self_collision, what, brute_force=True,
                   min_distance=None):
    """Filtered first contact and decide mode against the unfiltered exact check (and
    brute force without self-collision): same answers; decide's witness pair touches
    alone (comes within min_distance, when given) and its free_until is no later than
    the first contact."""
    opts = dict(self_collision=self_collision, time_tolerance="1e-9", min_distance=min_distance)
    plain = robot.check(q0, q1, obstacles, filter=False, **opts)
    if brute_force and not self_collision:
        same_first(robot.check(q0, q1, obstacles, filter=False, broad_phase="brute", **opts), plain, what)
    first = robot.check(q0, q1, obstacles, **opts)
    same_first(first, plain, what)
    decide = robot.check(q0, q1, obstacles, first_contact=False, **opts)
    assert decide.collides == plain.collides, what
    if plain.collides:
        assert decide.free_until <= plain.first_contact.lo, what
        assert first.free_until == first.first_contact.lo, what
        (witness,) = decide.scene.pairs
        assert pair_touches(robot, q0, q1, obstacles, witness.names, min_distance), what
    else:
        assert decide.free_until == first.free_until == 1, what
    return plain.collides


def pair_touches(robot, q0, q1, obstacles, names, min_distance=None):
    """The two bodies of a reported pair, checked alone as a polyccd scene (the links on
    robot.motions, pccd_scene_solve): do they touch (come within min_distance)?"""
    motions = robot.motions(q0, q1)
    from polyccd._robot_check import _names
    own = {n: P.Body(s, motions[k]) for n, (_, _, k, s) in zip(_names(robot), robot.shapes)}
    own.update({o.name: o for o in obstacles})
    return P.check([own[names[0]], own[names[1]]], min_distance=min_distance).collides


def arm(name):
    robot = load_urdf(os.path.join(ROBOTS, URDFS[name]), srdf=os.path.join(ROBOTS, SRDFS[name]))
    return robot


@needs_robots
@pytest.mark.parametrize("name", sorted(URDFS))
def test_filter_equals_brute_force_on_boxed_arms(name):
    robot = boxed(arm(name))
    rng = random.Random(SEED + len(name))
    seen = {"hit": 0, "free": 0}
    for k in range(SEGMENTS):
        q0, q1 = random_segment(robot, rng)
        q1 = q0 + (q1 - q0) / 3  # about a radian per joint at most
        obstacles = obstacles_near(robot, q0, q1, rng)
        for self_collision in (False, True):
            what = (name, k, self_collision)
            hit = check_all_ways(robot, q0, q1, obstacles, self_collision, what)
            seen["hit" if hit else "free"] += 1
    assert seen["hit"] and seen["free"], seen  # both kinds were checked


@needs_robots
@pytest.mark.parametrize("name", sorted(URDFS))
def test_filter_equals_unfiltered_on_full_meshes(name):
    robot = arm(name)
    rng = random.Random(SEED + 7 * len(name))
    for k in range(max(2, SEGMENTS // 4)):
        q0, q1 = random_segment(robot, rng)
        q1 = q0 + (q1 - q0) / 5
        obstacles = obstacles_near(robot, q0, q1, rng, n=3)
        what = (name, k)
        opts = dict(self_collision=False, time_tolerance="1e-9")
        ref = robot.check(q0, q1, obstacles, filter=False, **opts)
        same_first(robot.check(q0, q1, obstacles, **opts), ref, what)
        decide = robot.check(q0, q1, obstacles, first_contact=False, **opts)
        assert decide.collides == ref.collides, what


@needs_robots
@pytest.mark.parametrize("name,q", [
    ("panda", [0, 1.5, 0, 1.5, 0, 3.5, 0, 0.02]),   # joint 4 beyond its upper limit: folded
    ("ur5", [0, -1.0, 3.1, 3.1, 3.1, 0]),            # elbow and wrists folded back
])
def test_overlapping_start_answers_with_one_touching_pair(name, q):
    """A start pose with overlapping links (self-collision, adjacent pairs allowed): the
    first contact is exactly t = 0, reported with one touching pair (not every touching
    triangle pair), which touches when its two bodies are checked alone at the start
    pose; all_contacts still lists every pair, the witness among them."""
    robot = load_urdf(os.path.join(ROBOTS, URDFS[name]))
    q0 = np.array(q, dtype=float)
    q1 = q0 + 0.2
    if name == "panda":
        q1[-1] = q0[-1]
    allowed = robot.adjacent_pairs()
    for kw in (dict(), dict(first_contact=False)):
        r = robot.check(q0, q1, [], allowed=allowed, joint_limits="ignore", **kw)
        assert r.collides and len(r.scene.pairs) == 1
        (pair,) = r.scene.pairs
        assert pair_touches(robot, q0, q0, [], pair.names)
        if not kw:
            assert r.first_contact.exact == 0 and r.free_until == 0
            assert len(r.contacts) == 1
    every = robot.check(q0, q0, [], allowed=allowed, all_contacts=True, joint_limits="ignore")
    assert pair.names in {p.names for p in every.scene.pairs}
    assert sum(len(p.contacts) for p in every.scene.pairs) > 1


@needs_robots
@pytest.mark.parametrize("name", sorted(URDFS))
def test_filter_equals_unfiltered_with_self_collision(name):
    """Full meshes, self-collision on (adjacent and SRDF pairs allowed): link pairs are
    filtered relative to their common ancestor, so this compares that path too."""
    robot = arm(name)
    rng = random.Random(SEED + 11 * len(name))
    for k in range(max(3, SEGMENTS)):
        q0, q1 = random_segment(robot, rng)
        q1 = q0 + (q1 - q0) / 5
        obstacles = obstacles_near(robot, q0, q1, rng, n=2) if k % 2 else []
        check_all_ways(robot, q0, q1, obstacles, True, (name, k))


def gap_box(robot, q0, q1, rng, gap):
    """A 1 cm box ahead of a random link at t = 1, on the axis along which the link last
    moved most, its near face exactly gap (a Fraction) beyond the link's extreme vertex
    then, in exact rationals: gap 0 touches at t = 1, a small gap passes a hair from it
    (unless another part of the link crossed the box on the way), a negative one dips in."""
    motions = robot.motions(q0, q1)
    _, _, k, shape = rng.choice(robot.shapes)
    verts = [[float(c) for c in v] for v in shape.vertices]
    v = rng.choice(verts)
    d = [p - q for p, q in zip(motions[k].position(v, 1), motions[k].position(v, F(15, 16)))]
    a = max(range(3), key=lambda b: abs(d[b]))
    sign = 1 if d[a] > 0 else -1
    x = max((motions[k].position(v, 1) for v in verts), key=lambda p: sign * p[a])
    lo = [c - F(1, 200) for c in x]
    hi = [c + F(1, 200) for c in x]
    lo[a], hi[a] = sorted((x[a] + sign * gap, x[a] + sign * (gap + F(1, 100))))
    return P.Body(P.Mesh([[(lo[b], hi[b])[(i >> b) & 1] for b in range(3)] for i in range(8)], BOX_T),
                  name="gap")


@needs_robots
@pytest.mark.parametrize("name", sorted(URDFS))
def test_built_near_misses_and_touches(name):
    """Robot versus the gap boxes (self-collision is covered above: on the boxed arms the
    unfiltered self-collision check of such a segment can take minutes)."""
    robot = boxed(arm(name))
    rng = random.Random(SEED + 13 * len(name))
    seen = {True: 0, False: 0}
    for k in range(max(3, SEGMENTS // 2)):
        q0, q1 = random_segment(robot, rng)
        q1 = q0 + (q1 - q0) / 3
        for gap in (F(0), F(1, 10 ** 4), F(-1, 10 ** 4), F(1, 10 ** 9), F(-1, 10 ** 9)):
            box = gap_box(robot, q0, q1, rng, gap)
            seen[check_all_ways(robot, q0, q1, [box], False, (name, k, str(gap)))] += 1
    assert seen[True] and seen[False], seen  # both kinds were checked


@needs_robots
@pytest.mark.parametrize("name", sorted(URDFS))
def test_states_through_the_filter(name):
    """Robot states (q0 = q1, obstacles still: every time piece holds the same poses, so
    the filter stops at the first piece it cannot separate, link_filter.h's frozen
    sides, and the decide scan looks at one instant): the answers of the unfiltered
    check, on the full meshes with obstacles where the links are (self-collision off and
    on), and on the boxed arm against gap boxes touching, a hair from and a hair into a
    link."""
    robot = arm(name)
    rng = random.Random(SEED + 17 * len(name))
    for k in range(max(4, SEGMENTS)):
        q, _ = random_segment(robot, rng)
        obstacles = obstacles_near(robot, q, q, rng, n=3, spread=0.05)
        check_all_ways(robot, q, q, obstacles, k % 2 == 1, (name, k))
    boxes = boxed(robot)
    seen = {True: 0, False: 0}
    for k in range(3):
        q, _ = random_segment(boxes, rng)
        for gap in (F(0), F(1, 10 ** 9), F(-1, 10 ** 9)):
            box = gap_box(boxes, q, q, rng, gap)
            seen[check_all_ways(boxes, q, q, [box], False, (name, "gap", k, str(gap)))] += 1
    assert seen[True] and seen[False], seen  # both kinds were checked
