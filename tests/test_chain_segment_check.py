"""The segment check of every robot check (motion::Chain::check_segment) accepts a
revolute joint whose double difference |q1 - q0| is at most 3 without exact arithmetic
(lib/motion/chain.cpp gives the proof). It must accept exactly what the exact rules of
the link motions accept: on such segments, extreme values included, the filtered check
(which runs check_segment alone) and the exact link motions (Robot.motions, which apply
the exact rules) both succeed; beyond it (a turn of 2 pi or more, non-finite values) both
refuse with the same message."""
import math

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from test_robot_filter import arm  # noqa: E402
from test_robot_fk import needs_robots  # noqa: E402

EDGES = [0.0, 3.0, -3.0, math.pi - 0.1, 1e300, -1e300, 5e-324, 2.0 ** 60, math.nextafter(3.0, 0)]


@needs_robots
def test_fast_accept_is_what_the_exact_rules_accept():
    robot = arm("ur5")
    n = len(robot.joints)
    for a in EDGES:
        for d in (0.0, 3.0, -3.0, 1.0, 1e-300):
            q0 = np.full(n, a)
            q1 = q0 + d
            if not abs(q1[0] - q0[0]) <= 3.0:
                continue
            robot.motions(q0, q1)  # the exact rules accept
            robot.check(q0, q1, [], first_contact=False, joint_limits="ignore")


@needs_robots
@pytest.mark.parametrize("q1", [7.0, math.inf, math.nan])
def test_refusals_match(q1):
    robot = arm("ur5")
    n = len(robot.joints)
    q0, q = np.zeros(n), np.zeros(n)
    q[2] = q1
    with pytest.raises(P.InputError) as exact:
        robot.motions(q0, q)
    with pytest.raises(P.InputError) as filtered:
        robot.check(q0, q, [], joint_limits="ignore")
    assert str(filtered.value) == str(exact.value)
