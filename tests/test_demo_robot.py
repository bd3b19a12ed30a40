"""The robot part of `polyccd demo` (polyccd.apps._demo_robot): a Panda sweeping past a
2 mm plate. The exact check of the segment finds a contact, strictly between the
discrete check's samples 4/9 and 5/9 (fingers against the plate), and each of the 10
sampled poses is collision-free, decided exactly (a stationary robot), while the pose at
t = 1/2 between them collides: the same static check does see the plate. The contact
time is checked by two exact static tests around it, not by a stored number.
Skipped without yourdfpy / example-robot-data (about 1 s here)."""
from fractions import Fraction

import numpy as np
import pytest

from polyccd.apps import _demo_robot as D

needs_robot = pytest.mark.skipif(bool(D.missing_packages()),
                                 reason="yourdfpy or example-robot-data is not installed")


@pytest.fixture(scope="module")
def demo():
    return D.robot_demo()


@needs_robot
def test_the_segment_collides_between_two_samples(demo):
    r = demo.result
    assert r.collides
    lo, hi = r.first_contact.lo, r.first_contact.hi
    assert Fraction(4, 9) < lo <= hi < Fraction(5, 9), (lo, hi)
    assert {c.b[0] for c in r.contacts} == {"plate"}
    assert all(c.a[0].startswith("panda_") and "finger" in c.a[0] for c in r.contacts)
    assert set(r.joint_values[0]) == set(demo.robot.joints)


@needs_robot
def test_the_ten_sampled_poses_are_free_and_the_pose_between_is_not(demo):
    assert [s.t for s in demo.samples] == [Fraction(k, 9) for k in range(10)]
    assert [s.collides for s in demo.samples] == [False] * 10, demo.samples
    assert demo.between.collides


@needs_robot
def test_the_first_contact_time_against_static_poses(demo):
    # Free a little before the enclosure, colliding a little after (the segment's joint
    # values rounded to doubles, each pose decided exactly): the contact lies in between.
    robot, r = demo.robot, demo.result
    for dt, expected in ((Fraction(-1, 10**4), False), (Fraction(1, 10**4), True)):
        t = (r.first_contact.lo if dt < 0 else r.first_contact.hi) + dt
        values = robot.joint_values(np.array(D.Q0), np.array(D.Q1), t)
        q = np.array([values[n] for n in robot.joints])
        assert D.pose_collides(robot, q, [demo.plate]) is expected, (t, q.tolist())


@needs_robot
def test_run_robot_demo_prints_and_draws(tmp_path):
    lines = []
    demo, png, ok = D.run_robot_demo(tmp_path, out=lines.append)
    text = "\n".join(lines)
    assert ok and png is not None and png.stat().st_size > 10000
    assert "MISSES the contact" in text and "first contact: t in [" in text
    assert "joint values at the first contact" in text


def test_without_the_packages_the_demo_says_so_and_skips(monkeypatch, tmp_path):
    monkeypatch.setattr(D, "missing_packages", lambda: ["yourdfpy", "example-robot-data"])
    lines = []
    assert D.run_robot_demo(tmp_path, out=lines.append) == (None, None, True)
    assert D.robot_demo() is None
    assert "robot demo skipped: yourdfpy, example-robot-data not installed" in "\n".join(lines)
    assert not list(tmp_path.iterdir())
