"""polyccd.ompl's lean validator path (polyccd/_robot_edge.py: one C call per state or
edge, no result objects): RobotSpace.is_valid / motion_valid, and so OMPL's isValid /
checkMotion, equal Robot.check on random states and edges of the Panda among boxes and a
2 mm plate (self-collision off and on, decide and first-contact options, a minimum
distance); a state outside the joint limits is invalid with Robot.check's error kept in
space.errors; replacing check_options or the obstacles takes effect at the next check.
"""
import math
import os
import random

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
pytest.importorskip("ompl")
import polyccd as P  # noqa: E402
import polyccd.ompl as PO  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_fk import ROBOTS, URDFS, needs_robots  # noqa: E402

SEED = 20261128
FINGER = {"panda_finger_joint1": 0.02}


def scene():
    robot = load_urdf(os.path.join(ROBOTS, URDFS["panda"]))
    rng = random.Random(SEED)
    obstacles = []
    for k in range(4):
        a, r = rng.uniform(-math.pi, math.pi), rng.uniform(0.3, 0.6)
        c = [r * math.cos(a), r * math.sin(a), rng.uniform(0.1, 0.7)]
        size = [rng.uniform(0.05, 0.2) for _ in range(3)]
        if k == 3:
            size[2] = 0.002
        obstacles.append(P.Body(P.Mesh.box(size), P.Motion.linear(c, c), name=f"box{k}"))
    return robot, obstacles, rng


@needs_robots
@pytest.mark.parametrize("options", [dict(self_collision=False, first_contact=False),
                                     dict(self_collision=True, first_contact=False),
                                     dict(self_collision=False),
                                     dict(self_collision=False, first_contact=False,
                                          min_distance="0.01")])
def test_lean_validators_equal_robot_check(options):
    robot, obstacles, rng = scene()
    space = PO.RobotSpace(robot, obstacles, fixed=FINGER, **options)
    seen = set()
    for _ in range(10):
        q0 = np.array([rng.uniform(lo, hi) for lo, hi in space.bounds] + [0.02])
        q1 = np.clip(q0 + np.array([rng.uniform(-0.8, 0.8) for _ in space.bounds] + [0]),
                     [lo for lo, _ in space.bounds] + [0.02], [hi for _, hi in space.bounds] + [0.02])
        s0, s1 = space.state(q0), space.state(q1)
        want_state = not robot.check(q0, q0, obstacles, **options).collides
        want_edge = not robot.check(q0, q1, obstacles, **options).collides
        assert space.validity_checker.isValid(s0) == want_state
        assert space.motion_validator.checkMotion(s0, s1) == want_edge
        assert space.si.checkMotion(s0, s1) == want_edge  # through OMPL's C++
        seen.add(want_edge)
    assert space._edge is not None and not space.errors
    assert seen == {True, False}


@needs_robots
def test_lean_path_errors_and_replaced_options():
    robot, obstacles, rng = scene()
    space = PO.RobotSpace(robot, obstacles, fixed=FINGER, self_collision=False, first_contact=False,
                          bounds={"panda_joint1": (-4, 4)})
    q = np.zeros(8)
    q[0], q[3], q[7] = 3.5, -1.5, 0.02  # joint 1 beyond its URDF limit (2.8973)
    assert not space.is_valid(q)
    assert str(space.errors[-1]).startswith("q0[0] (panda_joint1): 3.5 is outside the joint limits")
    space.check_options = dict(self_collision=False, first_contact=False, joint_limits="ignore")
    hit = robot.check(q, q, obstacles, self_collision=False, joint_limits="ignore").collides
    assert space.is_valid(q) == (not hit) and len(space.errors) == 1
    inside = np.array([0, -0.3, 0, -2.0, 0, 1.8, 0.8, 0.02])  # a pose clear of the boxes
    assert space.is_valid(inside) == (not robot.check(inside, inside, obstacles).collides)
    c = [0, 0, 0.3]  # a plate through the arm's base column: in contact
    wall = P.Body(P.Mesh.box([1, 1, 0.002]), P.Motion.linear(c, c), name="cut")
    space.obstacles = [wall]
    assert not space.is_valid(inside)
    q[0] = float("nan")
    assert not space.is_valid(q) and "q0[0] (panda_joint1)" in str(space.errors[-1])
