"""The joint-limit policy of Robot.check / check_path (polyccd/robot.py, docs/robots.md):
q0 or q1 outside an actuated joint's URDF limits [lower, upper] is an InputError naming
the waypoint, the joint and the value (default joint_limits="error"); the closed bounds
themselves are inside; joint_limits="ignore" checks the segment as it is, with the same
answer as the same robot read from a URDF whose limits contain the segment; continuous
joints have no limits; the Panda's limits (example-robot-data) are the URDF's numbers.
"""
import math

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from polyccd import InputError  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_fk import ROBOTS, URDFS, needs_robots  # noqa: E402

# Two links on two joints (the shoulder about z, the elbow about z), limits written here.
URDF = """<?xml version="1.0"?>
<robot name="limited">
  <link name="base"><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.1 0.1"/></geometry></collision></link>
  <link name="lower"><collision><origin xyz="0.4 0 0"/><geometry><box size="0.8 0.1 0.1"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="%s" upper="%s" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="%s"><parent link="upper"/><child link="lower"/>
    <origin xyz="1 0 0"/><axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" effort="1" velocity="1"/></joint>
</robot>
"""


def robot(tmp_path, lower="-1", upper="2", elbow="revolute", name="r.urdf"):
    p = tmp_path / name
    p.write_text(URDF % (lower, upper, elbow))
    return load_urdf(str(p))


def post(x, y):
    """A 10 cm post standing at (x, y), as tall as the arm's height."""
    lo, hi = [x - 0.05, y - 0.05, 0], [x + 0.05, y + 0.05, 0.3]
    v = [[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)]
    t = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
         [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
    return P.Body(P.Mesh(v, t), name="post")


def test_limits_error_names_joint_and_value(tmp_path):
    r = robot(tmp_path)
    assert r.limits == {"shoulder": (-1.0, 2.0), "elbow": (-1.5, 1.5)}
    obstacles = [post(0, 1.5)]
    with pytest.raises(InputError, match=r"^q0\[0\] \(shoulder\): -1\.25 is outside the joint "
                       r"limits \[-1\.0, 2\.0\] of the URDF \(joint_limits=\"ignore\" allows it\)$"):
        r.check([-1.25, 0], [0, 0], obstacles)
    with pytest.raises(InputError, match=r"^q1\[1\] \(elbow\): 1\.6 is outside the joint limits "
                       r"\[-1\.5, 1\.5\]"):
        r.check([0, 0], [0, 1.6], obstacles)
    # The next double above the upper limit is outside; the limit itself is inside.
    with pytest.raises(InputError, match=r"^q1\[0\] \(shoulder\)"):
        r.check([0, 0], [np.nextafter(2.0, 3.0), 0], obstacles)
    r.check([-1.0, -1.5], [2.0, 1.5], obstacles)
    # check_path places the segment first, as for every other input error.
    with pytest.raises(InputError, match=r"^waypoints\[1\] -> waypoints\[2\]: q1\[0\] "
                       r"\(shoulder\): 2\.5 is outside"):
        r.check_path([[0, 0], [1, 0], [2.5, 0]], obstacles)
    with pytest.raises(InputError, match=r"^joint_limits: 'warn' is not \"error\" or \"ignore\""):
        r.check([0, 0], [1, 0], obstacles, joint_limits="warn")
    # A wrong shape keeps its own message; a non-finite value is the chain's to report.
    with pytest.raises(InputError, match=r"^q0: expected 2 joint values"):
        r.check([0], [0], obstacles)
    with pytest.raises(InputError, match=r"^q1\[0\] \(shoulder\): .*(finite|nan)"):
        r.check([0, 0], [float("nan"), 0], obstacles)


def test_limits_ignore_checks_the_segment_as_it_is(tmp_path):
    """Outside the limits with joint_limits="ignore": the same answer (first contact,
    contacts) as a robot read from a URDF whose limits contain the segment."""
    narrow = robot(tmp_path)
    wide = robot(tmp_path, "-3", "3", name="wide.urdf")
    segments = [([-2.5, 0.3], [-0.5, 0.3]), ([1.0, -0.2], [2.9, 0.4]), ([-1.2, 1.0], [-1.2, 1.0])]
    obstacles = [post(0, 1.5), post(-1.4, -0.3)]
    collided = 0
    for q0, q1 in segments:
        with pytest.raises(InputError, match=r"outside the joint limits"):
            narrow.check(q0, q1, obstacles)
        got = narrow.check(q0, q1, obstacles, joint_limits="ignore", time_tolerance="1e-9")
        ref = wide.check(q0, q1, obstacles, time_tolerance="1e-9")
        assert (got.collides, got.first_contact) == (ref.collides, ref.first_contact)
        assert got.contacts == ref.contacts
        collided += got.collides
        path = narrow.check_path([q0, q1], obstacles, joint_limits="ignore")
        assert path.segment == (0 if got.collides else None)
    assert 0 < collided < len(segments)


def test_continuous_joint_has_no_limits(tmp_path):
    r = robot(tmp_path, elbow="continuous")
    assert r.limits["elbow"] is None
    r.check([0, 3.0], [0, 3.0 + math.pi], [post(0, 1.5)])  # elbow at 6.14: no limit


@needs_robots
def test_panda_limits_are_the_urdfs():
    import xml.etree.ElementTree as ET
    import os
    path = os.path.join(ROBOTS, URDFS["panda"])
    r = load_urdf(path)
    xml = {j.get("name"): j for j in ET.parse(path).getroot().findall("joint")}
    for name in r.joints:
        lim = xml[name].find("limit")
        assert r.limits[name] == (float(lim.get("lower")), float(lim.get("upper")))
    q = np.array([(lo + hi) / 2 for lo, hi in (r.limits[n] for n in r.joints)])
    bad = q.copy()
    j = r.joints.index("panda_joint4")
    bad[j] = r.limits["panda_joint4"][1] + 0.01  # joint 4's upper limit is -0.0698
    far = P.Body(P.Spheres([[5, 5, 5]], [0.1]), name="far")
    assert not r.check(q, q, [far], self_collision=False).collides
    with pytest.raises(InputError, match=rf"^q1\[{j}\] \(panda_joint4\): .* is outside"):
        r.check(q, bad, [far], self_collision=False)
