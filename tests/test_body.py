"""Rigid bodies (polyccd.Mesh, polyccd.Spheres): edge extraction against an independent
pure-Python computation, closed meshes against Euler's formula, and every error path
(the message must name the bad input's place).

The oracle (`oracle_edges`) follows docs/python.md "Bodies": every unordered
side {a, b}, a != b, of a triangle, once, as (a, b) with a < b, sorted; each edge with
the ascending indices of the triangles that have it as a side.
"""
import copy
import random
from fractions import Fraction

import numpy as np
import pytest

import polyccd
from polyccd import InputError, LimitError, Mesh, Spheres

SEED = 20261122


def oracle_edges(triangles):
    incident = {}
    for t, tri in enumerate(triangles):
        for k in range(3):
            a, b = tri[k], tri[(k + 1) % 3]
            if a != b:
                incident.setdefault((min(a, b), max(a, b)), set()).add(t)
    return {e: tuple(sorted(ts)) for e, ts in sorted(incident.items())}


def check_edges(mesh, triangles, note):
    want = oracle_edges(triangles)
    assert mesh.edges.tolist() == [list(e) for e in want], note
    assert mesh.n_edges == len(want), note
    for i, (e, ts) in enumerate(want.items()):
        assert mesh.edge_triangles(i) == ts, (note, e)


TETRA_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TETRA_T = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
CUBE_V = [[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)]  # index 4x + 2y + z
CUBE_T = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
          [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]


@pytest.mark.parametrize("name, vertices, triangles", [("tetrahedron", TETRA_V, TETRA_T),
                                                       ("cube", CUBE_V, CUBE_T)])
def test_closed_meshes_satisfy_euler(name, vertices, triangles):
    mesh = Mesh(vertices, triangles)
    v, e, f = mesh.n_vertices, mesh.n_edges, mesh.n_triangles
    assert v - e + f == 2, (name, v, e, f)
    assert 3 * f == 2 * e  # closed 2-manifold: every edge has exactly two triangles
    assert all(len(mesh.edge_triangles(i)) == 2 for i in range(e))
    check_edges(mesh, triangles, name)


def test_random_meshes_match_the_oracle():
    rng = random.Random(SEED)
    for case in range(200):
        nv = rng.randint(1, 12)
        tris = [[rng.randrange(nv) for _ in range(3)] for _ in range(rng.randint(1, 25))]
        verts = [[rng.randint(-5, 5) for _ in range(3)] for _ in range(nv)]
        note = f"seed {SEED} case {case}: vertices={verts} triangles={tris}"
        mesh = Mesh(verts, tris)
        assert (mesh.n_vertices, mesh.n_triangles) == (nv, len(tris)), note
        check_edges(mesh, tris, note)
        # The same mesh from numpy arrays (the _d path and uint indices) agrees.
        mesh2 = Mesh(np.array(verts, dtype=np.float64), np.array(tris, dtype=np.uint32))
        assert mesh2.edges.tolist() == mesh.edges.tolist(), note


def test_degenerate_triangles_are_accepted():
    # Repeated indices, a single point, collinear and coincident vertices.
    verts = [[0, 0, 0], [1, 1, 1], [2, 2, 2], [0, 0, 0]]
    tris = [[0, 0, 1], [2, 2, 2], [0, 1, 2], [0, 3, 1]]
    mesh = Mesh(verts, tris)
    assert mesh.n_triangles == 4
    check_edges(mesh, tris, "degenerate")
    assert Mesh(verts, [[1, 1, 1]]).n_edges == 0  # a point-triangle has no edge
    assert Mesh(verts, [[0, 1, 0]]).edge_triangles(0) == (0,)  # listed once


def test_number_types_and_unused_vertices():
    verts = [[Fraction(1, 3), "2.5e-7", 10 ** 40], [0.1, -7, "-7/3"], [0, 0, 0],
             [np.float32(0.5), np.int64(3), Fraction(-1)]]
    mesh = Mesh(verts, [(0, 1, 2)])
    assert (mesh.n_vertices, mesh.n_edges, mesh.n_triangles) == (4, 3, 1)
    assert Mesh(np.array(verts[2:], dtype=np.float32), [[0, 1, 1]]).n_edges == 1
    assert Mesh(np.array([[1, 2, 3]], dtype=np.int64), np.array([[0, 0, 0]])).n_vertices == 1
    assert Mesh(np.array([[1, 2, 3]], dtype=np.longdouble), [[0, 0, 0]]).n_vertices == 1
    spheres = Spheres([[0, 0, 0], ["1/3", 0.25, 7]], [Fraction(1, 10), "1e-30"])
    assert spheres.n_spheres == 2
    assert Spheres(np.zeros((3, 3)), np.array([1.0, 0.5, 2.0])).n_spheres == 3
    assert Spheres(np.zeros((1, 3)), ["1/2"]).n_spheres == 1  # mixed: all as texts
    assert Spheres([[0, 0, 0]], np.array([0.5])).n_spheres == 1


def test_bodies_are_immutable():
    mesh, spheres = Mesh(TETRA_V, TETRA_T), Spheres([[0, 0, 0]], [1])
    for body in (mesh, spheres):
        with pytest.raises(AttributeError):
            body._handle = None
        assert copy.copy(body) is body and copy.deepcopy(body) is body
    assert "6 edges" in repr(mesh) and "1 balls" in repr(spheres)


NAN, INF = float("nan"), float("inf")


@pytest.mark.parametrize("vertices, triangles, place, word", [
    ([[0, 0, 0]], [[0, 0, 1]], "triangles[0][2]", "index 1 out of range (1 vertices)"),
    ([[0, 0, 0]] * 10, [[0, 1, 2], [3, 4, 5], [6, 7, 8], [9, 12, 0]], "triangles[3][1]",
     "index 12 out of range (10 vertices)"),
    (np.zeros((2, 3)), np.array([[0, 1, 2]]), "triangles[0][2]", "out of range (2 vertices)"),
    ([[0, 0, 0]], [[0, -1, 0]], "triangles[0][1]", "index -1"),
    ([[0, 0, 0]], [[0, 2 ** 32, 0]], "triangles[0][1]", "index 4294967296"),
    ([[0, 0, 0]], [[0, 0.0, 0]], "triangles[0][1]", "not an integer"),
    ([[0, 0, 0]], [[0, True, 0]], "triangles[0][1]", "not an integer"),
    ([[0, 0, 0]], np.array([[0.0, 0, 0]]), "triangles", "integer indices"),
    ([[0, 0, 0]], [], "triangles", "at least one triangle"),
    ([[0, 0, 0]], [[0, 0]], "triangles[0]", "expected 3"),
    ([[0, 0, 0]], np.array([0, 0, 0]), "triangles", "shape (n, 3)"),
    ([[0, 0, 0]], "012", "triangles", "expected"),
    ([[0, 0, NAN]], [[0, 0, 0]], "vertices[0][2]", "not a finite number"),
    (np.array([[0, 0, 0], [0, -INF, 0]]), [[0, 0, 1]], "vertices[1][1]", "infinity"),
    (np.array([[0, 0, 0], [NAN, 0, 0]]), [[0, 0, 1]], "vertices[1][0]", "NaN"),
    ([[0, 0, 0], [0, "1/0", 0]], [[0, 0, 1]], "vertices[1][1]", "zero denominator"),
    ([[0, 0, 0], [0, "abc", 0]], [[0, 0, 1]], "vertices[1][1]", "not a number"),
    ([[0, 0, 0], [0, True, 0]], [[0, 0, 1]], "vertices[1][1]", "boolean"),
    ([[0, 0, 0], [0, 0]], [[0, 0, 1]], "vertices[1]", "expected 3 numbers, got 2"),
    (np.zeros((2, 2)), [[0, 0, 1]], "vertices", "shape (n, 3)"),
    (np.zeros(6), [[0, 0, 1]], "vertices", "shape (n, 3)"),
    (5, [[0, 0, 0]], "vertices", "expected"),
    ([[0, 0, 0]], None, "triangles", "expected"),
])
def test_mesh_errors_name_the_place(vertices, triangles, place, word):
    with pytest.raises(InputError) as info:
        Mesh(vertices, triangles)
    message = str(info.value)
    assert message.startswith(place + ":") and word in message, message


@pytest.mark.parametrize("centers, radii, place, word", [
    ([[0, 0, 0]] * 3, [1, 2, Fraction(-1, 2)], "radii[2]", "-1/2 is not > 0"),
    ([[0, 0, 0]], [0], "radii[0]", "0 is not > 0"),
    (np.zeros((2, 3)), np.array([1.0, -0.0]), "radii[1]", "0 is not > 0"),
    (np.zeros((2, 3)), np.array([1.0, -0.5]), "radii[1]", "-1/2 is not > 0"),
    ([[0, 0, 0]], [NAN], "radii[0]", "not a finite number"),
    (np.zeros((1, 3)), np.array([INF]), "radii[0]", "infinity"),
    ([[0, INF, 0]], [1], "centers[0][1]", "not a finite number"),
    (np.array([[0, 0, NAN]]), np.array([1.0]), "centers[0][2]", "NaN"),
    (np.array([[0, 0, NAN]]), ["1"], "centers[0][2]", "not a finite number"),
    ([[0, 0, "x"]], [1], "centers[0][2]", "not a number"),
    ([[0, 0, 0]], ["1/0"], "radii[0]", "zero denominator"),
    ([[0, 0, 0]], [[1]], "radii[0]", "expected a number"),
    ([[0, 0, 0]], [1, 2], "centers, radii", "1 centers but 2 radii"),
    ([], [], "centers", "at least one ball"),
    (np.zeros((0, 3)), np.zeros(0), "centers", "at least one ball"),
    ([[0, 0]], [1], "centers[0]", "expected 3 numbers"),
    (np.zeros((1, 3)), np.zeros((1, 1)), "radii", "got shape (1, 1)"),
])
def test_spheres_errors_name_the_place(centers, radii, place, word):
    with pytest.raises(InputError) as info:
        Spheres(centers, radii)
    message = str(info.value)
    assert message.startswith(place + ":") and word in message, message


def test_limits_and_bad_edge_index():
    too_long = "1" * (polyccd._lib.PCCD_MAX_NUMBER_CHARS + 1)
    with pytest.raises(LimitError, match=r"^vertices\[0\]\[0\]:"):
        Mesh([[too_long, 0, 0]], [[0, 0, 0]])
    mesh = Mesh(TETRA_V, TETRA_T)
    with pytest.raises(InputError, match="edge 6 out of range"):
        mesh.edge_triangles(6)
    with pytest.raises(InputError, match="not an edge index"):
        mesh.edge_triangles(-1)
    assert polyccd._lib.PCCD_MAX_BODY_ELEMENTS == 50_000_000
