"""Robot checks with a minimum distance on the UR5 (issue 33, item 4: within 3x of the
check without it). The filter now clears a link passing a few millimetres beyond delta
(the nearest-point axis of pred/closest_axis.h in its leaf test), a solid link whose box
meets an obstacle's at t = 0 keeps its bound when no containment is possible then
(scene/solid_start.h), feature pairs beside a plate are cleared by the axis filter of
pred/delta_axis.h, and a witness within delta found edge to edge
(scene/delta_witness.h) or after another pair's bound tightens the window of the
first-contact solve. Exactness is kept: every answer equals the unfiltered exact check
(filter=False, which runs none of the robot filter's code), on

  - the bench's near misses (tests/bench/bench_robot.py, seed 20261124: UR5 segments
    passing 0.053 and 0.0518 from a 2 mm plate with delta 0.05): no contact, and the
    filter clears every pair, so no feature pair is solved exactly (145 and 10 before);
  - boxes built in exact rationals at a gap of delta, delta - 1e-9 and delta + 1e-9
    ahead of a link's extreme vertex at t = 1 (a contact exactly at t = 1 or earlier,
    or a miss by 1e-9 unless the link passed within delta on the way);
  - random segments among small boxes where the links pass, both modes;
  - a solid link holding an obstacle at t = 0 (the contact is at t = 0) and one whose
    world box holds the obstacle but whose own box does not.
"""
import random
from fractions import Fraction as F

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from helpers import BOX_TRIANGLES, box  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_arm import ARM, write  # noqa: E402
from test_robot_filter import arm, gap_box, obstacles_near, same_first  # noqa: E402
from test_robot_fk import needs_robots, random_segment  # noqa: E402

DELTA = F(1, 20)
SEED = 3301

# The bench's plates (robot_fcl.make_obstacles, seed 20261124) and two of its segments.
PLATES = {"plate1": ([0.00035089210838170617, -0.4290349100933466, 0.15362039095052832],
                     [0.002350892108381706, -0.23903901692968155, 0.4020424329669791]),
          "plate2": ([-0.1462870886525296, 0.43878807746300025, 0.18478776853447773],
                     [-0.1442870886525296, 0.6538906653116561, 0.38561794997700194])}
NEAR_MISSES = [
    ("plate1",  # the upper arm 0.053 from the plate at t = 0, moving away
     [-3.7997112609632446, -3.3161472696074514, 1.720352129813441, -1.1846992287922111,
      -5.5172606073539034, 5.812650330083287],
     [-4.368737139181061, -4.2240912838303055, 1.4349199705538627, -0.18695978511809885,
      -5.650882248106517, 5.5518234532392015]),
    ("plate2",  # a wrist link 0.0518 from the plate's edge near t = 0.23
     [5.448141487813908, -3.691732209126828, 2.4846524310085236, -2.750144612749014,
      -6.014772154188284, 3.997147874627391],
     [5.818928832633029, -4.016258674393043, 2.2615549376387345, -2.4355237152978475,
      -5.528305524706118, 3.278078894851543]),
]


def check_both(robot, q0, q1, obstacles, what, **kw):
    """Filtered first contact and decide mode against the unfiltered exact check."""
    opts = dict(self_collision=False, time_tolerance="1e-9", min_distance=DELTA, **kw)
    ref = robot.check(q0, q1, obstacles, filter=False, **opts)
    first = robot.check(q0, q1, obstacles, **opts)
    same_first(first, ref, what)
    decide = robot.check(q0, q1, obstacles, first_contact=False, **opts)
    assert decide.collides == ref.collides, what
    if ref.collides:
        assert decide.free_until <= ref.first_contact.lo, what
    return ref, first, decide


@needs_robots
@pytest.mark.parametrize("plate,q0,q1", NEAR_MISSES)
def test_bench_near_misses_are_cleared_by_the_filter(plate, q0, q1):
    robot = arm("ur5")
    obstacles = [P.Body(box(*PLATES[plate]), name=plate)]
    ref, first, decide = check_both(robot, q0, q1, obstacles, plate)
    assert not ref.collides
    for r in (first, decide):  # every pair cleared before any exact motion
        assert r.scene.stats["solved"] == 0, (plate, r.scene.stats)


@needs_robots
def test_near_misses_at_delta_on_random_segments():
    robot = arm("ur5")
    rng = random.Random(SEED)
    for k in range(3):
        q0, q1 = random_segment(robot, rng)
        q1 = q0 + (q1 - q0) / 5
        for gap in (DELTA, DELTA - F(1, 10 ** 9), DELTA + F(1, 10 ** 9)):
            state = rng.getstate()
            obstacle = gap_box(robot, q0, q1, rng, gap)
            ref, _, _ = check_both(robot, q0, q1, [obstacle], (k, str(gap)))
            if gap <= DELTA:  # the extreme vertex is gap from the box's face at t = 1
                assert ref.collides and ref.first_contact.lo <= 1, (k, str(gap))
            rng.setstate(state)  # the same link and vertex for each gap
        rng.random()


@needs_robots
def test_random_segments_equal_the_unfiltered_check():
    robot = arm("ur5")
    rng = random.Random(SEED + 1)
    seen = {True: 0, False: 0}
    for k in range(4):
        q0, q1 = random_segment(robot, rng)
        q1 = q0 + (q1 - q0) / 5
        ref, _, _ = check_both(robot, q0, q1, obstacles_near(robot, q0, q1, rng, n=3), k)
        seen[ref.collides] += 1
    assert seen[True], seen


@pytest.mark.parametrize("solid", [False, True])
@pytest.mark.parametrize("delta", [None, DELTA])
def test_solid_link_and_an_obstacle_at_zero(tmp_path, solid, delta):
    """The synthetic arm's upper link (a solid 1 x 0.2 x 0.2 box, its centre at
    (0.5, 0, 0.2) turned by q[0] about z) at q[0] = pi/4: a 2 cm cube at its centre is
    inside it at t = 0 (contact at t = 0); one at (0.6, 0.1, 0.2) is inside its world
    box but 0.24 from the link, and the link turning back by 0.8 sweeps across it."""
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    q0 = [0.7853981633974483, 0.0]
    s = F(1, 100)

    def cube(c):
        lo, hi = [x - s for x in c], [x + s for x in c]
        return P.Body(P.Mesh([[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)],
                             BOX_TRIANGLES, solid=solid), name="cube")
    inside = cube([F(35355, 100000), F(35355, 100000), F(1, 5)])
    beside = cube([F(3, 5), F(1, 10), F(1, 5)])
    for q1, obstacle, hit_at_zero in (([1.0, 0.3], inside, True), ([-0.015, 0.3], beside, False),
                                      ([1.3, 0.3], beside, False)):
        for kw in (dict(), dict(first_contact=False)):
            opts = dict(self_collision=False, min_distance=delta, **kw)
            ref = robot.check(q0, q1, [obstacle], filter=False, **opts)
            got = robot.check(q0, q1, [obstacle], **opts)
            assert got.collides == ref.collides, (q1, kw)
            if kw:
                continue
            same_first(got, ref, (q1, solid, delta))
            if hit_at_zero:
                assert got.first_contact.exact == 0
            elif got.collides:
                assert got.first_contact.lo > 0
