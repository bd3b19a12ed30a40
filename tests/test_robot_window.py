"""The exact solve of first-contact mode on the window [lower, t_w] (issue 30,
lib/scene/robot.cpp): the pairs left after a witness are solved on the segment
t = lower + (t_w - lower) s, and the time tolerance is one of t there (tol / (t_w -
lower) in s). Two Panda segments of tests/bench/bench_robot.py's generator (seed
20261124, the first two that collide), each against the obstacle it hits first: the
filtered first contact equals the unfiltered exact check's (same touching features,
enclosures that overlap, width <= the tolerance), and the contact pair is decided in
interval arithmetic. Before the tolerance was scaled, the window asked for an enclosure
2^14 times tighter than tol in t, below the spacing of doubles there, and the contact pair
always went to the exact stage (with the default tolerance, stage_exact 1 on both
segments: the last check fails; 1e-6 was within reach of doubles even so).
"""
import os
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_filter import box_mesh  # noqa: E402
from test_robot_fk import ROBOTS, URDFS, needs_robots  # noqa: E402

# (q0, q1, the obstacle box's corners): the doubles bench_robot.py drew (repr-exact).
SEGMENTS = [
    ([-2.7735294297966626, 1.1214331471875059, 1.0742821741444386, -2.057914224364589,
      -0.6463803675402899, 2.4605603916954486, 1.4094397655986808, 0.02],
     [-2.8973, 0.5936519172088226, 1.621887264781361, -2.246464962704013,
      -1.5244796655267985, 3.38567242419288, 0.8404138873808646, 0.02],
     [0.00035089210838170617, -0.4290349100933466, 0.15362039095052832],
     [0.002350892108381706, -0.23903901692968155, 0.4020424329669791]),
    ([0.2884917699510412, 0.4922217138697884, 0.04411532088329251, -2.9069995441043477,
      1.848781401832563, 2.337154857663308, -0.1937390910067971, 0.02],
     [-0.044844469483993565, -0.24395876975166675, 0.9201296079869088, -2.1211582156240336,
      1.3179473316298376, 1.3847877743725892, -0.7928309071692023, 0.02],
     [0.3510936051925515, 0.23844118717588664, 0.14625160871723075],
     [0.4668412776139089, 0.4049258197100383, 0.2815335588553146]),
]


@needs_robots
@pytest.mark.parametrize("k", range(len(SEGMENTS)))
@pytest.mark.parametrize("tol", [None, "1e-6"])
def test_window_keeps_the_time_tolerance_of_t(k, tol):
    robot = load_urdf(os.path.join(ROBOTS, URDFS["panda"]))
    q0, q1, lo, hi = SEGMENTS[k]
    obstacles = [P.Body(box_mesh(lo, hi), name="box")]
    opts = dict(self_collision=False)
    if tol:
        opts["time_tolerance"] = tol
    width = F(tol) if tol else F(1, 10**12)  # the library's default time tolerance
    ref = robot.check(np.array(q0), np.array(q1), obstacles, filter=False, **opts)
    got = robot.check(np.array(q0), np.array(q1), obstacles, **opts)
    assert ref.collides and got.collides
    a, b = got.first_contact, ref.first_contact
    assert a.exact == b.exact
    assert a.lo <= b.hi and b.lo <= a.hi, (a, b)
    assert 0 <= a.hi - a.lo <= width, a
    assert sorted((c.a, c.b) for c in got.contacts) == sorted((c.a, c.b) for c in ref.contacts)
    assert got.scene.stats["stage_exact"] == 0, got.scene.stats
