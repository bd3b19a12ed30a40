"""Self pairs solved in their common ancestor's frame (lib/scene/robot.cpp, solve_exact;
issue 33) answer as the world frame does.

A synthetic arm of five boxes on four revolute joints about different axes, so that
most self pairs have a moving common ancestor (link2 / link4: link2, which turns with
two joints above it). Robot.check with self-collision (filtered and unfiltered, with and
without a minimum distance) is compared with an independent solve of the same bodies in
the world frame: a polyccd scene (pccd_scene_solve) of every link body on its world
motion (Robot.motions), the robot's allowed pairs skipped. Everything the reports say is
equal: whether they collide, the first contact's enclosure and exactness, the pairs
touching first and their feature pairs (a robot check in first-contact mode lists the
pairs it found touching, not every pair in contact as the scene does).
"""
import random
from fractions import Fraction as F

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from polyccd._robot_check import _names  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot import SEED  # noqa: E402

LINK = ('  <link name="{n}"><collision><origin xyz="{x} 0 0"/><geometry><box size="{l} {w} {w}"/>'
        '</geometry></collision></link>\n')
JOINT = ('  <joint name="j{k}" type="revolute"><parent link="{p}"/><child link="{c}"/>'
         '<origin xyz="{o} 0 {z}" rpy="0 0 0"/><axis xyz="{axis}"/>'
         '<limit lower="-6" upper="6" effort="1" velocity="1"/></joint>\n')
# Axes: about z, y, z, x. Lengths so that the tip can fold back onto link2 and link1.
AXES = ("0 0 1", "0 1 0", "0 0 1", "1 0 0")
LENGTHS = (0.6, 0.5, 0.4, 0.3)


def arm_urdf():
    text = '<?xml version="1.0"?>\n<robot name="folding">\n'
    text += LINK.format(n="base", x=0, l=0.3, w=0.3)
    for k, length in enumerate(LENGTHS, start=1):
        text += LINK.format(n=f"link{k}", x=length / 2, l=length, w=0.08)
    parent, offset = "base", 0
    for k, length in enumerate(LENGTHS, start=1):
        text += JOINT.format(k=k, p=parent, c=f"link{k}", o=offset, z=0.2 if k == 1 else 0,
                             axis=AXES[k - 1])
        parent, offset = f"link{k}", length
    return text + "</robot>\n"


def first(r):
    """What a first-contact report says: collides, the first contact, the first pairs."""
    def t(ct):
        return None if ct is None else (ct.lo, ct.hi, ct.exact)
    return (r.collides, t(r.first_contact),
            tuple((p.bodies, p.names, t(p.first_contact),
                   tuple((c.a, c.b, t(c.first_contact)) for c in p.contacts)) for p in r.first))


def world_frame(robot, q0, q1, min_distance):
    """The same bodies as one scene on their world motions, the allowed pairs skipped."""
    motions = robot.motions(q0, q1)
    names = _names(robot)
    bodies = [P.Body(s, motions[k], name=n) for n, (_, _, k, s) in zip(names, robot.shapes)]
    link_of = {n: link for n, (link, _, _, _) in zip(names, robot.shapes)}
    allowed = robot.adjacent_pairs()
    skip = [(a, b) for i, a in enumerate(names) for b in names[i + 1:]
            if link_of[a] == link_of[b] or frozenset((link_of[a], link_of[b])) in allowed]
    return P.check(bodies, skip_pairs=skip, min_distance=min_distance, time_tolerance="1e-9")


@pytest.mark.parametrize("min_distance", [None, F(1, 20)])
def test_self_pairs_equal_the_world_frame(tmp_path, min_distance):
    path = tmp_path / "folding.urdf"
    path.write_text(arm_urdf())
    robot = load_urdf(str(path))
    rng = random.Random(SEED + 33)
    collided = deep = 0
    for case in range(10):
        q0 = [rng.uniform(-2.5, 2.5) for _ in LENGTHS]
        q1 = [x + rng.uniform(-2, 2) for x in q0]
        world = world_frame(robot, q0, q1, min_distance)
        for filt in (True, False):
            got = robot.check(q0, q1, [], self_collision=True, filter=filt, min_distance=min_distance,
                              time_tolerance="1e-9")
            assert first(got.scene) == first(world), (case, q0, q1, filt)
        collided += world.collides
        # A first pair whose common ancestor moves (not base): the frame changed something.
        deep += any("base" not in p.names for p in world.first)
    assert collided >= 2 and deep >= 1, (collided, deep)
