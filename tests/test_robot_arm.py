"""Robots (polyccd.robot): a small synthetic arm written here (obstacle and
self-collision answers equal brute force, the allowed pairs, the first colliding
segment of a path, a minimum distance) and the errors: bad URDFs (missing mesh file,
floating / planar joints, zero axis) and bad segments, named in q's terms by the C
library (a full turn: "q1[1] (elbow): ...").
"""
import math
import pickle
import random
from fractions import Fraction as F

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from helpers import box, summary  # noqa: E402
from polyccd import InputError  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot import SEED  # noqa: E402


# ---------------------------------------------------------------- a synthetic arm

ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base"><collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.2 0.2"/></geometry></collision></link>
  <link name="lower"><collision><origin xyz="0.4 0 0"/><geometry><box size="0.8 0.1 0.1"/></geometry></collision>
                     <collision><origin xyz="0.8 0 0" rpy="0 0 0.5"/><geometry><sphere radius="0.08"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.2" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-6" upper="6" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="%s"><parent link="upper"/><child link="lower"/>
    <origin xyz="1 0 0" rpy="0 0 0"/><axis xyz="%s"/><limit lower="-6" upper="6" effort="1" velocity="1"/></joint>
</robot>
"""


def write(tmp_path, text, name="arm.urdf"):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


def test_synthetic_arm_equals_brute_force(tmp_path):
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    assert robot.joints == ["shoulder", "elbow"]
    assert robot.adjacent_pairs() == {frozenset(("base", "upper")), frozenset(("upper", "lower"))}
    rng = random.Random(SEED)
    collided = 0
    for case in range(6):
        q0 = [rng.uniform(-3, 3), rng.uniform(-3, 3)]
        q1 = [x + rng.uniform(-2.5, 2.5) for x in q0]
        c = [rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), F(1, 5)]
        obstacle = P.Body(box([c[0], c[1], 0], [c[0] + 0.1, c[1] + 0.1, 0.5]), name="post")
        for allowed in (None, []):
            got = robot.check(q0, q1, [obstacle], allowed=allowed, time_tolerance="1e-9")
            brute = robot.check(q0, q1, [obstacle], allowed=allowed, time_tolerance="1e-9",
                                broad_phase="brute")
            assert summary(got.scene) == summary(brute.scene), (case, q0, q1, c, allowed)
            collided += got.collides
        # With the adjacent pairs checked, upper and lower always touch (they share a face).
        assert robot.check(q0, q1, [], allowed=[]).collides
        assert not robot.check(q0, q1, [], self_collision=True).scene.pairs or \
            all(set(p.names) != {"upper", "lower[0]"} for p in robot.check(q0, q1, []).scene.pairs)
    assert collided > 0


def test_synthetic_arm_path(tmp_path):
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    post = P.Body(box([1.5, -0.05, 0], [1.6, 0.05, 0.5]), name="post")  # on the +x axis
    # The arm points along -y, swings to -x (free: the post is at +x), then to +y through +x? no:
    # from -x back through -y to +x, where it meets the post.
    waypoints = [[-math.pi / 2, 0], [-math.pi + 0.1, 0], [-math.pi / 2, 0], [0.3, 0]]
    r = robot.check_path(waypoints, [post])
    assert r.segment == 2, r.segment
    assert r.result.collides and {c.b[0] for c in r.result.contacts} == {"post"}
    # The shoulder's angle at the first contact: between the segment's ends, and the
    # arm's far end (x = 1.88 at most) first reaches the post's corner.
    lo = r.result.joint_values[0]["shoulder"]
    assert -math.pi / 2 < lo < 0.3
    assert robot.check_path(waypoints[:3], [post]).segment is None


def test_synthetic_arm_min_distance(tmp_path):
    """Robot.check and check_path pass min_distance through: every broad phase equals
    brute force at delta > 0 (the box phases grow one body's boxes by delta), and a post
    the arm's tip passes 0.12 away from (tip at x = 1.88 when the arm points along +x,
    post from x = 2) is met within 1/5, not within 1/10."""
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    rng = random.Random(SEED + 1)
    decided = 0
    for case in range(4):
        q0 = [rng.uniform(-3, 3), rng.uniform(-3, 3)]
        q1 = [x + rng.uniform(-2.5, 2.5) for x in q0]
        c = [rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)]
        obstacle = P.Body(box([c[0], c[1], 0], [c[0] + 0.1, c[1] + 0.1, 0.5]), name="post")
        delta = F(1, 10)  # (1/4 puts base and lower within delta at t = 0: slow brute force)
        brute = robot.check(q0, q1, [obstacle], min_distance=delta, time_tolerance="1e-9",
                            broad_phase="brute")
        for phase in ("auto", "bvh", "boxes"):
            got = robot.check(q0, q1, [obstacle], min_distance=delta, time_tolerance="1e-9",
                              broad_phase=phase)
            assert summary(got.scene) == summary(brute.scene), (case, q0, q1, c, phase)
        plain = robot.check(q0, q1, [obstacle], time_tolerance="1e-9")
        decided += brute.collides and (not plain.collides or
                                       plain.first_contact.lo > brute.first_contact.hi)
    assert decided > 0
    post = P.Body(box([2, -0.05, 0], [2.1, 0.05, 0.5]), name="post")
    waypoints = [[-math.pi / 2, 0], [-math.pi + 0.1, 0], [-math.pi / 2, 0], [0.3, 0]]
    path = dict(self_collision=False, time_tolerance="1e-9")
    assert robot.check_path(waypoints, [post], **path).segment is None
    assert robot.check_path(waypoints, [post], min_distance="1/10", **path).segment is None
    r = robot.check_path(waypoints, [post], min_distance="1/5", **path)
    assert r.segment == 2 and {c.b[0] for c in r.result.contacts} == {"post"}
    brute = robot.check(waypoints[2], waypoints[3], [post], min_distance="1/5",
                        broad_phase="brute", **path)
    assert summary(r.result.scene) == summary(brute.scene)


# ---------------------------------------------------------------- errors

def test_bad_urdfs(tmp_path):
    with pytest.raises(InputError, match="joints.elbow: type 'floating' is not supported"):
        load_urdf(write(tmp_path, ARM % ("floating", "0 0 1")))
    with pytest.raises(InputError, match="joints.elbow: type 'planar' is not supported"):
        load_urdf(write(tmp_path, ARM % ("planar", "0 0 1")))
    with pytest.raises(InputError, match=r"^joints.elbow.axis: the direction is the zero vector"):
        load_urdf(write(tmp_path, ARM % ("revolute", "0 0 0")))
    with pytest.raises(InputError, match=r"^path: .* is not a readable URDF \(could not broadcast"):  # yourdfpy's check
        load_urdf(write(tmp_path, (ARM % ("revolute", "0 0 1")).replace('xyz="1 0 0"', 'xyz="1 0"')))
    text = (ARM % ("revolute", "0 0 1")).replace('<sphere radius="0.08"/>', '<mesh filename="missing/part.stl"/>')
    with pytest.raises(InputError, match=r"^links.lower.collision\[1\].geometry.mesh: mesh file '.*part.stl' not found"):
        load_urdf(write(tmp_path, text))
    with pytest.raises(InputError, match=r"^path: URDF file .* not found"):
        load_urdf(str(tmp_path / "nothing.urdf"))
    robot = load_urdf(write(tmp_path, ARM % ("continuous", "0 0 1")))
    assert robot.limits["elbow"] is None
    with pytest.raises(InputError, match=r"^q1\[1\] \(elbow\): the revolute segment from 0 to 7 turns by 2 pi"):
        robot.motions([0, 0], [0, 7])
    with pytest.raises(InputError, match=r"^waypoints\[1\] -> waypoints\[2\]: q1\[1\] \(elbow\)"):
        robot.check_path([[0, 0], [0, 1], [0, 8]], [P.Body(P.Spheres([[9, 9, 9]], [1]))])
    with pytest.raises(InputError, match=r"^q0\[1\] \(elbow\): "):  # not finite
        robot.motions([0, float("nan")], [0, 0])
    with pytest.raises(InputError, match=r"^q0: expected 2 joint values"):
        robot.motions([0], [0])
    with pytest.raises(InputError, match=r"^allowed\[0\]:"):
        robot.check([0, 0], [0, 1], allowed=[("base", "nope")])


def test_robot_check_takes_limits(tmp_path):
    """Robot.check and check_path pass limits= to the scene (polyccd.Limits): a work limit
    below what the segment needs stops it with LimitError, a generous one changes nothing."""
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    post = P.Body(box([1.5, -0.05, 0], [1.6, 0.05, 0.5]), name="post")
    q0, q1 = [-math.pi / 2, 0], [0.3, 0]
    free = robot.check(q0, q1, [post])
    assert free.collides
    with pytest.raises(P.LimitError, match=r"^config\.max_work: the limit of 3 work steps was reached"):
        robot.check(q0, q1, [post], limits=P.Limits(max_work=3))
    with pytest.raises(P.LimitError, match=r"^waypoints\[0\] -> waypoints\[1\]: config\.max_work"):
        robot.check_path([q0, q1], [post], limits=P.Limits(max_work=3))
    same = robot.check(q0, q1, [post], limits=P.Limits(max_work=10 ** 9))
    assert same.first_contact == free.first_contact


def test_chain_errors_name_the_value_as_the_caller_does():
    """Chain.set_value_place (pccd_chain_set_value_place): the C library names a bad
    joint value with the place the caller gave (load_urdf gives q's index and the joint
    name), so no message is rewritten afterwards; pickles keep the places."""
    c = P.Chain()
    c.add_link(-1, "revolute", [0, 0, 1])
    c.add_link(0, "prismatic", [1, 0, 0])
    with pytest.raises(InputError, match=r"^q1\[0\]: the revolute segment from 0 to 7 turns by 2 pi"):
        c.motions([0, 0], [7, 0])
    c.set_value_place(0, "[3] (wrist)")
    with pytest.raises(InputError, match=r"^q1\[3\] \(wrist\): the revolute segment from 0 to 7 turns"):
        c.motions([0, 0], [7, 0])
    with pytest.raises(InputError, match=r"^q0\[1\]: "):  # the other link keeps its index
        c.motions([0, float("nan")], [0, 0])
    with pytest.raises(InputError, match=r"^k: 2 out of range \(the chain has 2 links\)"):
        c.set_value_place(2, "[9]")
    again = pickle.loads(pickle.dumps(c))
    with pytest.raises(InputError, match=r"^q1\[3\] \(wrist\): "):
        again.motions([0, 0], [7, 0])
    m = pickle.loads(pickle.dumps(c.motions([0, 0], [1, 1])[1]))  # a chain Motion's recipe
    assert m.position([0, 0, 0], 1) == c.motions([0, 0], [1, 1])[1].position([0, 0, 0], 1)
