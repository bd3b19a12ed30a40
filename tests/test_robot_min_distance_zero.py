"""First-contact mode with a minimum distance where the start pose is already within
delta of an obstacle (issue 33): every pair is tested at t = 0 before any traversal; the
pairs before the first one certainly within delta then are dropped when certainly
farther than delta at 0, else solved exactly at 0, and the exact solve after a witness
at 0 runs on the window [0, 2^-14], or not at all when no pair before the witness pair
is left (lib/scene/robot.cpp). The answers (first contact, its pairs and features)
equal the unfiltered exact check and brute force (test_robot_filter.check_all_ways) on
the boxy arm of test_robot_arm.py: its upper link starts along +x (shoulder at 0) with a
post 0.03 beside it (within delta 0.05 at t = 0, not touching), among random posts
listed before and after it, so the pair within delta at 0 is neither first nor last."""
import random
from fractions import Fraction as F

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from helpers import box  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_arm import ARM, write  # noqa: E402
from test_robot_filter import check_all_ways, pair_touches  # noqa: E402

SEED = 3302


def posts(rng, gap):
    """Two random posts, the post `gap` beside the upper link at shoulder 0 (the link
    spans y in [-0.1, 0.1], z in [0.1, 0.3], x in [0, 1]), then two more random posts."""
    out = []
    for k in range(4):
        c = [rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)]
        out.append(P.Body(box([c[0], c[1], 0], [c[0] + 0.1, c[1] + 0.1, 0.5]), name=f"post{k}"))
    near = P.Body(box([F(9, 20), F(1, 10) + gap, 0], [F(11, 20), F(1, 5) + gap, F(1, 2)]), name="near")
    return out[:2] + [near] + out[2:]


@pytest.mark.parametrize("delta", [F(1, 20)])
def test_start_within_delta_equals_exact(tmp_path, delta):
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    rng = random.Random(SEED)
    hits = witnessed = 0
    for case in range(5):
        q0 = [0, rng.uniform(-2.5, 2.5)]
        q1 = [rng.uniform(-2, 2), q0[1] + rng.uniform(-2, 2)]
        obstacles = posts(rng, F(3, 100))
        hits += check_all_ways(robot, q0, q1, obstacles, False, (case, q0, q1, delta), min_distance=delta)
        # The near post is within delta at t = 0 (0.03 < delta) whatever else happens.
        for self_collision in (True, False):
            first = robot.check(q0, q1, obstacles, min_distance=delta, self_collision=self_collision)
            assert first.first_contact.hi == 0, case
            # Each pair reported (without self-collision: the filter's witness at 0, every
            # pair before it farther than delta then; lib/scene/robot.cpp) is within delta
            # at q0, checked alone as a scene of the two bodies standing at q0.
            for pair in first.scene.pairs:
                assert pair_touches(robot, q0, q0, obstacles, pair.names, delta), (case, pair.names)
                witnessed += features_within(robot, q0, obstacles, pair, delta, case)
    assert witnessed >= 5  # the filter's witness answered (one triangle pair per case)


def features_within(robot, q0, obstacles, pair, delta, case):
    """Each reported triangle pair of `pair`, the two triangles alone standing at q0, is
    within delta (a static scene of two one-triangle meshes). Returns how many."""
    from polyccd._robot_check import _names
    motions = robot.motions(q0, q0)
    bodies = {n: (s, motions[k]) for n, (_, _, k, s) in zip(_names(robot), robot.shapes)}
    bodies.update({o.name: (o.shape, o.motion) for o in obstacles})
    done = 0
    for c in pair.contacts:
        if c.a[0] != "triangle" or c.b[0] != "triangle":
            continue  # the exact solve's features (vertex, edge): its own tests cover them
        alone = []
        for name, (_, index) in zip(pair.names, (c.a, c.b)):
            shape, motion = bodies[name]
            alone.append(P.Body(P.Mesh(shape.exact_vertices(), shape.triangles[index:index + 1]), motion))
        assert P.check(alone, min_distance=delta).first_contact.hi == 0, (case, pair.names, c)
        done += 1
    return done
    assert hits == 5
