"""Static bodies placed by a pose (docs/python.md, "Placing bodies"): Body(shape,
pose=...), Motion.fixed and Motion.translation with a constant vector, exact like
Motion.between. Positions are checked against the rotation of the quaternion computed
here in Fractions; a first contact against a time derived by hand (3-4-5 rotation)."""
from fractions import Fraction as F

import numpy as np
import pytest

import polyccd as P
from polyccd import Body, InputError, Mesh, Motion


def rotate(q, p):
    """R(q) p / |q|^2 for the quaternion q = (w, x, y, z), exact (any nonzero length)."""
    w, x, y, z = (F(c) for c in q)
    n = w * w + x * x + y * y + z * z
    R = [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]
    return tuple(sum(R[i][j] * F(p[j]) for j in range(3)) / n for i in range(3))


POSE = ((3, "1/2", -1), (2, 0, 0, 1))   # a turn by 2 atan(1/2) about z: cos 3/5, sin 4/5


@pytest.mark.parametrize("t", [0, "1/3", 1])
def test_body_pose_places_the_body_exactly(t):
    body = Body(Mesh.box([1, 1, 1]), pose=POSE)
    for p in ([0, 0, 0], [1, 2, 3], ["1/3", 0, "-7/2"]):
        want = tuple(a + F(b) for a, b in zip(rotate(POSE[1], p), POSE[0]))
        assert body.motion.position(p, t) == want
        assert Motion.fixed(POSE).position(p, t) == want
        assert Motion.between(POSE, POSE).position(p, t) == want


def test_body_pose_as_a_matrix():
    m = np.eye(4)
    m[:3, 3] = [3, 0.5, -1]
    body = Body(Mesh.box([1, 1, 1]), pose=m)
    assert body.motion.position([1, 1, 1], "1/2") == (4, F(3, 2), 0)


def test_pose_and_motion_together_are_refused():
    with pytest.raises(InputError, match="^pose: give a motion or a pose, not both"):
        Body(Mesh.box([1, 1, 1]), Motion.linear([0, 0, 0], [1, 0, 0]), pose=POSE)
    with pytest.raises(InputError, match=r"^pose: expected a 4x4 pose matrix"):
        Body(Mesh.box([1, 1, 1]), pose=[1, 2, 3])


def test_translation_takes_a_constant_vector():
    m = Motion.translation([0.5, 0, 0.4])
    for t in (0, "1/2", 1):
        assert m.position([0, 0, 0], t) == (F(1, 2), 0, F(0.4))
    mixed = Motion.translation([[0, 1], "1/3", F(2)])
    assert mixed.position([0, 0, 0], "1/4") == (F(1, 4), F(1, 3), 2)
    with pytest.raises(InputError, match=r"^translation\[1\]\[0\]"):
        Motion.translation([0, "abc", 0])


def test_first_contact_with_a_turned_static_box():
    """A point from x = -5 to 5 on the x axis meets the unit cube at (3, 0, 0) turned by
    (cos, sin) = (3/5, 4/5): the face of normal (-4/5, 3/5, 0) at distance 1/2 meets the
    axis at x = 3 - (1/2) / (4/5) = 19/8 (inside the face: its tangent offset is -3/8),
    reached at t = (19/8 + 5) / 10 = 59/80."""
    point = Body(Mesh([[0, 0, 0]], [[0, 0, 0]]), Motion.linear([-5, 0, 0], [5, 0, 0]))
    for solid in (False, True):
        wall = Body(Mesh.box([1, 1, 1], solid=solid), pose=((3, 0, 0), (2, 0, 0, 1)))
        res = P.check([point, wall])
        assert res.first_contact.exact == F(59, 80)
