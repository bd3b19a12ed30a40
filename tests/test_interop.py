"""numpy / trimesh / gemmi interop (docs/python.md, "Interop"), with exactness
checked against what the C library reports back: a float64 given is the rational used.

The round trips read coordinates back through exact contact times: a body at an
unknown height h is approached by a ball of radius 1/2 (or a plate) on an exact linear
motion, so the first contact time t is a rational the library reports exactly, and h
follows from t by exact Fraction arithmetic here (e.g. 3/2 - 4t). A library that rounded
h anywhere (to a double, to a float32, to a decimal) would report another t.
"""
import pickle
import random
from fractions import Fraction

import numpy as np
import pytest

import polyccd
from polyccd import Body, Index, Mesh, Motion, Spheres
import polyccd.apps
from polyccd.apps import spheres_from_gemmi

SEED = 20261124
FALL = Body(Spheres([[0, 0, 2]], ["1/2"]), Motion.linear([0, 0, 0], [0, 0, -4]), name="ball")


def plate(z, dtype=None):
    """A large triangle at height z (all three vertices), as an array of dtype."""
    v = np.array([[-10, -10, z], [10, -10, z], [0, 10, z]], dtype=dtype)
    return Mesh(v, np.array([[0, 1, 2]]))


def plate_height(mesh):
    """The height of a horizontal plate, read back from the exact first contact of a
    ball of radius 1/2 falling from z = 2 to z = -2: z_ball(t) = 2 - 4t = h + 1/2."""
    r = Index(Body(mesh, name="plate")).query(FALL)
    assert r.collides and r.first_contact.exact is not None
    return Fraction(3, 2) - 4 * r.first_contact.exact


def test_float64_vertices_are_their_binary_values():
    rng = random.Random(SEED)
    for case in range(20):
        z = rng.uniform(-1, 1) * 2.0 ** rng.randint(-40, 0)
        assert plate_height(plate(z, np.float64)) == Fraction(z), (case, z.hex())
    z32 = np.float32(0.1)  # float32: its own binary value, not 0.1 and not a float64 of 0.1
    assert plate_height(plate(z32, np.float32)) == Fraction(float(z32))


def test_integer_and_fraction_arrays_are_exact():
    assert plate_height(plate(1, np.int64)) == 1
    third = Fraction(1, 3)  # no double: the object array goes as exact texts
    assert plate_height(plate(third, object)) == third
    # An integer beyond 2^53 is no double: 2^60 + 1 must not become 2^60.
    big = 2 ** 60 + 1
    mesh = plate(big, np.int64)
    ball = Body(Spheres([[0, 0, big + 2]], ["1/2"]), Motion.linear([0, 0, 0], [0, 0, -4]))
    r = Index(Body(mesh)).query(ball)
    assert r.first_contact.exact == Fraction(3, 8)  # 2 - 4t = 1/2
    assert mesh.exact_vertices()[0, 2] == big and not mesh.exact_doubles


def test_float64_spheres_are_their_binary_values():
    rng = random.Random(SEED + 1)
    for case in range(10):
        c = np.array([[rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)]])
        r = np.array([rng.uniform(0.1, 1)])
        balls = Index(Body(Spheres(c, r), name="balls"))
        flat = Mesh([[-10, -10, 0], [10, -10, 0], [0, 10, 0]], [[0, 1, 2]])
        # A plate falling from z = 5 to -5 meets the top z + r, one rising meets z - r.
        top = balls.query(Body(flat, Motion.linear([0, 0, 5], [0, 0, -5])))
        bottom = balls.query(Body(flat, Motion.linear([0, 0, -5], [0, 0, 5])))
        z_plus_r = 5 - 10 * top.first_contact.exact
        z_minus_r = -5 + 10 * bottom.first_contact.exact
        assert (z_plus_r + z_minus_r) / 2 == Fraction(c[0, 2]), case
        assert (z_plus_r - z_minus_r) / 2 == Fraction(r[0]), case


def test_motion_positions_read_back_the_floats():
    rng = np.random.default_rng(SEED)
    p0, p1 = rng.normal(size=3), rng.normal(size=3)
    m = Motion.linear(p0, p1)
    assert m.position([0, 0, 0], 0) == tuple(Fraction(x) for x in p0)
    assert m.position(np.zeros(3, dtype=np.int64), 1) == tuple(Fraction(x) for x in p1)
    ctrl = rng.normal(size=(4, 3))
    assert Motion.bezier(ctrl).position([0, 0, 0], 1) == tuple(Fraction(x) for x in ctrl[3])


def test_solve_takes_coefficient_arrays():
    points = [[[Fraction(1, 4), 0], [Fraction(1, 4), 0], [1, -2]], [[0], [0], [0]],
              [[1], [0], [0]], [[0], [1], [0]]]
    want = polyccd.solve("vertex-face", points)
    as_array = np.empty((4, 3), dtype=object)
    for i in range(4):
        for a in range(3):
            as_array[i, a] = np.array(points[i][a], dtype=object)
    assert polyccd.solve("vertex-face", as_array) == want
    assert want.first_contact.exact == Fraction(1, 2)


def test_solve_linear_exact_path_matches_the_double_path():
    rng = np.random.default_rng(SEED + 2)
    for case in range(30):
        t0 = rng.integers(-4, 5, size=(4, 3)) / 4.0
        t1 = rng.integers(-4, 5, size=(4, 3)) / 4.0
        want = polyccd.solve_linear("edge-edge", t0, t1)
        as_fractions = np.vectorize(Fraction, otypes=[object])
        assert polyccd.solve_linear("edge-edge", as_fractions(t0), as_fractions(t1)) == want
        assert polyccd.solve_linear("edge-edge", (4 * t0).astype(np.int64) / 4,
                                    t1.astype(np.float32)) == want
        assert polyccd.collides_linear("edge-edge", as_fractions(t0), t1) == want.collides
    # Not doubles: a third. The vertex falls from z = 1 to z = -1/3 + ... : exact path.
    t0 = np.array([[Fraction(1, 3), Fraction(1, 3), 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]],
                  dtype=object)
    t1 = t0.copy()
    t1[0, 2] = Fraction(-1, 2)
    assert polyccd.solve_linear("vertex-face", t0, t1).first_contact.exact == Fraction(2, 3)
    with pytest.raises(polyccd.InputError, match=r"t0\[0\]\[0\]\[0\]: 1/3 is not exactly"):
        polyccd.solve_linear_many("vertex-face", t0[None], t1[None])


def test_pickles_rebuild_the_same_bodies_and_motions():
    motions = [Motion(translation=[[0, 1], ["1/3"], [0.1, 0, 2]], rotation=[[1], [0], [0], [0, 1]]),
               Motion.linear([0, 0, 0], [1.5, 0, 0]), Motion.bezier(np.eye(4, 3)),
               Motion.hermite([0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]),
               Motion.axis_rotation([0, 0, 1], [1, 0, 0], 0, "1/2"),
               Motion.screw([0, 0, 1], [1, 0, 0], 0, "1/2", 3).compose([1, 2, 0, 0], [0, 1, 0])]
    for m in motions:
        again = pickle.loads(pickle.dumps(m))
        for t in (0, Fraction(1, 3), 1):
            assert again.position([1, 2, 3], t) == m.position([1, 2, 3], t)
    cube = Mesh(np.array([[x, y, z] for x in (0, 1.5) for y in (0, 1) for z in (0, 1)]),
                [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                 [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    ball = Spheres([["7/2", "1/2", "1/2"]], [Fraction(1, 2)])
    bodies = [Body(cube, name="cube"), Body(ball, Motion.linear([0, 0, 0], [-3, 0, 0]), name="ball")]
    want = polyccd.check(bodies)
    again = pickle.loads(pickle.dumps(bodies))
    # The ball's left side x = 3 - 3t meets the face x = 3/2 at t = 1/2.
    assert polyccd.check(again) == want and want.first_contact.exact == Fraction(1, 2)
    assert again[0].shape.exact_vertices().tolist() == cube.exact_vertices().tolist()
    ix = Index(bodies[0])
    assert pickle.loads(pickle.dumps(ix)).query(again[1]) == ix.query(bodies[1])
    assert pickle.loads(pickle.dumps(want)) == want  # results travel without their bodies


def test_results_as_arrays():
    plate_ = Mesh([[-4, -4, 0], [4, -4, 0], [-4, 4, 0], [4, 4, 0]], [[0, 1, 3], [0, 3, 2]])
    tri = Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    queries = [Body(tri, Motion.linear([k, 0, 1 + k], [k, 0, 1 - k])) for k in range(4)]
    results = Index(Body(plate_)).query_many(queries)
    a = polyccd.answers(results)
    assert a.collides.tolist() == [r.collides for r in results] == [False, True, True, True]
    assert np.isnan(a.approx[0]) and a.lo[0] is None
    assert a.lo[1:].tolist() == [Fraction(1 + k, 2 * k) for k in (1, 2, 3)] == a.hi[1:].tolist()
    r = results[1]
    touching = {("a", c.a) for p in r.first for c in p.contacts} | \
               {("b", c.b) for p in r.first for c in p.contacts}
    for body, side in ((0, "a"), (1, "b")):
        got = r.feature_indices(body)
        want = {}
        for s, (kind, k) in touching:
            if s == side:
                want.setdefault(kind, set()).add(k)
        assert {k: v.tolist() for k, v in got.items()} == {k: sorted(v) for k, v in want.items()}
        assert all(v.dtype == np.int64 for v in got.values())
    assert {k: v.tolist() for k, v in r.feature_indices("body1").items()} == \
        {k: v.tolist() for k, v in r.feature_indices(1).items()}


trimesh = pytest.importorskip("trimesh")


def test_from_trimesh_is_exact_and_the_contact_comes_back():
    rng = np.random.default_rng(SEED + 3)
    box = trimesh.creation.box(extents=rng.uniform(0.5, 1, size=3))
    box.apply_translation(rng.uniform(-0.4, 0.4, size=3))  # top in (-1, 1), see plate_height
    mesh = Mesh.from_trimesh(box)
    assert mesh.exact_vertices().tolist() == [[Fraction(x) for x in v] for v in box.vertices]
    z = float(box.vertices[:, 2].max())
    assert plate_height(Mesh.from_trimesh(trimesh.Trimesh(
        [[-10, -10, z], [10, -10, z], [0, 10, z]], [[0, 1, 2]], process=False))) == Fraction(z)
    with pytest.raises(polyccd.InputError, match="to_geometry"):
        Mesh.from_trimesh(trimesh.Scene([box]))
    # The contact back: a ball falling onto the box's top face.
    top = box.vertices[:, 2].max()
    cx, cy = box.vertices[:, :2].mean(axis=0)
    ball = Body(Spheres([[cx, cy, top + 1]], [0.25]), Motion.linear([0, 0, 0], [0, 0, -1]),
                name="ball")
    r = polyccd.check([Body(mesh, name="box"), ball])
    scene = polyccd.apps.to_trimesh(r)
    red = np.all(scene.geometry["box"].visual.face_colors[:, :3] == (0xe8, 0, 0x1c), axis=1)
    assert np.nonzero(red)[0].tolist() == r.feature_indices("box").get("triangle", []).tolist()
    balls = scene.geometry["ball"].visual.face_colors[:, :3]
    assert np.all(balls == (0xe8, 0, 0x1c))  # the only ball touches
    # The centre falls at speed 1 from the double top + 1 (rounded: its own binary value).
    assert r.first_contact.exact == Fraction(top + 1) - Fraction(top) - Fraction(1, 4)


def test_to_png_writes_a_picture(tmp_path):
    pytest.importorskip("matplotlib")
    tri = Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    r = polyccd.check([Body(tri, name="a"), Body(Spheres([[0.25, 0.25, 1]], [0.5]),
                                                 Motion.linear([0, 0, 0], [0, 0, -1]))])
    path = polyccd.apps.to_png(r, tmp_path / "c.png", size=(400, 200))
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(polyccd.InputError, match="does not hold its bodies"):
        polyccd.apps.to_png(pickle.loads(pickle.dumps(r)), tmp_path / "d.png")


PDB = """\
HETATM    1  C1  LIG A   1      14.264  35.079  18.209  1.00 20.00           C
HETATM    2  O1  LIG A   1      -1.250   0.001   7.125  1.00 20.00           O
HETATM    3  N1  LIG A   1       0.100   0.200   0.300  1.00 20.00           N
END
"""


def test_spheres_from_gemmi_path_is_the_files_decimals_and_structures_their_doubles(tmp_path):
    gemmi = pytest.importorskip("gemmi")
    path = tmp_path / "lig.pdb"
    path.write_text(PDB)
    want = [[Fraction(line[30 + 8 * a:38 + 8 * a].strip()) for a in range(3)]
            for line in PDB.splitlines() if line.startswith("HETATM")]
    radii = [Fraction("1.70"), Fraction("1.52"), Fraction("1.55")]  # Bondi C, O, N
    balls = spheres_from_gemmi(path)
    assert balls.exact_centers().tolist() == want
    assert balls.exact_radii().tolist() == radii
    assert [balls.info.label(k) for k in range(3)] == ["A:LIG1 C1", "A:LIG1 O1", "A:LIG1 N1"]
    # The library's view: a plate falling from z = 30 to z = -30 first meets the top of
    # the highest ball, at 30 - 60 t = max(z + r).
    flat = Mesh([[-99, -99, 0], [99, -99, 0], [0, 99, 0]], [[0, 1, 2]])
    r = Index(Body(balls)).query(Body(flat, Motion.linear([0, 0, 30], [0, 0, -30])))
    assert 30 - 60 * r.first_contact.exact == max(c[2] + q for c, q in zip(want, radii))
    structure = gemmi.read_structure(str(path))
    in_memory = spheres_from_gemmi(structure)
    assert in_memory.exact_centers().tolist() == [
        [Fraction(a.pos.x), Fraction(a.pos.y), Fraction(a.pos.z)]
        for a in structure[0][0][0]]
    assert spheres_from_gemmi(structure[0]).exact_centers().tolist() == \
        in_memory.exact_centers().tolist()
    cif = tmp_path / "lig.cif"
    structure.make_mmcif_document().write_file(str(cif))
    assert spheres_from_gemmi(cif).exact_centers().tolist() == want
