"""The witness pass of a minimum separation at t = 0 (lib/scene/pair_search.cpp,
within_at_zero; Pair_ctx::within_at_zero): in decide mode and in a robot's first-contact
mode a feature pair within delta at t = 0 ends a body pair's search, decided from the
positions at t = 0 alone. Checked against an independent oracle: the exact distance of
the two meshes at t = 0 in Fractions (brute force over vertex-triangle and edge-edge
pairs; the bodies are built apart, so no triangles cross), with gaps exactly delta and
2^-40 inside and outside, on motions that only move the bodies apart afterwards (so
"within delta during [0, 1]" is "within delta at t = 0"). The reported feature pair
must itself be within delta at t = 0 by the oracle. A body on a rotation with W(0) != 1
checks the scale D(0) of the positions."""
from fractions import Fraction as F
from itertools import product

import pytest

import polyccd as P
from helpers import box
from oracle_distance import point_segment, point_triangle, segment_segment

DELTA = F(1, 20)
TINY = F(1, 2 ** 40)
GAPS = [DELTA, DELTA - TINY, DELTA + TINY, 2 * DELTA, DELTA / 2]


def edges(tris):
    return sorted({tuple(sorted((t[i], t[(i + 1) % 3]))) for t in tris for i in range(3)})


def feature_distance2(va, ta, fa, vb, tb, fb):
    """Squared distance of feature fa of mesh (va, ta) to fb of (vb, tb) (vertex-triangle,
    edge-edge or triangle-triangle, as reported)."""
    def points(v, t, f):
        kind, i = f
        return {"vertex": lambda: [v[i]], "edge": lambda: [v[k] for k in edges(t)[i]],
                "triangle": lambda: [v[k] for k in t[i]]}[kind]()
    x, y = points(va, ta, fa), points(vb, tb, fb)
    if len(x) == 1:
        return point_triangle(x[0], *y) if len(y) == 3 else point_segment(x[0], *y)
    if len(y) == 1:
        return point_triangle(y[0], *x) if len(x) == 3 else point_segment(y[0], *x)
    if len(x) == 3 and len(y) == 3:  # the filter's witness: two closed triangles
        return mesh_distance2(x, [[0, 1, 2]], y, [[0, 1, 2]])
    return segment_segment(*x, *y)


def mesh_distance2(va, ta, vb, tb):
    """Squared distance of two disjoint closed triangle meshes: brute force."""
    d = min(point_triangle(p, *[vb[k] for k in t]) for p, t in product(va, tb))
    d = min(d, min(point_triangle(p, *[va[k] for k in t]) for p, t in product(vb, ta)))
    ea, eb = edges(ta), edges(tb)
    return min(d, min(segment_segment(va[i], va[j], vb[k], vb[m]) for (i, j), (k, m) in product(ea, eb)))


TETRA = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TETRA_T = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


@pytest.mark.parametrize("gap", GAPS)
def test_scene_decide_within_delta_at_zero(gap):
    """A tetrahedron turning about z with W(0) = 1 + tau0^2 != 1 (tan of the half angle
    from 1/3 to 1/2: about 14 degrees) and a box moving 10 away along x from a gap at
    t = 0: the turning vertices move far slower than 10, so the gap only grows."""
    spin = P.Motion.axis_rotation([0, 0, 1], [0, 0, 0], F(1, 3), F(1, 2))
    tetra = P.Mesh(TETRA, TETRA_T)
    va = [list(spin.position(p, 0)) for p in TETRA]
    x = max(v[0] for v in va) + gap
    slab = box([x, -4, -4], [x + 1, 4, 4])
    vb = [list(map(F, v)) for v in slab.exact_vertices()]
    tb = slab.triangles.tolist()
    d2 = mesh_distance2(va, TETRA_T, vb, tb)
    assert d2 == gap * gap  # the oracle sees the gap built
    a = P.Body(tetra, spin, name="tetra")
    b = P.Body(slab, P.Motion.linear([0, 0, 0], [10, 0, 0]), name="slab")
    want = d2 <= DELTA ** 2
    decide = P.check([a, b], min_distance=DELTA, first_contact=False)
    first = P.check([a, b], min_distance=DELTA)
    assert decide.collides == first.collides == want, gap
    if want:
        assert first.first_contact.exact == 0
        assert decide.stats["solved"] == 1  # the witness pass: one pair, then done
        for c in decide.pairs[0].contacts:
            assert feature_distance2(va, TETRA_T, c.a, vb, tb, c.b) <= DELTA ** 2, c


# One revolute link, every number dyadic (so the URDF's doubles are the numbers meant):
# the link's box spans x in [0, 1], y in [-1/8, 1/8], z in [1/8, 3/8] at q = 0.
LINK = """<?xml version="1.0"?>
<robot name="one">
  <link name="base"/>
  <link name="arm"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.25 0.25"/></geometry></collision></link>
  <joint name="turn" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.25" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-6" upper="6" effort="1" velocity="1"/></joint>
</robot>
"""


@pytest.mark.parametrize("gap", GAPS)
def test_robot_first_contact_within_delta_at_zero(tmp_path, gap):
    """The link at q = 0 beside a post a gap away in +y, turning to q = -1 (away: every
    point of the link then has y < 1/8). First-contact mode (the witness path of
    robots), filtered and not: the contact is at t = 0 exactly when the oracle's
    distance is <= delta, and the reported feature pair is within delta at t = 0."""
    pytest.importorskip("yourdfpy")
    from polyccd.robot import load_urdf
    path = tmp_path / "one.urdf"
    path.write_text(LINK)
    robot = load_urdf(str(path))
    y = F(1, 8) + gap
    post = box([F(1, 4), y, 0], [F(1, 2), y + F(1, 4), F(1, 2)])
    vb = [list(map(F, v)) for v in post.exact_vertices()]
    tb = post.triangles.tolist()
    (_, _, k, shape), = robot.shapes
    motion = robot.motions([0], [-1])[k]
    va = [list(motion.position(list(map(F, p)), 0)) for p in shape.exact_vertices()]
    ta = shape.triangles.tolist()
    d2 = mesh_distance2(va, ta, vb, tb)
    assert d2 == gap * gap
    want = d2 <= DELTA ** 2
    obstacles = [P.Body(post, name="post")]
    for kw in (dict(), dict(filter=False), dict(first_contact=False)):
        r = robot.check([0], [-1], obstacles, min_distance=DELTA, self_collision=False, **kw)
        assert r.collides == want, (gap, kw)
        if want:  # the witness pass: the one pair within delta solved, then done (with
            # the filter, its own witness at 0 may answer first: edge to edge within
            # delta, lib/scene/delta_witness.h, nothing solved; checked below)
            solved = r.scene.stats["solved"]
            assert solved == 1 or (solved == 0 and kw.get("filter", True)), (gap, kw, r.scene.stats)
        if want and kw.get("first_contact", True):
            assert r.first_contact.exact == 0, (gap, kw)
            (pair,) = r.scene.pairs
            assert pair.contacts
            for c in pair.contacts:
                a, b = (c.a, c.b) if pair.names[0] != "post" else (c.b, c.a)
                assert feature_distance2(va, ta, a, vb, tb, b) <= DELTA ** 2, (gap, kw, c)
