"""Robot checks with a minimum distance through the certified filter (issue 33): its
witnesses now serve min_distance too (a triangle pair certainly within delta at a
piece's midpoint, lib/scene/delta_witness.h). On random segments of the boxy arm of
test_robot_arm.py among posts: the filtered first contact equals the unfiltered exact
check and brute force, decide mode agrees, its free_until is no later than the first
contact, and its witness pair, checked alone as a two-body scene with the same
min_distance, is within delta."""
import random
from fractions import Fraction as F

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from helpers import box  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_arm import ARM, write  # noqa: E402
from test_robot_filter import check_all_ways  # noqa: E402

SEED = 3300


@pytest.mark.parametrize("delta", [F(1, 20), F(1, 8)])
def test_filtered_min_distance_equals_exact(tmp_path, delta):
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    rng = random.Random(SEED)
    hits = 0
    for case in range(6):
        q0 = [rng.uniform(-3, 3), rng.uniform(-3, 3)]
        q1 = [x + rng.uniform(-2, 2) for x in q0]
        c = [rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)]
        posts = [P.Body(box([c[0], c[1], 0], [c[0] + 0.1, c[1] + 0.1, 0.5]), name="post")]
        hits += check_all_ways(robot, q0, q1, posts, False, (case, q0, q1, c, delta),
                               min_distance=delta)
    assert hits >= 2
