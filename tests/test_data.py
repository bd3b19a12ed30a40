"""Example data (polyccd.apps._data: libcgal-demo files, mesh and molecule loaders), the scene
renderer (polyccd.apps._render) and the demo scenes (polyccd.apps._demo_scenes).

The CGAL files come from Debian's libcgal-demo package, installed with apt-get when it
is missing and the tests run as root, and extracted into $POLYCCD_DATA_DIR (default
build/data). The float checks of the demo scenes (python-fcl, numpy
distances) only check how the scenes were built; they decide no contact.
"""
import os
import struct
import time
from fractions import Fraction

import numpy as np
import pytest

import polyccd
from polyccd import Motion
from polyccd.apps import _data, _demo_scenes, _render

trimesh = pytest.importorskip("trimesh")
gemmi = pytest.importorskip("gemmi")
pytest.importorskip("matplotlib")


def _cgal(name):
    """A libcgal-demo file (installing the package when missing and root)."""
    try:
        return _data.cgal_data_file(name, install=True)
    except polyccd.InputError as e:
        if "apt-get install libcgal-demo" in str(e) and os.geteuid() != 0:
            pytest.skip(f"libcgal-demo is not installed and this is not root: {e}")
        raise


@pytest.fixture(scope="module")
def pdb_path():
    return _cgal("1t7i.pdb")


@pytest.fixture(scope="module")
def pinion_path():
    return _cgal("pinion.off")


def _png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR"
    return struct.unpack(">II", head[16:24])


# ------------------------------------------------------------------ cgal_data_file ---

def test_cgal_data_file_extracts_once_into_the_cache(pinion_path, monkeypatch, tmp_path):
    assert pinion_path.is_file() and pinion_path.parent == _data.data_dir() / "cgal"
    assert pinion_path.read_text().startswith("OFF")
    monkeypatch.setenv("POLYCCD_DATA_DIR", str(tmp_path))
    first = _data.cgal_data_file("pinion.off")
    assert first == tmp_path / "cgal" / "pinion.off"
    assert first.read_bytes() == pinion_path.read_bytes()
    stamp = first.stat().st_mtime_ns
    monkeypatch.setattr(_data, "CGAL_DEMO_DIRS", ("/nonexistent",))  # no tarball needed
    assert _data.cgal_data_file("pinion.off") == first and first.stat().st_mtime_ns == stamp
    assert not [p for p in (tmp_path / "cgal").iterdir() if p.name.startswith(".part-")]


def test_cgal_data_file_by_path_suffix_and_in_examples(pdb_path, monkeypatch, tmp_path):
    monkeypatch.setenv("POLYCCD_DATA_DIR", str(tmp_path))
    p = _data.cgal_data_file("meshes/rotor.off")
    assert p.read_text().startswith("OFF")
    assert _data.cgal_data_file("1t7i.pdb").read_bytes() == pdb_path.read_bytes()


def test_cgal_data_file_errors(pinion_path, monkeypatch, tmp_path):
    monkeypatch.setenv("POLYCCD_DATA_DIR", str(tmp_path))
    with pytest.raises(polyccd.InputError, match="no-such-mesh.off: no such file"):
        _data.cgal_data_file("no-such-mesh.off")
    for bad in ("", "/etc/passwd", "../x.off", 3):
        with pytest.raises(polyccd.InputError):
            _data.cgal_data_file(bad)
    monkeypatch.setattr(_data, "CGAL_DEMO_DIRS", (str(tmp_path / "absent"),))
    with pytest.raises(polyccd.InputError) as e:
        _data.cgal_data_file("pinion.off")
    assert "pinion.off" in str(e.value) and "apt-get install libcgal-demo" in str(e.value)
    assert "data.tar.gz" in str(e.value)


# ----------------------------------------------------------------------- load_mesh ---

@pytest.mark.parametrize("name", ["pinion.off", "rotor.off", "fandisk.off"])
def test_load_mesh_keeps_the_file_as_trimesh_reads_it(name):
    path = _cgal(name)
    mesh = _data.load_mesh(path)
    ref = trimesh.load(str(path), process=False)
    assert isinstance(mesh, polyccd.Mesh)
    assert mesh.n_vertices == len(ref.vertices) and mesh.n_triangles == len(ref.faces)
    assert np.array_equal(mesh.vertices, ref.vertices)
    assert np.array_equal(mesh.triangles, ref.faces)
    # the header of the OFF file says the same
    counts = [line for line in path.read_text().splitlines()[1:4]
              if line.strip() and not line.startswith("#")][0].split()
    assert (mesh.n_vertices, mesh.n_triangles) == (int(counts[0]), int(counts[1]))
    assert mesh.n_edges == len(_render._edges_of(mesh.triangles))
    assert np.array_equal(mesh.edges, _render._edges_of(mesh.triangles))


def test_load_mesh_center_and_scale(pinion_path):
    raw = _data.load_mesh(pinion_path)
    mesh = _data.load_mesh(pinion_path, center=True, scale=2)
    lo, hi = raw.vertices.min(axis=0), raw.vertices.max(axis=0)
    assert np.array_equal(mesh.vertices, (raw.vertices - (lo + hi) / 2) * 2.0)
    assert np.allclose(mesh.vertices.min(axis=0) + mesh.vertices.max(axis=0), 0, atol=1e-12)
    assert not mesh.vertices.flags.writeable


@pytest.mark.parametrize("suffix", ["stl", "ply", "obj"])
def test_load_mesh_formats(tmp_path, suffix):
    box = trimesh.creation.box(extents=(1, 2, 3))
    path = tmp_path / f"box.{suffix}"
    box.export(str(path))
    mesh = _data.load_mesh(path)
    ref = trimesh.load(str(path), process=False)
    assert mesh.n_triangles == 12 == len(ref.faces)
    assert mesh.n_vertices == len(ref.vertices)
    assert np.allclose(np.sort(np.abs(mesh.vertices).max(axis=0)), [0.5, 1, 1.5])


def test_load_mesh_scene_is_concatenated():
    a, b = trimesh.creation.box(), trimesh.creation.icosahedron()
    scene = trimesh.Scene()
    scene.add_geometry(a, node_name="a", geom_name="a")
    shift = np.eye(4)
    shift[:3, 3] = (5, 0, 0)
    scene.add_geometry(b, node_name="b", geom_name="b", transform=shift)
    vertices, faces = _data._trimesh_arrays(scene, "scene")
    assert len(vertices) == len(a.vertices) + len(b.vertices)
    assert len(faces) == len(a.faces) + len(b.faces)
    assert faces.max() == len(vertices) - 1
    assert np.isclose(vertices[:, 0].max(), 5 + b.vertices[:, 0].max())
    assert isinstance(_data.LoadedMesh(vertices, faces), polyccd.Mesh)


def test_load_mesh_errors(tmp_path):
    with pytest.raises(polyccd.InputError, match="no such file"):
        _data.load_mesh(tmp_path / "absent.off")
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")
    with pytest.raises(polyccd.InputError):
        _data.load_mesh(bad)


# ------------------------------------------------------------------------ load_pdb ---

def _pdb_lines(path):
    return [line for line in open(path) if line.startswith(("ATOM  ", "HETATM"))]


def test_load_pdb_ligand_is_exact(pdb_path):
    balls, info = _data.load_pdb(pdb_path, "017")
    lines = [line for line in _pdb_lines(pdb_path) if line[17:20] == "017"]
    assert isinstance(balls, polyccd.Spheres) and balls.n_spheres == len(info) == 38 == len(lines)
    # HETATM 1646  N1  017   200      14.264  35.079  18.209  ...  N
    assert info.atom_names[0] == "N1" and info.serials[0] == 1646
    assert info.coordinates[0] == (Fraction("14.264"), Fraction("35.079"), Fraction("18.209"))
    for k, line in enumerate(lines):  # every coordinate is the file's decimal text exactly
        assert info.coordinates[k] == tuple(Fraction(line[c:c + 8]) for c in (30, 38, 46))
        assert info.atom_names[k] == line[12:16].strip()
    assert info.coordinates[0][0] != Fraction(14.264)  # not the nearest double
    assert info.label(0) == "017-200 N1"
    assert balls.centers.dtype == np.float64 and balls.centers[0, 0] == 14.264


def test_load_pdb_radii_per_element(pdb_path):
    balls, info = _data.load_pdb(pdb_path)
    expected = {"C": 1.70, "N": 1.55, "O": 1.52, "S": 1.80, "P": 1.80}
    assert set(info.elements) == set(expected)
    for element, radius in zip(info.elements, balls.radii):
        assert radius == expected[element]
    assert _data.vdw_radius("C") == Fraction(17, 10)
    assert _data.vdw_radius("H") == Fraction(6, 5)
    assert _data.vdw_radius("CL") == Fraction("1.75")
    assert _data.vdw_radius("F") == Fraction("1.47")
    zn = gemmi.Element("Zn").vdw_r
    assert _data.vdw_radius("Zn") == Fraction(f"{zn:.2f}") and abs(float(Fraction(f"{zn:.2f}")) - zn) < 1e-6
    half, _ = _data.load_pdb(pdb_path, "017", radius_scale="1/2")
    full, _ = _data.load_pdb(pdb_path, "017")
    assert np.array_equal(half.radii * 2, full.radii)


def test_load_pdb_selections(pdb_path):
    lines = _pdb_lines(pdb_path)
    protein, pinfo = _data.load_pdb(pdb_path, "protein")
    # polymer atoms of the first alternative location (blank or A): 1369 + 123
    expected = [line for line in lines if line.startswith("ATOM") and line[16] in " A"]
    assert protein.n_spheres == len(expected) == 1492
    assert set(pinfo.chains) == {"A", "B"} and "017" not in pinfo.residue_names
    assert pinfo.label(0) == "A:PRO1 N"
    everything, info = _data.load_pdb(pdb_path)
    assert "HOH" not in info.residue_names
    assert {"017", "PO4", "ACT"} <= set(info.residue_names)
    wet, winfo = _data.load_pdb(pdb_path, waters=True)
    assert winfo.residue_names.count("HOH") == sum(line[17:20] == "HOH" for line in lines)
    both, binfo = _data.load_pdb(pdb_path, "protein", altloc=None)
    assert both.n_spheres == sum(line.startswith("ATOM") for line in lines) == 1615
    asp, ainfo = _data.load_pdb(pdb_path, lambda r: r.name == "ASP" and r.seqid.num == 25)
    assert set(ainfo.residue_names) == {"ASP"} and set(ainfo.chains) == {"A", "B"}
    two, tinfo = _data.load_pdb(pdb_path, ["017", "ACT"])
    assert set(tinfo.residue_names) == {"017", "ACT"}
    with pytest.raises(polyccd.InputError, match="no atom selected"):
        _data.load_pdb(pdb_path, "XYZ")
    with pytest.raises(polyccd.InputError, match="radius_scale"):
        _data.load_pdb(pdb_path, "017", radius_scale=0)
    with pytest.raises(polyccd.InputError, match="no such file"):
        _data.load_pdb(pdb_path.parent / "absent.pdb")


# -------------------------------------------------------------------------- render ---

def test_float_pose_matches_motion_position():
    m = _demo_scenes._turning_bezier([[0, 0, 0], [1, 2, 0], [2, 0, 1], [3, 1, 1]],
                                     (1, 2, 2), 0, "0.4", pivot=("1/3", 0, 2))
    for t in (0, Fraction(1, 3), 0.75, 1):
        R, o = _render._float_pose(m, t)
        assert np.allclose(R @ R.T, np.eye(3), atol=1e-14) and np.isclose(np.linalg.det(R), 1)
        for p in ([1, 2, 3], [-0.5, 0.25, 4]):
            exact = np.array([float(x) for x in m.position(p, Fraction(t))])
            assert np.allclose(R @ np.array(p, dtype=float) + o, exact, atol=1e-12)
    R, o = _render._float_pose(None, 0.5)
    assert np.array_equal(R, np.eye(3)) and not o.any()


def test_contacts_are_normalised():
    assert _render._contacts(None, 2) == []
    assert _render._contacts([(1, ("edge", 3)), (0, ("triangle", 2))], 2) == [
        (0, "triangle", 2), (1, "edge", 3)]
    with pytest.raises(polyccd.InputError):
        _render._contacts([(2, ("edge", 3))], 2)
    with pytest.raises(polyccd.InputError):
        _render._contacts([(0, ("face", 3))], 2)


def test_render_scene_writes_a_png(tmp_path, pinion_path):
    mesh = _data.load_mesh(pinion_path, center=True)
    bodies = [(mesh, None, "a"), (mesh, Motion.linear([1.2, 0, 0], [1.6, 0, 0]), "b")]
    edges = mesh.edges
    out = _render.render_scene(bodies, Fraction(1, 2), [(0, ("triangle", 5)),
                                                        (1, ("edge", len(edges) - 1)),
                                                        (1, ("vertex", 7))],
                               tmp_path / "pair.png", title="two pinions")
    assert out.stat().st_size > 20000 and _png_size(out) == (1600, 800)
    single = _render.render_scene(bodies, 0, [], tmp_path / "one.png", size=(800, 600))
    assert single.stat().st_size > 10000 and _png_size(single) == (800, 600)


def test_render_scene_molecule_and_big_mesh(tmp_path, pdb_path):
    protein, pinfo = _data.load_pdb(pdb_path, "protein")
    ligand, linfo = _data.load_pdb(pdb_path, "017")
    out = _render.render_scene([(protein, None, "protease"), (ligand, None, "ligand")], 0,
                               [(0, ("sphere", 10)), (1, ("sphere", 3))],
                               tmp_path / "mol.png", labels={0: pinfo, 1: linfo})
    assert out.stat().st_size > 20000 and _png_size(out) == (1600, 800)
    big = _data.load_mesh(_cgal("refined_elephant.off"))
    assert big.n_triangles > 80000
    start = time.perf_counter()
    out = _render.render_scene([(big, None, "elephant"),
                                (big, Motion.linear([1, 0, 0], [1, 0, 0]), "copy")], 1,
                               [(0, ("triangle", 0)), (1, ("vertex", 9))],
                               tmp_path / "big.png")
    assert time.perf_counter() - start < 20  # a few seconds on 2 cores
    assert _png_size(out) == (1600, 800)


def test_render_scene_needs_float_geometry(tmp_path):
    plain = polyccd.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(polyccd.InputError, match="no float geometry"):
        _render.render_scene([(object(), None)], 0, [], tmp_path / "x.png")
    # Every Mesh / Spheres gives its float arrays (Mesh.vertices, ...); geometry= overrides.
    assert _png_size(_render.render_scene([(plain, None)], 0, [], tmp_path / "p.png")) == \
        (1600, 800)
    geometry = {0: {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]}}
    out = _render.render_scene([(plain, None)], 0, [(0, ("triangle", 0))], tmp_path / "x.png",
                               geometry=geometry)
    assert _png_size(out) == (1600, 800)


# ---------------------------------------------------------------------- demo scenes ---

def _fcl_state(mesh, motion_a, motion_b, t):
    """(overlap, distance) of two copies of mesh at their float poses at t, by python-fcl
    directly (trimesh's collision manager would also need scipy)."""
    import fcl
    model = fcl.BVHModel()
    model.beginModel(len(mesh.triangles), len(mesh.vertices))
    model.addSubModel(np.asarray(mesh.vertices, float), np.asarray(mesh.triangles, np.int32))
    model.endModel()
    objects = [fcl.CollisionObject(model, fcl.Transform(*_render._float_pose(m, t)))
               for m in (motion_a, motion_b)]
    hit = fcl.collide(*objects, fcl.CollisionRequest(), fcl.CollisionResult()) > 0
    distance = fcl.distance(*objects, fcl.DistanceRequest(), fcl.DistanceResult())
    return hit, distance


def test_mechanical_scene_apart_at_0_overlapping_at_1():
    pytest.importorskip("fcl")
    bodies, description = _demo_scenes.mechanical_scene()
    assert "pinion" in description and len(bodies) == 2
    for body in bodies:
        body.motion.validate()
    a, b = bodies
    mesh = a.shape
    assert trimesh.Trimesh(mesh.vertices, mesh.triangles, process=False).is_watertight

    def state(t):
        return _fcl_state(mesh, a.motion, b.motion, t)

    hit0, d0 = state(0)
    assert not hit0 and d0 > 1.0  # clearly apart
    hit1, _ = state(1)
    assert hit1
    # overlapping solids: pinion B's centre is inside pinion A's gear body (root radius
    # 0.57 about z) at t = 1, not just touching
    centre = _render._float_pose(b.motion, 1)[1]
    assert np.hypot(*centre[:2]) < 2 * _demo_scenes.PINION_ROOT - 0.05
    # the axes are z: the pose turns the pinion's measured axis to z
    R, _ = _render._float_pose(a.motion, 0)
    axis = np.array([-0.82774185, -0.31405044, 0.46499005])
    assert np.allclose(R @ axis, [0, 0, 1], atol=1e-3)


def _ball_gap(scene_bodies, t):
    """The least float gap |c_i - c_j| - r_i - r_j between the two bodies' balls."""
    (p, pm), (q, qm) = [(b.shape, b.motion) for b in scene_bodies]
    Rp, op = _render._float_pose(pm, t)
    Rq, oq = _render._float_pose(qm, t)
    cp, cq = p.centers @ Rp.T + op, q.centers @ Rq.T + oq
    gaps = np.linalg.norm(cp[:, None] - cq[None], axis=2) - p.radii[:, None] - q.radii[None]
    return gaps.min()


def test_ligand_scene_apart_at_0_overlapping_at_1():
    bodies, description = _demo_scenes.ligand_scene()
    assert "darunavir" in description
    protease, ligand = bodies
    assert protease.motion is None and ligand.motion is not None
    ligand.motion.validate()
    assert protease.shape.n_spheres == 1492 and ligand.shape.n_spheres == 38
    assert _ball_gap(bodies, 0) > 3.0  # outside the protease
    assert _ball_gap(bodies, 1) < -0.4  # the crystal pose: hydrogen bonds overlap
    # t = 1 is exactly the crystal pose: each ball centre goes back to the file's text
    info = ligand.shape.info
    for k in (0, 17, 37):
        assert ligand.motion.position(info.coordinates[k], 1) == info.coordinates[k]
    leave, _ = _demo_scenes.ligand_scene("leave")
    assert _ball_gap(leave, 0) < -0.4 and _ball_gap(leave, 1) > 3.0
    assert leave[1].motion.position(info.coordinates[5], 0) == info.coordinates[5]
    # the two directions are the same path
    for t in (Fraction(1, 5), Fraction(2, 3)):
        assert leave[1].motion.position([1, 2, 3], 1 - t) == ligand.motion.position([1, 2, 3], t)


# ---------------------------------------------------------------- the body demo ---

def _float_first_contact_ligand(bodies, lo=0.0, hi=1.0):
    """Float bisection on the least ball gap (a cross-check of the construction)."""
    assert _ball_gap(bodies, lo) > 0 >= _ball_gap(bodies, hi)
    for _ in range(45):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if _ball_gap(bodies, mid) <= 0 else (mid, hi)
    return hi


def test_run_demo_scenes(tmp_path):
    pytest.importorskip("fcl")
    from polyccd.apps import _demo_bodies
    lines = []
    start = time.perf_counter()
    results = _demo_bodies.run_demo_scenes(tmp_path, out=lines.append)
    assert time.perf_counter() - start < 120
    text = "\n".join(lines)
    for label in ("mechanical", "ligand"):
        result, seconds, png = results[label]
        assert result.collides and png == tmp_path / f"scene_{label}.png"
        assert _png_size(png) == (1600, 800) and png.stat().st_size > 30000
        ct = result.first_contact
        assert ct.lo <= ct.hi and ct.hi - ct.lo <= Fraction(1, 10 ** 12)
    # leaving from the crystal pose: the van der Waals balls already overlap (t = 0),
    # e.g. Asp25 OD1 of chain B with O18 (2.54 A apart, radii 1.52 + 1.52)
    leave = results["ligand_leaving"][0]
    assert leave.first_contact.exact == 0
    protease, ligand = _demo_scenes.ligand_scene("leave")[0]
    labels = {(protease.shape.info.label(c.a[1]), ligand.shape.info.label(c.b[1]))
              for c in leave.first[0].contacts}
    assert any(a == "B:ASP25 OD1" and b.endswith(" O18") for a, b in labels), labels
    # the exact answers agree with float estimates of the same scenes
    mech = results["mechanical"][0].first_contact
    bodies, _ = _demo_scenes.mechanical_scene()

    def hit(t):
        return _fcl_state(bodies[0].shape, bodies[0].motion, bodies[1].motion, t)[0]
    assert not hit(mech.approx - 1e-4) and hit(mech.approx + 1e-4)
    lig = results["ligand"][0]
    estimate = _float_first_contact_ligand(_demo_scenes.ligand_scene()[0])
    assert abs(lig.first_contact.approx - estimate) < 1e-6
    # the touching atoms are named in the report
    (pair,) = lig.first
    info = _demo_scenes.ligand_scene()[0][0].shape.info
    for c in pair.contacts:
        assert c.a[0] == "sphere" and info.label(c.a[1]) in text
    assert "first contact: t" in text and "wall time" in text
