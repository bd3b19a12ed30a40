"""Joint axes and coordinates of any finite size (issue 23, item 2: no NaN, no silent
degeneration). Joint axes of any size turn their link:

An axis of (1e300, 0, 0) or (1e160, 1e160, 0) was accepted, its norm overflowed, the
link never turned (joint values NaN) and a collision was reported as none; (1e-200, 0, 0)
failed with "s0: NaN is not a finite number", naming no link. lib/motion/chain.cpp now
scales such an axis exactly by a power of two. Each case is built so that the answer is
known: a ball on the link at a point p perpendicular to the axis direction u turns by
a quarter turn to u x p, where a still ball waits; it must be found, at the time of
the unit axis (same direction), and the joint values must be finite.
"""
import math
from fractions import Fraction as F

import numpy as np
import pytest

import polyccd as P

AXES = [(1e300, 0, 0), (1e160, 1e160, 0), (1e-200, 0, 0), (0, 5e-324, 0), (1e308, 1e308, 1e308),
        (-1e300, 0, 1e-300), (3.0, 4.0, 0)]


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def quarter_turn_case(axis):
    """(moving body, still body, expected end point) for a revolute joint about axis."""
    big = max(abs(x) for x in axis)
    u = unit([x / big for x in axis])  # the direction, in doubles (for building only)
    helper = [1.0, 0, 0] if abs(u[0]) < 0.9 else [0, 1.0, 0]
    p = unit(np.cross(u, helper))
    end = list(np.cross(u, p))
    chain = P.Chain()
    chain.add_link(-1, "revolute", axis)
    motion = chain.motions([0.0], [math.pi / 2])[0]
    return chain, motion, p, end


@pytest.mark.parametrize("axis", AXES)
def test_extreme_axes_turn_their_link(axis):
    chain, motion, p, end = quarter_turn_case(axis)
    moving = P.Body(P.Spheres([p], [0.125]), motion)
    still = P.Body(P.Spheres([end], [0.125]))
    r = P.check([moving, still])
    assert r.collides
    # The time is that of the same direction given at an ordinary size.
    big = max(abs(x) for x in axis)
    ref_chain, ref_motion, _, _ = quarter_turn_case([x / big * 0.75 for x in axis])
    ref = P.check([P.Body(P.Spheres([p], [0.125]), ref_motion), still])
    assert abs(float(r.first_contact.lo) - float(ref.first_contact.lo)) < 1e-9
    # Positions and joint values: finite, and where the quarter turn puts them.
    x = [float(c) for c in motion.position(p, 1)]
    assert max(abs(a - b) for a, b in zip(x, end)) < 1e-12
    values = chain.joint_values([0.0], [math.pi / 2], 1)
    assert np.isfinite(values).all() and abs(values[0] - math.pi / 2) < 1e-12


def test_prismatic_extreme_axis_moves_by_the_joint_value():
    for axis in [(1e300, 0, 0), (0, 0, 1e-200)]:
        chain = P.Chain()
        chain.add_link(-1, "prismatic", axis)
        motion = chain.motions([0.0], [2.0])[0]
        moved = [float(c) for c in motion.position([0, 0, 0], 1)]
        direction = [1.0 if a else 0.0 for a in axis]
        assert moved == pytest.approx([2 * d for d in direction], abs=1e-12)
        assert chain.joint_values([0.0], [2.0], 1)[0] == pytest.approx(2.0)


def test_zero_and_non_finite_axes_are_refused_with_their_place():
    for axis, message in [((0, 0, 0), "axis: the direction is the zero vector"),
                          ((0.0, -0.0, 0), "axis: the direction is the zero vector"),
                          ((math.inf, 0, 0), r"axis\[0\]: inf"),
                          ((0, math.nan, 0), r"axis\[1\]: NaN")]:
        with pytest.raises(P.InputError, match=message):
            P.Chain().add_link(-1, "revolute", axis)


@pytest.mark.parametrize("broad_phase", ["auto", "brute", "boxes", "bvh", "range"])
def test_bodies_beyond_the_double_range(broad_phase):
    """A triangle with corners at +-1e400 (beyond any double: its bounds are infinite,
    they were NaN) and a unit ball falling through its middle from z = 3 to z = -3:
    contact exactly at t = 1/3, in every broad phase and the index; the same ball
    falling at x = 3e400, outside the triangle, touches nothing."""
    tri = P.Body(P.Mesh([["-1e400", "-1e400", 0], ["1e400", "-1e400", 0], [0, "1e400", 0]],
                        [[0, 1, 2]]))
    for x, hit in [(0, True), ("3e400", False)]:
        ball = P.Body(P.Spheres([[x, 0, 0]], [1]), P.Motion.linear([0, 0, 3], [0, 0, -3]))
        for pair in ([tri, ball], [ball, tri]):
            r = P.check(pair, broad_phase=broad_phase)
            assert r.collides == hit
            if hit:
                assert r.first_contact.exact == F(1, 3)
        if broad_phase == "auto":
            assert P.Index(tri).query(ball).collides == hit
