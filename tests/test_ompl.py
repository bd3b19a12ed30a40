"""polyccd.ompl (the optional "ompl" extra): OMPL's validators on polyccd's exact checks.

- The missing-extra error names the extra; `import polyccd` imports neither polyccd.ompl
  nor ompl (both without ompl installed).
- The joint path: RobotSpace.interpolate / joint_path equal Robot.joint_values (the C
  library's values of the exact chain path) at sampled rational times, for a small arm
  written here and the Franka Panda (example-robot-data), fixed joints included.
- The validators on random segments of the small arm among posts: checkMotion(s1, s2)
  (called from Python and through OMPL's C++ SpaceInformation) equals Robot.check (whose
  broad phases test_robot.py holds to brute force); the last-valid form returns, for an
  invalid motion, a fraction strictly below the certified first contact's lower end, a
  state on the joint path at that fraction, contact-free by an exact static check, and
  a contact-free path from s1 to it; isValid equals the exact static check. A check that raises (a work
  limit) makes the motion invalid and is kept in space.errors.
- RRTConnect plans the small arm around a post: the path is free by polyccd's check of
  every segment and by exact static checks of dense poses along the joint path.
"""
import random
import subprocess
import sys
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
import polyccd.ompl as PO  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_fk import ROBOTS, URDFS, needs_robots  # noqa: E402
from test_robot_limits import URDF, post  # noqa: E402

SEED = 20261125


def arm(tmp_path, elbow="revolute"):
    p = tmp_path / "arm.urdf"
    p.write_text(URDF % ("-3", "3", elbow))
    return load_urdf(str(p))


def test_missing_extra_names_it(monkeypatch, tmp_path):
    robot = arm(tmp_path)
    for name in ("ompl", "ompl.base", "ompl.geometric"):
        monkeypatch.setitem(sys.modules, name, None)  # `import ompl` raises ImportError
    monkeypatch.setattr(PO, "_CLASSES", None)
    with pytest.raises(ModuleNotFoundError, match=r"^polyccd\.ompl needs the package 'ompl', "
                       r"which is not installed \(.*\); install it with: pip install "
                       r'"polyccd\[ompl\]" \(adds the \'ompl\' extra\'s packages to this '
                       r'installed polyccd\)$'):
        PO.RobotSpace(robot, [post(0, 1.5)])
    with pytest.raises(ImportError, match=r'pip install "polyccd\[ompl\]"'):
        PO.MotionValidator
    # joint_path needs no OMPL.
    assert PO.joint_path([True], [0.0], [1.0], 1.0)[0] == pytest.approx(1.0, abs=1e-15)


def test_import_polyccd_does_not_import_ompl():
    code = ("import sys, polyccd; print('polyccd.ompl' in sys.modules, 'ompl' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "False"]


def check_joint_path(robot, space, rng, segments, times):
    """RobotSpace.joint_path and interpolate against Robot.joint_values."""
    names = robot.joints
    worst = 0.0
    for _ in range(segments):
        q0, q1 = space.q(space.state(sample(space, rng))), space.q(space.state(sample(space, rng)))
        s0, s1 = space.state(q0), space.state(q1)
        for k in range(times + 1):
            t = F(k, times) if k in (0, times) else F(rng.randrange(1, 10 ** 6), 10 ** 6)
            exact = robot.joint_values(q0, q1, t)
            mine = space.joint_path(q0, q1, float(t))
            state = space.q(space.interpolate(s0, s1, float(t)))
            for j, n in enumerate(names):
                worst = max(worst, abs(mine[j] - exact[n]), abs(state[j] - exact[n]))
        # The vectorized form equals the scalar one.
        ts = np.array([0.25, 0.5, 0.75])
        np.testing.assert_array_equal(space.joint_path(q0, q1, ts)[1],
                                      space.joint_path(q0, q1, 0.5))
    return worst


def sample(space, rng):
    return [rng.uniform(lo, hi) for lo, hi in space.bounds]


def test_interpolation_is_the_chains_joint_path(tmp_path):
    pytest.importorskip("ompl")
    rng = random.Random(SEED)
    robot = arm(tmp_path)
    space = PO.RobotSpace(robot, [post(0, 1.5)])
    assert check_joint_path(robot, space, rng, 20, 12) < 1e-12
    # Not the linear interpolation of the angles: the half-angle path leaves it between
    # the ends (joint 0 from -2.5 to 2.5 is at 0 when t = 1/2, at -1.43... when t = 1/4).
    q = space.joint_path([-2.5, 0], [2.5, 0], 0.25)
    assert abs(q[0] - (-1.25)) > 0.1


@needs_robots
def test_interpolation_is_the_chains_joint_path_panda():
    pytest.importorskip("ompl")
    import os
    robot = load_urdf(os.path.join(ROBOTS, URDFS["panda"]))
    rng = random.Random(SEED + 1)
    space = PO.RobotSpace(robot, [post(3, 3)], fixed={"panda_finger_joint1": 0.02})
    assert space.joints == robot.joints[:7]
    assert check_joint_path(robot, space, rng, 10, 10) < 1e-12
    assert space.q(space.state(np.zeros(7)))[7] == 0.02
    # With the fingers planned too, the prismatic joint moves linearly.
    free = PO.RobotSpace(robot, [post(3, 3)])
    assert check_joint_path(robot, free, rng, 5, 10) < 1e-12


def random_segments(space, rng, n):
    out = []
    for _ in range(n):
        q0 = np.array(sample(space, rng))
        q1 = np.clip(q0 + [rng.uniform(-2, 2) for _ in q0], *np.array(space.bounds).T)
        out.append((q0, q1))
    return out


def test_validators_agree_with_robot_check(tmp_path):
    pytest.importorskip("ompl")
    robot = arm(tmp_path)
    obstacles = [post(0, 1.5), post(-1.4, -0.3), post(1.2, 0.2)]
    options = dict(time_tolerance="1e-9")
    space = PO.RobotSpace(robot, obstacles, **options)
    mv, si = space.motion_validator, space.si
    rng = random.Random(SEED + 2)
    counts = {"valid": 0, "invalid": 0, "backoff": 0}
    for q0, q1 in random_segments(space, rng, 24):
        s0, s1 = space.state(q0), space.state(q1)
        ref = robot.check(q0, q1, obstacles, **options)
        assert mv.checkMotion(s0, s1) == (not ref.collides)
        assert si.checkMotion(s0, s1) == (not ref.collides)  # through OMPL's C++
        for q, s in ((q0, s0), (q1, s1)):
            still = robot.check(q, q, obstacles)
            assert si.isValid(s) == space.validity_checker.isValid(s) == (not still.collides)
        out = si.allocState()
        last = [out, -1.0]
        valid = mv.checkMotion(s0, s1, last)
        assert valid == (not ref.collides)
        assert mv.checkMotionWithLastValid(s0, s1, si.allocState())[0] == valid
        if valid:
            assert last[1] == -1.0  # untouched, as OMPL's validators leave it
            counts["valid"] += 1
            continue
        counts["invalid"] += 1
        f, q = last[1], space.q(out)
        assert 0 <= f and (f == 0 or F(f) < ref.first_contact.lo)
        if f == 0:
            np.testing.assert_array_equal(q, q0)
            continue
        counts["backoff"] += 1
        exact = robot.joint_values(q0, q1, F(f))
        np.testing.assert_allclose(q, [exact[n] for n in robot.joints], rtol=0, atol=1e-12)
        assert not robot.check(q, q, obstacles).collides
        assert not robot.check(q0, q, obstacles).collides
    assert counts["valid"] and counts["invalid"] and counts["backoff"], counts
    assert space.errors == []


def test_a_check_that_raises_is_invalid(tmp_path):
    pytest.importorskip("ompl")
    robot = arm(tmp_path)
    space = PO.RobotSpace(robot, [post(0, 1.5)], limits=P.Limits(max_work=3))
    s0, s1 = space.state([-1.5, 0]), space.state([1.5, 0])
    assert not space.si.checkMotion(s0, s1)
    assert not space.si.isValid(s0)  # a free state, but its check ends on the budget
    assert space.errors and all(isinstance(e, P.LimitError) for e in space.errors)
    with pytest.raises(P.InputError, match=r"^fixed: joint 'elbow' is neither planned nor fixed"):
        PO.RobotSpace(robot, [], joints=["shoulder"])
    with pytest.raises(P.InputError, match=r"^joints: 'wrist' is not an actuated joint"):
        PO.RobotSpace(robot, [], joints=["wrist"])


def test_rrtconnect_plans_around_a_post(tmp_path):
    pytest.importorskip("ompl")
    from ompl import geometric as og, util as ou
    ou.setLogLevel(ou.LogLevel.LOG_WARN)
    ou.RNG.setSeed(SEED)
    robot = arm(tmp_path)
    # The arm (shoulder link 1 m, forearm 0.8 m, at z 0.1 to 0.2) must not sweep through
    # the post at (1.5, 0): it folds its elbow to pass, or turns the other way round.
    obstacles = [post(1.5, 0.0)]
    space = PO.RobotSpace(robot, obstacles)
    start, goal = [-0.8, 0.0], [0.8, 0.0]
    assert not space.motion_valid(np.array(start), np.array(goal))
    ss = space.simple_setup()
    ss.setStartAndGoalStates(space.state(start), space.state(goal))
    ss.setPlanner(og.RRTConnect(space.si))
    assert ss.solve(30.0) and ss.haveExactSolutionPath()
    path = space.simplify(ss.getSolutionPath())
    waypoints = space.waypoints(path)
    assert np.allclose(waypoints[0], start) and np.allclose(waypoints[-1], goal)
    assert space.check_path(path, broad_phase="brute").segment is None
    poses = space.interpolate_path(path, 0.02)
    assert len(poses) > 2 * len(waypoints)
    for q in poses:
        assert not robot.check(q, q, obstacles).collides
    assert space.errors == []
