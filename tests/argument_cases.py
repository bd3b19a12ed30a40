"""The public callables of polyccd for the typed-argument property tests
(tests/test_arguments_*.py, issue 33): for each, a valid call (small inputs: each
call takes well under a millisecond or two) and the kind of each argument
(argument_values.KINDS), so that the test can replace one argument at a time by a
wrong value and require polyccd.InputError naming it.

Places: a message names the argument by its name ("points[1]: ...") or by the C
argument it becomes (PLACES: check_step's V0 is the C library's v_t0). ACCEPTED is the
one list of documented acceptances: public names whose arguments are not checked, and
why.
"""
from dataclasses import dataclass, field
from fractions import Fraction
from math import inf
from typing import Any, Callable, Dict, Tuple

import numpy as np
from hypothesis import strategies as st

import polyccd as P
from argument_values import choices

# Public names that take no checked arguments, and why (the one list of acceptances).
ACCEPTED = {
    # result records: built by polyccd from the C library's answers, read by the caller
    "LinearBatch": "result record (solve_linear_many builds it)",
    "Result": "result record (solve builds it)",
    "Answers": "result record (answers() builds it)",
    "ContactTime": "result record",
    "Feature": "result record",
    "StepResult": "result record (check_step builds it)",
    "StepContacts": "result record",
    "SceneResult": "result record (its methods are checked)",
    "PairResult": "result record",
    "Contact": "result record",
    "ContactGeometry": "result record (SceneResult.contact_geometry builds it)",
    "Error": "exception class: any message",
    "InputError": "exception class: any message",
    "LimitError": "exception class: any message",
    "InternalError": "exception class: any message",
    "Cancel": "no argument (set and reset take none)",
    "Chain": "no argument (its methods are checked)",
    "__version__": "a string constant",
    "KINDS": "a constant",
    "BROAD_PHASES": "a constant",
    # polyccd.robot
    "Robot": "built by load_urdf (its methods are checked)",
    "RobotResult": "result record (Robot.check builds it; RobotResult.of is its builder)",
    "RobotContact": "result record",
    "PathResult": "result record",
    "RobotBatch": "result record (Robot.check_many builds it)",
    "SUPPORTED": "a constant",
    # polyccd.ompl
    "BACKOFF": "a constant",
}

# Values of an argument that are accepted though not of its kind, and why:
# {(case name or "*", argument): (test, reason)}.
ACCEPTED_VALUES = {
    ("*", "time_tolerance"): (lambda v: v is None, "None is the C library's NULL: the default 1e-12"),
    ("check_step", "min_distance"): (lambda v: v is None, "None: no minimum distance, as in check"),
    ("collision_free_stepsize", "min_distance"): (lambda v: v is None, "None: no minimum distance"),
    ("check_step", "faces"): (lambda v: v is None, "None: no faces (particles: points=)"),
    ("collision_free_stepsize", "faces"): (lambda v: v is None, "None: no faces (particles: points=)"),
    ("joint_path", "t"): (lambda v: _times(v), "t may be an array of times (empty: none)"),
    ("RobotSpace.joint_path", "t"): (lambda v: _times(v), "t may be an array of times (empty: none)"),
    ("RobotSpace.waypoints", "path"): (lambda v: isinstance(v, list) and not v, "an empty path: no waypoint"),
    ("Motion.translation", "coeffs_xyz"): (lambda v: _constants(v), "a number is a constant coordinate"),
    ("Robot.check_joint_limits", "q0"): (lambda v: _non_finite(v), "non-finite values: the chain's to report"),
    ("Robot.check_joint_limits", "q1"): (lambda v: _non_finite(v), "non-finite values: the chain's to report"),
    # polyccd.ompl's validators never raise (polyccd/ompl.py: an exception inside a check
    # makes the state or motion invalid and is kept in RobotSpace.errors)
    ("RobotSpace.is_valid", "q"): (lambda v: True, "a validator: invalid, error in space.errors"),
    ("RobotSpace.motion_valid", "q1"): (lambda v: True, "a validator"),
    ("RobotSpace.motion_valid", "q2"): (lambda v: True, "a validator"),
    ("RobotSpace.last_valid", "q1"): (lambda v: True, "a validator"),
    ("RobotSpace.last_valid", "q2"): (lambda v: True, "a validator"),
}

def _non_finite(v):
    """A list of real numbers, one of them a NaN or an infinity (check_joint_limits' docstring)."""
    return isinstance(v, list) and all(type(x) in (int, float) for x in v) and any(x != x or abs(x) == inf for x in v)


def _constants(v):
    """3 coordinates, each a coefficient list or an exact number (Motion.translation's
    docstring: [0.5, 0, 0.4] stands still at that offset)."""
    def number(x):
        if isinstance(x, bool):
            return False
        if isinstance(x, (int, Fraction)) or (isinstance(x, float) and x == x and abs(x) != inf):
            return True
        try:
            return isinstance(x, str) and Fraction(x) is not None
        except (ValueError, ZeroDivisionError):
            return False
    return (isinstance(v, list) and len(v) == 3 and all(isinstance(c, list) or number(c) for c in v)
            and not all(isinstance(c, list) for c in v))


def _times(v):
    return isinstance(v, (list, tuple)) and all(type(x) in (int, float) and 0 <= x <= 1 for x in v)


# Methods that take no argument (nothing to replace).
NO_ARGUMENTS = {"Mesh.exact_vertices", "Spheres.exact_centers", "Spheres.exact_radii",
                "Cancel.set", "Cancel.reset", "Robot.adjacent_pairs", "RobotSpace.simple_setup",
                "RobotResult.of", "RobotBatch.raise_first"}  # of: Robot.check's builder of its result, from its own values


@dataclass
class Case:
    """name: "function", "Class" (its constructor) or "Class.method"; call(**kwargs);
    valid: a function giving the kwargs of a valid call; kinds: {argument: kind};
    places: {argument: names its message may start with} (default: the argument)."""
    name: str
    call: Callable[..., Any]
    valid: Callable[[], Dict[str, Any]]
    kinds: Dict[str, Any]
    places: Dict[str, Tuple[str, ...]] = field(default_factory=dict)


TRI = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
MESH = P.Mesh(TRI, [[0, 1, 2]])
BALL = P.Spheres([[0, 0, 0]], [1])
MOTION = P.Motion.linear([0, 0, 0], [1, 0, 0])
MOVING = P.Body(BALL, MOTION, name="a")
STILL = P.Body(BALL, P.Motion.linear([3, 0, 0], [3, 0, 0]), name="b")
INDEX = P.Index(STILL)
SCENE = P.check([MOVING, STILL])
CHAIN = P.Chain()
CHAIN.add_link(-1, "revolute", [0, 0, 1], [0, 0, 0], [0, 0, 0])
VF0 = [[0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]]
VF1 = [[0.25, 0.25, -1], [0, 0, 0], [1, 0, 0], [0, 1, 0]]
V0 = np.array(VF0[1:] + [[0.25, 0.25, 1]], dtype=np.float64)
V1 = np.array(VF1[1:] + [[0.25, 0.25, -1]], dtype=np.float64)
FACES = np.array([[0, 1, 2]])

CONFIG_PLACES = {"min_distance": ("config.min_distance",), "time_tolerance": ("config.time_tolerance",)}
OPTIONS = {"time_tolerance": "number", "want_time": "bool", "want_exact": "bool",
           "limits": "limits", "min_distance": "number?"}
SCENE_OPTIONS = {"time_tolerance": "number", "all_contacts": "bool", "threads": "int",
                 "broad_phase": choices("auto", "boxes", "brute", "bvh", "range"),
                 "want_exact": "bool", "limits": "limits", "min_distance": "number?"}
STEP_OPTIONS = {"V0": "points", "V1": "points", "faces": "triangles", "edges": "edges",
                "points": "numbers", "obstacles": "bodies", "min_distance": "number",
                "threads": "int", "limits": "limits"}
STEP_PLACES = {"V0": ("v_t0",), "V1": ("v_t1",), "threads": ("opt.threads",), "paths": ("coeffs",),
               **CONFIG_PLACES}
THREADS = {"threads": ("opt.threads",), **CONFIG_PLACES}


def _step_valid():
    return {"V0": V0, "V1": V1, "faces": FACES, "points": [3]}


CASES = [
    Case("kind_points", P.kind_points, lambda: {"kind": "vertex-face"},
         {"kind": choices(*P.KINDS)}),
    Case("usable_threads", P.usable_threads, lambda: {"requested": 2}, {"requested": "int"}),
    Case("solve", P.solve, lambda: {"kind": "sphere-sphere", "points": [[[0, 1], [0], [0]], [[3], [0], [0]]],
                                    "radii": [1, 1]},
         {"kind": choices(*P.KINDS), "points": "points", "radii": "numbers", **OPTIONS}, CONFIG_PLACES),
    Case("solve_linear", P.solve_linear, lambda: {"kind": "vertex-face", "p_t0": VF0, "p_t1": VF1},
         {"kind": choices(*P.KINDS), "p_t0": "points", "p_t1": "points", **OPTIONS}, CONFIG_PLACES),
    Case("collides_linear", P.collides_linear, lambda: {"kind": "vertex-face", "p_t0": VF0, "p_t1": VF1},
         {"kind": choices(*P.KINDS), "p_t0": "points", "p_t1": "points"}),
    Case("solve_linear_many", P.solve_linear_many,
         lambda: {"kind": "vertex-face", "t0": np.array([VF0], float), "t1": np.array([VF1], float)},
         {"kind": choices(*P.KINDS), "t0": "points", "t1": "points", "threads": "int", **OPTIONS},
         THREADS),
    Case("answers", P.answers, lambda: {"results": [P.solve_linear("vertex-face", VF0, VF1)]},
         {"results": "bodies"}),
    Case("Motion", P.Motion, lambda: {"translation": [[0, 1], [0], [0]], "rotation": [[1], [0], [0], [0]]},
         {"translation": "translation", "rotation": "rotation"}),
    Case("Motion.axis_rotation", P.Motion.axis_rotation,
         lambda: {"axis": [0, 0, 1], "center": [0, 0, 0], "tau0": 0, "tau1": 1},
         {"axis": "vector", "center": "vector", "tau0": "number", "tau1": "number"}),
    Case("Motion.screw", P.Motion.screw,
         lambda: {"axis": [0, 0, 1], "center": [0, 0, 0], "tau0": 0, "tau1": 1, "advance": 1},
         {"axis": "vector", "center": "vector", "tau0": "number", "tau1": "number", "advance": "number"}),
    Case("Motion.between", P.Motion.between,
         lambda: {"pose0": ([0, 0, 0], [1, 0, 0, 0]), "pose1": ([1, 0, 0], [0, 0, 0, 1])},
         {"pose0": "vector", "pose1": "vector"}),
    Case("Motion.bezier", P.Motion.bezier, lambda: {"ctrl": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]}, {"ctrl": "points"}),
    Case("Motion.hermite", P.Motion.hermite,
         lambda: {"p0": [0, 0, 0], "v0": [1, 0, 0], "p1": [1, 0, 0], "v1": [1, 0, 0]},
         {"p0": "vector", "v0": "vector", "p1": "vector", "v1": "vector"}),
    Case("Motion.linear", P.Motion.linear, lambda: {"p0": [0, 0, 0], "p1": [1, 0, 0]},
         {"p0": "vector", "p1": "vector"}),
    Case("Motion.fixed", P.Motion.fixed, lambda: {"pose": ([1, 0, 0], [0, 0, 0, 1])}, {"pose": "vector"}),
    Case("Motion.translation", P.Motion.translation, lambda: {"coeffs_xyz": [[0, 1], [0], [0]]},
         {"coeffs_xyz": "translation"}, {"coeffs_xyz": ("translation",)}),
    Case("Motion.compose", MOTION.compose, lambda: {"quat": [1, 0, 0, 0], "offset": [0, 0, 1], "side": "world"},
         {"quat": "quaternion", "offset": "vector", "side": choices("body", "world")}),
    Case("Motion.position", MOTION.position, lambda: {"p": [0, 0, 0], "t": "1/2"},
         {"p": "vector", "t": "number", "limits": "limits"}),
    Case("Motion.then", MOTION.then, lambda: {"outer": MOTION}, {"outer": "motion!", "limits": "limits"}),
    Case("Motion.validate", MOTION.validate, lambda: {}, {"limits": "limits"}),
    Case("Chain.add_link", lambda **k: P.Chain().add_link(**k),
         lambda: {"parent": -1, "joint": "prismatic", "axis": [1, 0, 0], "xyz": [0, 0, 0], "rpy": [0, 0, 0]},
         {"parent": "int", "joint": choices("fixed", "revolute", "continuous", "prismatic"),
          "axis": "vector", "xyz": "vector", "rpy": "vector"}),
    Case("Chain.joint_values", CHAIN.joint_values, lambda: {"q0": [0], "q1": [1], "t": "1/2"},
         {"q0": "numbers", "q1": "numbers", "t": "number"}),
    Case("Chain.motions", CHAIN.motions, lambda: {"q0": [0], "q1": [1]},
         {"q0": "numbers", "q1": "numbers", "limits": "limits"}),
    Case("Chain.set_value_place", lambda **k: _chain().set_value_place(**k), lambda: {"k": 0, "place": "[0] (a)"},
         {"k": "int", "place": "str"}),
    Case("Mesh", P.Mesh, lambda: {"vertices": TRI, "triangles": [[0, 1, 2]]},
         {"vertices": "points", "triangles": "triangles", "limits": "limits"}),
    Case("Mesh.box", P.Mesh.box, lambda: {"extents": [1, 2, 3]}, {"extents": "vector"}),
    Case("Mesh.cylinder", P.Mesh.cylinder, lambda: {"radius": 1, "height": 2, "sections": 5},
         {"radius": "number", "height": "number", "sections": "int"}),
    Case("Mesh.edge_triangles", MESH.edge_triangles, lambda: {"i": 1}, {"i": "int"}),
    Case("Mesh.from_trimesh", P.Mesh.from_trimesh, lambda: {"mesh": _trimesh()}, {"mesh": "body"}),
    Case("Spheres", P.Spheres, lambda: {"centers": [[0, 0, 0], [1, 0, 0]], "radii": [1, "1/2"]},
         {"centers": "points", "radii": "numbers"}, dict.fromkeys(("centers", "radii"), ("centers, radii",))),
    Case("Body", P.Body, lambda: {"shape": BALL, "motion": MOTION, "name": "x"},
         {"shape": "body", "motion": "motion", "name": "str?"}),
    Case("check", P.check, lambda: {"bodies": [MOVING, STILL], "skip_pairs": [(0, 1)]},
         {"bodies": "bodies", "skip_pairs": "bodies", "first_contact": "bool", **SCENE_OPTIONS}, THREADS),
    Case("Index", P.Index, lambda: {"body": STILL}, {"body": "body", "limits": "limits"}),
    Case("Index.query", INDEX.query, lambda: {"body": MOVING}, {"body": "body", **SCENE_OPTIONS}, THREADS),
    Case("Index.query_many", INDEX.query_many, lambda: {"bodies": [MOVING]},
         {"bodies": "bodies", **SCENE_OPTIONS}, THREADS),
    Case("Limits", P.Limits, lambda: {"max_seconds": 2.5, "max_work": 10, "cancel": P.Cancel(),
                                      "max_number_bits": 100},
         {"max_seconds": "number?", "max_work": "int?", "cancel": "limits", "max_number_bits": "int?"},
         {k: (f"limits.{k}",) for k in ("max_seconds", "max_work", "cancel", "max_number_bits")}),
    Case("check_step", P.check_step, _step_valid,
         {**STEP_OPTIONS, "first_contact": "bool", "all_contacts": "bool", "paths": "points"}, STEP_PLACES),
    Case("collision_free_stepsize", P.collision_free_stepsize, _step_valid, dict(STEP_OPTIONS), STEP_PLACES),
    Case("SceneResult.contact_geometry", SCENE.contact_geometry, lambda: {"pair": 0, "contact": 0},
         {"pair": "int", "contact": "int", "bodies": "bodies"}),
    Case("SceneResult.feature_indices", SCENE.feature_indices, lambda: {"body": 0, "pairs": "all"},
         {"body": st.one_of(choices("a", "b").filter(lambda v: not isinstance(v, int) or v not in (0, 1))),
          "pairs": choices("first", "all")}),
]


def _chain():
    c = P.Chain()
    c.add_link(-1, "revolute", [0, 0, 1], [0, 0, 0], [0, 0, 0])
    return c


def _trimesh():
    import trimesh
    return trimesh.Trimesh(vertices=TRI, faces=[[0, 1, 2]], process=False)
