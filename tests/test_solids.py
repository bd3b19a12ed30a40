"""Solid meshes through the Python API (docs/python.md, "Solids"): the box in a box,
refused meshes (the message names the first open or flipped edge, which the test finds
on its own), Mesh.from_trimesh's rule, robots' links, the contact reported, and the
C library's answer for a solid asked of a sphere body. The scene answers against the
independent oracle: tests/test_solid_corpus.py."""
from fractions import Fraction
from fractions import Fraction as F

import pytest

import oracle_solid
from test_body_pose import rotate
import polyccd as P
from polyccd import Body, InputError, Mesh, Motion, Spheres

TET = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TET_TRIS = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def first_bad_edge(triangles):
    """The first edge (a < b, sorted) not used exactly once in each direction: (edge,
    the least triangle using it); found here with directed-edge counts."""
    uses = {}
    for t, tri in enumerate(triangles):
        for k in range(3):
            a, b = tri[k], tri[(k + 1) % 3]
            uses.setdefault((min(a, b), max(a, b)), []).append((t, (a, b)))
    for edge in sorted(uses):
        dirs = [d for _, d in uses[edge]]
        if len(dirs) != 2 or dirs[0] == dirs[1]:
            return edge, min(t for t, _ in uses[edge])
    return None


def test_box_in_box_collides_at_zero_when_solid_only():
    small = Body(Mesh.box([1, 1, 1]), Motion.linear([0, 0, 0], [0.5, 0.25, 0]), name="small")
    solid = P.check([Body(Mesh.box([4, 4, 4], solid=True), name="big"), small])
    assert solid.collides and solid.first_contact.exact == 0
    (pair,) = solid.pairs
    (contact,) = pair.contacts
    assert contact.a == ("solid", 0) and contact.b[0] == "vertex"
    surface = P.check([Body(Mesh.box([4, 4, 4]), name="big"), small])
    assert not surface.collides and surface.first_contact is None


@pytest.mark.parametrize("tris", [
    TET_TRIS[:3],                                      # open: edges of triangle 0 with one use
    [TET_TRIS[0], TET_TRIS[1], TET_TRIS[2], [1, 3, 2]],  # the last face flipped
    [TET_TRIS[0][::-1]] + TET_TRIS[1:],                # the first face flipped
    TET_TRIS + [[0, 1, 2], [0, 2, 1]],                 # an edge of four triangles
])
def test_refused_solid_names_the_first_bad_edge(tris):
    (a, b), t = first_bad_edge(tris)
    with pytest.raises(InputError, match=r"^triangles: edge \(%d, %d\) of triangle %d " % (a, b, t)):
        Mesh(TET, tris, solid=True)
    assert not Mesh(TET, tris).solid                   # as a surface it is fine


def test_refused_solid_with_a_repeated_index():
    with pytest.raises(InputError, match=r"^triangles\[4\]: \(0, 0, 1\) repeats a vertex index"):
        Mesh(TET, TET_TRIS + [[0, 0, 1]], solid=True)


def test_solid_flag_and_bad_values():
    assert Mesh(TET, TET_TRIS, solid=True).solid
    assert Mesh(TET, [t[::-1] for t in TET_TRIS], solid=True).solid   # inward normals too
    assert "solid" in repr(Mesh.box([1, 1, 1], solid=True))
    assert Mesh.cylinder(1, 2, solid=True).solid
    with pytest.raises(InputError, match=r'^solid: expected True or False, got "yes"'):
        Mesh(TET, TET_TRIS, solid="yes")


def test_from_trimesh_solid_rule():
    trimesh = pytest.importorskip("trimesh")
    closed = trimesh.creation.box(extents=(1, 2, 3))
    assert Mesh.from_trimesh(closed).solid
    assert not Mesh.from_trimesh(closed, solid=False).solid
    opened = trimesh.Trimesh(closed.vertices, closed.faces[1:], process=False)
    assert not Mesh.from_trimesh(opened).solid
    edge, t = first_bad_edge(opened.faces.tolist())
    with pytest.raises(InputError, match=r"^triangles: edge \(%d, %d\) of triangle %d" % (*edge, t)):
        Mesh.from_trimesh(opened, solid=True)
    with pytest.raises(InputError, match=r"^solid: expected None, True or False"):
        Mesh.from_trimesh(closed, solid=1)


def test_spheres_are_solid_and_contained_balls_touch():
    ball = Spheres([[0.25, 0.5, -0.5]], [0.125])
    res = P.check([Body(ball), Body(Mesh.box([4, 4, 4], solid=True))], all_contacts=True)
    assert res.first_contact.exact == 0
    assert [(c.a, c.b) for c in res.pairs[0].contacts] == [(("sphere", 0), ("solid", 0))]


def test_c_refuses_a_solid_of_spheres():
    from polyccd._pccd import ffi, lib
    out = ffi.new("pccd_body **")
    ball = Spheres([[0, 0, 0]], [1])
    assert lib.pccd_body_new_solid(out, ball._handle) == lib.PCCD_EINVAL
    assert out[0] == ffi.NULL
    assert "a sphere body is not a mesh" in P._errors.last_error()
    solid = ffi.new("int *")
    assert lib.pccd_body_solid(ball._handle, solid) == lib.PCCD_OK and solid[0] == 1


def test_contact_geometry_of_a_solid_is_refused():
    bodies = [Body(Mesh.box([4, 4, 4], solid=True)), Body(Mesh.box([1, 1, 1]))]
    res = P.check(bodies)
    c = res.pairs[0].contacts[0]
    with pytest.raises(InputError, match="a solid .* has no contact point"):
        res.contact_geometry(0, 0)
    assert c.a == ("solid", 0)


def test_solid_pickles():
    import pickle
    m = pickle.loads(pickle.dumps(Mesh.box([2, 2, 2], solid=True)))
    assert m.solid


ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base"><collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.2 0.2"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.2" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-6" upper="6" effort="1" velocity="1"/></joint>
</robot>
"""


@pytest.mark.parametrize("use_filter", [True, False])
def test_robot_link_holding_an_obstacle(tmp_path, use_filter):
    """A ball strictly inside the upper link's box (x in [0, 1], |y| <= 0.1, z in
    [0.1, 0.3] at q = 0; turning by 0.1 about z keeps it inside): contained at t = 0."""
    pytest.importorskip("yourdfpy")
    from polyccd.robot import load_urdf
    path = tmp_path / "arm.urdf"
    path.write_text(ARM)
    robot = load_urdf(str(path))
    assert all(shape.solid for _, _, _, shape in robot.shapes)
    ball = Body(Spheres([[0.5, 0, 0.2]], [0.01]), name="ball")
    res = robot.check([0], [0.1], [ball], self_collision=False, filter=use_filter)
    assert res.collides and res.first_contact.exact == 0
    assert any("solid" in (c.a[0], c.b[0]) for p in res.scene.pairs for c in p.contacts)
    robot.shapes = [(l, i, k, Mesh(s.exact_vertices(), s.triangles)) for l, i, k, s in robot.shapes]
    assert not robot.check([0], [0.1], [ball], self_collision=False, filter=use_filter).collides


def test_oracle_winding_self_check():
    """The oracle's own test on a case known by construction: the unit tetrahedron holds
    (1/8, 1/8, 1/8), not (1, 1, 1), either orientation."""
    for tris, sign in ((TET_TRIS, 1), ([t[::-1] for t in TET_TRIS], -1)):
        v = [tuple(Fraction(x) for x in p) for p in TET]
        w = oracle_solid.winding(v, tris, (Fraction(1, 8),) * 3)
        assert abs(w) == 1 and oracle_solid.winding(v, tris, (Fraction(1),) * 3) == 0
        assert w * sign == oracle_solid.winding(v, TET_TRIS, (Fraction(1, 8),) * 3)


def test_point_in_solid_of_a_larger_mesh_against_the_oracle():
    """A solid icosphere of 320 triangles (the library's (y, z) grid has several cells)
    turned and moved at t = 0, and points (one-point meshes) at random places and at
    places whose rays are degenerate (y and z of a vertex, of an edge's midpoint): each
    touches the solid at t = 0 exactly when the oracle's winding number about it is
    nonzero (a point on the surface, which the oracle reports, is left out)."""
    import random
    trimesh = pytest.importorskip("trimesh")
    tm = trimesh.creation.icosphere(subdivisions=2, radius=3)
    pose = ((F(1, 3), F(-1, 7), F(2)), (2, 1, -1, 3))
    solid = Body(Mesh.from_trimesh(tm, solid=True), pose=pose)
    assert solid.shape.solid
    verts = [tuple(F(x) for x in v) for v in tm.vertices.tolist()]
    tris = tm.faces.tolist()
    world = [tuple(a + b for a, b in zip(rotate(pose[1], v), pose[0])) for v in verts]
    rng = random.Random(32)
    points = [tuple(F(rng.uniform(-3.5, 3.5)) for _ in range(3)) for _ in range(40)]
    for k in range(20):                  # rays through a vertex or an edge's midpoint
        a, b = verts[rng.randrange(len(verts))], verts[rng.randrange(len(verts))]
        y, z = ((a[1], a[2]) if k % 2 else ((a[1] + b[1]) / 2, (a[2] + b[2]) / 2))
        points.append((F(rng.uniform(-3.5, 3.5)), y, z))
    inside = 0
    for p in points:
        q = tuple(a + b for a, b in zip(rotate(pose[1], p), pose[0]))    # p in world
        try:
            want = oracle_solid.winding(world, tris, q) != 0
        except oracle_solid.OnSurface:
            continue
        got = P.check([solid, Body(Mesh([[str(c) for c in q]], [[0, 0, 0]]))])
        assert got.collides == want, p
        assert not want or got.first_contact.exact == 0
        inside += want
    assert 10 <= inside <= 50, inside


def test_robot_self_pair_with_a_link_inside_another(tmp_path):
    """A small box on a fixed joint inside the upper link's box: a self pair in contact at
    t = 0 when that pair is checked (allowed=() checks even adjacent links; all_contacts,
    as base and upper touch at t = 0 too), none when it is allowed (the default: adjacent
    links are not checked)."""
    pytest.importorskip("yourdfpy")
    from polyccd.robot import load_urdf
    inner = ARM.replace("</robot>", """  <link name="inner"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <joint name="fix" type="fixed"><parent link="upper"/><child link="inner"/><origin xyz="0.5 0 0"/></joint>
</robot>""")
    path = tmp_path / "arm.urdf"
    path.write_text(inner)
    robot = load_urdf(str(path))
    for use_filter in (True, False):
        res = robot.check([0], [0.1], allowed=(), filter=use_filter, all_contacts=True)
        assert res.collides and res.first_contact.exact == 0
        names = {p.names for p in res.scene.pairs if any("solid" in (c.a[0], c.b[0]) for c in p.contacts)}
        assert any("inner" in n[0] + n[1] for n in names), names
        assert not robot.check([0], [0.1], filter=use_filter).collides


def test_pictures_of_a_containment_mark_the_point_held(tmp_path):
    pytest.importorskip("matplotlib")
    from polyccd.apps import to_png
    res = P.check([Body(Mesh.box([4, 4, 4], solid=True)), Body(Mesh.box([1, 1, 1]))])
    assert list(res.feature_indices(0)["solid"]) == [0] and list(res.feature_indices(1)["vertex"]) == [0]
    assert to_png(res, tmp_path / "solid.png").stat().st_size > 0
