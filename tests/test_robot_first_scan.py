"""First-contact robot checks whose first contact comes after t = 0: the witness scan at
1/8, ..., 7/8 bounds every pair's traversal, the scan's pair is cleared first to the
finest piece and a witness after its bound tightens the window (scene/robot.cpp,
scene/instant_scan.h); where one feature pair has proven a vertex-edge or vertex-vertex
feature touching first, the feature pairs holding it skip the exclusion filters
(pred/solve.cpp, touches_known). Every answer must equal the unfiltered exact check
(filter=False runs none of the filter's code) and, in decide mode, name a witness pair
that comes within delta when checked alone (test_robot_filter.check_all_ways).

The segments are three of the issue-21 bench's UR5 segments with self-collision
(tests/bench/bench_robot.py, seed 20261124, among its six obstacles) that come within
0.05 after t = 0: the forearm near a plate's corner (7 feature pairs tied at one
vertex-edge approach), the forearm near the end effector, wrist 1 near the end effector.
"""
from fractions import Fraction as F

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from helpers import box  # noqa: E402
from test_robot_filter import arm, check_all_ways  # noqa: E402
from test_robot_fk import needs_robots  # noqa: E402

DELTA = F(1, 20)

OBSTACLES = [
    ("box0", [-0.34582872591653935, 0.4630980961578027, 0.06706020135699196],
     [-0.19501037895792991, 0.616828414836328, 0.13773005602495797]),
    ("box1", [0.3510936051925515, 0.23844118717588664, 0.14625160871723075],
     [0.4668412776139089, 0.4049258197100383, 0.2815335588553146]),
    ("box2", [-0.6479454595039089, -0.3827409358001199, 0.43559019106793195],
     [-0.46495691190557914, -0.19136537421079536, 0.581339122371184]),
    ("plate0", [-0.0677876861794136, -0.40594672789276565, 0.6528790926224848],
     [0.228729871776095, -0.19735866282494594, 0.6548790926224848]),
    ("plate1", [0.00035089210838170617, -0.4290349100933466, 0.15362039095052832],
     [0.002350892108381706, -0.23903901692968155, 0.4020424329669791]),
    ("plate2", [-0.1462870886525296, 0.43878807746300025, 0.18478776853447773],
     [-0.1442870886525296, 0.6538906653116561, 0.38561794997700194]),
]

# (q0, q1, the pair first within delta, about when)
SEGMENTS = [
    ([-1.587070036403543, -2.8992091416823773, 0.9102327448629577, -6.190821452487669,
      -4.09672999096456, 2.3769780621025856],
     [-0.6087111191175845, -2.5432053561824404, 1.8026269981165972, -6.28318530718,
      -5.022601920276531, 2.371242486523979], ("forearm_link", "plate2"), 0.1924),
    ([-5.114126662922975, 5.1285960393814864, 1.134562257098926, 2.219138603487684,
      -5.197059534844112, -2.1591394092881515],
     [-4.885348817420336, 4.331608013950769, 0.7746497624890154, 2.016078653334069,
      -4.266243684601248, -1.3545427594433568], ("forearm_link", "ee_link"), 0.5199),
    ([-4.814613917243493, 1.2186641907279938, 0.009877933546381445, -1.223387333318687,
      -1.6667977462001602, 3.064204558930589],
     [-3.9651565452230266, 0.9712932349938879, 0.8732538755978432, -0.4199035213880169,
      -1.6773457197484023, 2.097986727355077], ("wrist_1_link", "ee_link"), 0.5486),
]


def obstacles():
    return [P.Body(box(lo, hi), name=n) for n, lo, hi in OBSTACLES]


@needs_robots
@pytest.mark.parametrize("k", range(len(SEGMENTS)))
def test_first_within_delta_after_zero_equals_the_unfiltered_check(k):
    q0, q1, pair, t = SEGMENTS[k]
    robot = arm("ur5")
    assert check_all_ways(robot, q0, q1, obstacles(), True, k, min_distance=DELTA)
    got = robot.check(q0, q1, obstacles(), self_collision=True, min_distance=DELTA)
    assert got.first_contact.lo > 0 and abs(float(got.first_contact.lo) - t) < 1e-3, (k, got.first_contact)
    first = [p.names for p in got.scene.first]
    assert pair in first, (k, first)
    # The feature pairs tied at the first time each report it (none is left out by the
    # skipped filters): the forearm's edge against the plate's corner, 7 of them.
    if k == 0:
        (contacts,) = [p.contacts for p in got.scene.pairs if p.names == pair]
        assert len(contacts) == 7 and len({(c.first_contact.lo, c.first_contact.hi) for c in contacts}) == 1


@needs_robots
@pytest.mark.parametrize("k", range(len(SEGMENTS)))
def test_without_min_distance_equals_the_unfiltered_check(k):
    q0, q1, _, _ = SEGMENTS[k]
    check_all_ways(arm("ur5"), q0, q1, obstacles(), True, k)
