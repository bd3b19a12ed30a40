"""One bad value per C entry point family: the exception's message is the C library's,
"PLACE: what is wrong" (polyccd.h, "Error messages"), and PLACE names the argument AND
the index as the Python arguments nest them (points[1][2][3], translation[1][1], ...).

Most cases go through the public Python API with a value only C rejects (Python passes
number strings through unchecked, float arrays as doubles). The few C checks the Python
API cannot reach, because Python reads only valid indices or checks its own arguments
first (the _d coordinate setters, result / report getters, pccd_scene_options), call
the C function through the bindings' one handle helper and one error mapping.
"""
import subprocess
import sys

import numpy as np
import pytest

import polyccd
from polyccd import InputError, LimitError, Mesh, Motion, Spheres
from polyccd._errors import check
from polyccd._handles import new
from polyccd._pccd import ffi, lib

Z = [[0], [0], [0]]
TRI = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
HALF = Motion(rotation=[["-1/2", 1], [0], [0], [0]])  # r(t) = t - 1/2 vanishes at 1/2


def with_coeff(value, point, axis, index, kind_points=4):
    points = [[[0], [0], [0]] for _ in range(kind_points)]
    points[point][axis] = [0] * index + [value]
    return points


def raises(exc, call, message_start, *words):
    """call() raises exc whose message starts with message_start and holds each word."""
    with pytest.raises(exc) as info:
        call()
    message = str(info.value)
    assert message.startswith(message_start), message
    assert not message.startswith("pccd_"), message  # the C function name is dropped
    for w in words:
        assert w in message, message
    return message


def doubles(*xs):
    return ffi.new("double[]", list(xs))


# ---------------------------------------------------------------- queries

def test_query_coordinate_strings():
    raises(InputError, lambda: polyccd.solve("vertex-face", with_coeff("abc", 1, 2, 3)),
           'points[1][2][3]: "abc" is not a number')
    raises(InputError, lambda: polyccd.solve("vertex-edge", with_coeff("1/0", 2, 0, 1, 3)),
           'points[2][0][1]: "1/0" has a zero denominator')
    raises(LimitError, lambda: polyccd.solve("vertex-face", with_coeff("1e-100001", 3, 1, 2)),
           "points[3][1][2]: ")
    raises(LimitError, lambda: polyccd.solve("vertex-face", with_coeff(1, 0, 1, 65)),
           "points[0][1]: degree 65 exceeds the limit of 64")


def test_query_coordinate_doubles():
    q = new("query", lib.PCCD_VERTEX_FACE)
    raises(InputError, lambda: check(lib.pccd_query_set_coord_d(q, 2, 1, doubles(0, 0, np.nan), 3)),
           "points[2][1][2]: NaN is not a finite number")
    raises(InputError, lambda: check(lib.pccd_query_set_coord_d(q, 4, 1, doubles(0), 1)),
           "point: 4 out of range (this kind has 4 points)")
    raises(InputError, lambda: check(lib.pccd_query_set_coord_d(q, 0, 3, doubles(0), 1)),
           "axis: 3 out of range")


@pytest.mark.parametrize("call", [polyccd.solve_linear, polyccd.collides_linear])
def test_linear_double_arrays(call):
    p = np.zeros((4, 3))
    bad = p.copy()
    bad[1, 2] = -np.inf
    raises(InputError, lambda: call("vertex-face", p, bad), "p_t1[1][2]: infinity is not a finite")
    raises(InputError, lambda: call("vertex-face", bad, p), "p_t0[1][2]: infinity is not a finite")


def test_query_radii():
    ball = [Z, [[3, -4], [0], [0]]]
    raises(InputError, lambda: polyccd.solve("sphere-sphere", ball, [1, "-1/2"]),
           "radii[1]: -1/2 is not > 0")
    raises(InputError, lambda: polyccd.solve("sphere-sphere", ball, ["x", 1]),
           'radii[0]: "x" is not a number')


def test_config_time_tolerance():
    points = with_coeff(1, 0, 2, 0)
    raises(InputError, lambda: polyccd.solve("vertex-face", points, time_tolerance="abc"),
           'config.time_tolerance: "abc" is not a number')
    raises(InputError, lambda: polyccd.solve_linear("vertex-face", np.zeros((4, 3)),
                                                    np.zeros((4, 3)), time_tolerance="0"),
           'config.time_tolerance: "0" must be greater than 0')


# ---------------------------------------------------------------- motions

def test_motion_translation_and_rotation_strings():
    raises(InputError, lambda: Motion(translation=[[0], [0, "x"], [0]]),
           'translation[1][1]: "x" is not a number')
    raises(InputError, lambda: Motion(rotation=[[1], [0], [0], ["1/0"]]),
           'rotation[3][0]: "1/0" has a zero denominator')
    raises(LimitError, lambda: Motion(translation=[[0], [0], [0] * 66]),
           "translation[2]: degree 65 exceeds the limit of 64")


def test_motion_translation_and_rotation_doubles():
    m = new("motion")
    raises(InputError, lambda: check(lib.pccd_motion_set_translation_d(m, 1, doubles(0, np.nan), 2)),
           "translation[1][1]: NaN is not a finite number")
    raises(InputError, lambda: check(lib.pccd_motion_set_rotation_d(m, 0, doubles(np.inf), 1)),
           "rotation[0][0]: infinity is not a finite number")
    raises(InputError, lambda: check(lib.pccd_motion_set_rotation_d(m, 4, doubles(1), 1)),
           "component: 4 out of range")


def test_motion_paths_and_poses():
    raises(InputError, lambda: Motion.bezier([[0] * 3, [0] * 3, [0, "y", 0], [0] * 3]),
           'ctrl[2][1]: "y" is not a number')
    raises(InputError, lambda: Motion.hermite([0] * 3, [0] * 3, [0] * 3, ["z", 0, 0]),
           'v1[0]: "z" is not a number')
    raises(InputError, lambda: Motion().compose([1, 0, "q", 0], [0] * 3), 'quat[2]: "q"')
    raises(InputError, lambda: Motion().compose([1, 0, 0, 0], [0, "o", 0]), 'offset[1]: "o"')
    raises(InputError, lambda: Motion().compose([0, 0, 0, 0], [0] * 3), "quat: the zero quaternion")
    raises(InputError, lambda: Motion.axis_rotation([0, 0, 0], [0] * 3, 0, 1),
           "axis: the direction is the zero vector")
    raises(InputError, lambda: Motion.screw([0, 0, 1], [0, "c", 0], 0, 1, 1), 'center[1]: "c"')
    raises(InputError, lambda: Motion().position([0, 0, 0], "3/2"), "t: 3/2 is outside [0, 1]")


# ---------------------------------------------------------------- bodies

def test_mesh_vertices_and_triangles():
    raises(InputError, lambda: Mesh([[0, 0, 0], [1, 0, 0], [0, "v", 0]], [[0, 1, 2]]),
           'vertices[2][1]: "v" is not a number')  # pccd_body_new_mesh_s
    v = np.array(TRI, dtype=float)
    v[1, 0] = np.nan
    raises(InputError, lambda: Mesh(v, [[0, 1, 2]]), "vertices[1][0]: NaN")  # _d
    raises(InputError, lambda: Mesh(np.array(TRI, dtype=float), [[0, 1, 2], [0, 1, 7]]),
           "triangles[1][2]: index 7 out of range (3 vertices)")
    raises(InputError, lambda: Mesh(TRI, [[0, 1, 2]]).edge_triangles(3),
           "i: edge 3 out of range (the body has 3 edges)")


def test_spheres_centers_and_radii():
    raises(InputError, lambda: Spheres([[0, 0, 0], [0, 0, "c"]], [1, 1]),
           'centers[1][2]: "c" is not a number')  # pccd_body_new_spheres_s
    raises(InputError, lambda: Spheres(np.zeros((3, 3)), np.array([1.0, 2.0, -0.5])),
           "radii[2]: -1/2 is not > 0")  # _d
    raises(InputError, lambda: Spheres(np.zeros((1, 3)), np.array([np.nan])),
           "radii[0]: NaN is not a finite number")


# ---------------------------------------------------------------- scenes, index, reports

def test_scene_motion_and_options():
    ball = Spheres([[0, 0, 0]], [1])
    bodies = [polyccd.Body(ball), polyccd.Body(ball, HALF)]
    raises(InputError, lambda: polyccd.check(bodies), "bodies[1].motion: ", "t = 1/2")
    scene = new("scene")
    for b in bodies[:1] * 2:
        check(lib.pccd_scene_add(scene, b.shape._handle, ffi.NULL, ffi.NULL))
    opt = ffi.new("pccd_scene_options *")
    check(lib.pccd_scene_options_init(opt))
    opt.threads = 0
    raises(InputError, lambda: check(lib.pccd_scene_solve(scene, ffi.NULL, opt, new("report"))),
           "opt.threads: 0 is outside 1..1024")


def test_index_motions():
    ball = Spheres([[0, 0, 0]], [1])
    raises(InputError, lambda: polyccd.Index(polyccd.Body(ball, HALF)), "motion: ", "t = 1/2")
    ix = polyccd.Index(polyccd.Body(ball))
    queries = [polyccd.Body(ball), polyccd.Body(ball), polyccd.Body(ball, HALF)]
    raises(InputError, lambda: ix.query_many(queries), "bodies[2].motion: ", "t = 1/2")


def test_result_and_report_getters():
    res = new("result")
    raises(polyccd.InternalError, lambda: check(lib.pccd_result_collides(res, ffi.new("int *"))),
           "res: holds no answer", "status -5")  # a bug if Python ever did this
    check(lib.pccd_solve_linear_d(lib.PCCD_VERTEX_VERTEX, doubles(*[0] * 6), doubles(*[0] * 6),
                                  ffi.NULL, res))
    raises(InputError, lambda: check(lib.pccd_result_feature(res, 5, ffi.new("int *"),
                                                              ffi.new("size_t[4]"))),
           "i: 5 out of range (1 features)")
    raises(InputError, lambda: check(lib.pccd_result_time(res, 3, ffi.NULL, 0, ffi.NULL)),
           "which: 3 is not 0 (lo), 1 (hi) or 2 (exact)")
    ball = Spheres([[0, 0, 0]], [1])
    scene = new("scene")
    for _ in range(2):
        check(lib.pccd_scene_add(scene, ball._handle, ffi.NULL, ffi.NULL))
    rep = new("report")
    check(lib.pccd_scene_solve(scene, ffi.NULL, ffi.NULL, rep))
    raises(InputError, lambda: check(lib.pccd_report_pair(rep, 3, ffi.NULL, ffi.NULL, ffi.NULL)),
           "pair: 3 out of range (1 pairs in contact)")
    raises(InputError, lambda: check(lib.pccd_report_contact(rep, 0, 9, ffi.NULL, ffi.NULL,
                                                             ffi.NULL, ffi.NULL)),
           "contact: 9 out of range")


# ---------------------------------------------------------------- the package layout

def test_import_polyccd_imports_no_application():
    code = ("import sys, polyccd\n"
            "bad = [m for m in sys.modules if m.split('.')[0] in "
            "('trimesh', 'matplotlib', 'gemmi', 'dask', 'distributed', 'tqdm', 'yourdfpy', 'pinocchio') or m.startswith('polyccd.apps') or m == 'polyccd.robot']\n"
            "print(bad)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]", out
    assert not hasattr(polyccd, "load_scene")  # an application: polyccd.apps.load_scene
