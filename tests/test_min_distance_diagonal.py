"""Euclidean box tests of a minimum separation (enclose::boxes_within, issue 33): the
bvh phase, the driver's sub-piece bounds and the robot filter keep a pair of boxes only
when their Euclidean distance may be <= delta. Growing one box by delta on every axis,
as before, kept boxes up to sqrt(3) delta apart (a cube's corner), and a robot's near
misses solved about 3x the feature pairs. Two cubes corner to corner along the diagonal
(1, 1, 1) with a gap a on each axis, so a < delta on every axis: at a = 1/25 their
distance is sqrt(3) / 25 > delta = 1/20 (no pair is within delta, so none is solved:
several were before), at a = 1/40 it is sqrt(3) / 40 < delta (within at t = 0). The
distances are the Fractions brute force of test_min_distance_at_zero.py."""
from fractions import Fraction as F

import pytest

import polyccd as P
from helpers import box
from test_min_distance_at_zero import DELTA, LINK, mesh_distance2

GAPS = [F(1, 25), F(1, 40)]


def exact(mesh):
    return [list(map(F, v)) for v in mesh.exact_vertices()], mesh.triangles.tolist()


@pytest.mark.parametrize("gap", GAPS)
@pytest.mark.parametrize("phase", ["bvh", "auto"])
def test_cubes_corner_to_corner(gap, phase):
    a, b = box([0, 0, 0], [1, 1, 1]), box([1 + gap] * 3, [2 + gap] * 3)
    d2 = mesh_distance2(*exact(a), *exact(b))
    assert d2 == 3 * gap * gap
    want = d2 <= DELTA ** 2
    bodies = [P.Body(a, name="a"), P.Body(b, P.Motion.linear([0, 0, 0], [1, 1, 1]), name="b")]
    for first in (True, False):
        r = P.check(bodies, min_distance=DELTA, broad_phase=phase, first_contact=first)
        assert r.collides == want, (gap, phase, first)
        if want:
            assert first is False or r.first_contact.exact == 0
        else:
            assert r.stats["solved"] == 0, (gap, phase, first, r.stats)


@pytest.mark.parametrize("gap", GAPS)
def test_robot_link_corner_to_corner(tmp_path, gap):
    """The link of test_min_distance_at_zero.py standing at q = 0 (its corner at
    (1, 1/8, 3/8)) and a cube off that corner along the diagonal: the filter clears the
    pair (no exact motion, nothing solved) exactly when it is farther than delta."""
    pytest.importorskip("yourdfpy")
    from polyccd.robot import load_urdf
    path = tmp_path / "one.urdf"
    path.write_text(LINK)
    robot = load_urdf(str(path))
    corner = [1 + gap, F(1, 8) + gap, F(3, 8) + gap]
    cube = box(corner, [x + F(1, 2) for x in corner])
    (_, _, k, shape), = robot.shapes
    motion = robot.motions([0], [0])[k]
    va = [list(motion.position(list(map(F, p)), 0)) for p in shape.exact_vertices()]
    d2 = mesh_distance2(va, shape.triangles.tolist(), *exact(cube))
    assert d2 == 3 * gap * gap
    want = d2 <= DELTA ** 2
    for kw in (dict(), dict(first_contact=False), dict(filter=False)):
        r = robot.check([0], [0], [P.Body(cube, name="cube")], min_distance=DELTA,
                        self_collision=False, **kw)
        assert r.collides == want, (gap, kw)
        if not want:
            assert r.scene.stats["solved"] == 0, (gap, kw, r.scene.stats)
