"""The plainmp side of bench_plainmp.py and bench_planning.py (plainmp 0.3.6, optional:
tests/bench/requirements-plainmp.txt): importing it (PLAINMP_SITE: a site-packages
directory to append to sys.path, e.g. another venv's), its Panda on a given URDF (a
PandaSpec whose urdf_path_override returns it, plainmp's own sphere model), axis-aligned
boxes as its SDFs, the edge check at a resolution, and its RRTConnect planner. A helper
module, not a benchmark."""
import math
import os
import sys
from pathlib import Path

import numpy as np


def load():
    """(plainmp namespace dict, None) or (None, why it is not importable)."""
    if os.environ.get("PLAINMP_SITE"):
        sys.path.append(os.environ["PLAINMP_SITE"])
    try:
        from plainmp.ompl_solver import Algorithm, OMPLSolver, OMPLSolverConfig
        from plainmp.problem import Problem
        from plainmp.psdf import BoxSDF, Pose, UnionSDF
        from plainmp.robot_spec import PandaSpec
    except ImportError as e:
        return None, str(e)
    return dict(Algorithm=Algorithm, OMPLSolver=OMPLSolver, OMPLSolverConfig=OMPLSolverConfig,
                Problem=Problem, BoxSDF=BoxSDF, Pose=Pose, UnionSDF=UnionSDF,
                PandaSpec=PandaSpec), None


def panda(mods, urdf, boxes, self_collision):
    """(spec, SphereCollisionCst) of the Panda on urdf among boxes [(name, lo, hi)]."""
    class Spec(mods["PandaSpec"]):
        def urdf_path_override(self):
            return Path(urdf)

    spec = Spec()
    cst = spec.create_collision_const(self_collision=self_collision, use_cache=False)
    cst.set_sdf(mods["UnionSDF"]([mods["BoxSDF"](np.subtract(hi, lo), mods["Pose"](np.add(lo, hi) / 2, np.eye(3)))
                                  for _, lo, hi in boxes]))
    return spec, cst


def edge_collides(cst, q0, q1, res):
    """True when a state q0 + (q1 - q0) k / m, m = ceil(|q1 - q0|_2 / res), is invalid
    (OMPL's Euclidean resolution), stopping at the first, as a planner does."""
    d = q1 - q0
    m = max(1, math.ceil(float(np.linalg.norm(d)) / res))
    for k in range(m + 1):
        if not cst.is_valid(q0 + d * (k / m)):
            return True
    return False


def planner(mods, spec, cst, resolution, seconds):
    """plan(start, goal) -> (waypoints (k, 7) or None, seconds): plainmp's OMPLSolver,
    RRTConnect, its box motion validator at `resolution` rad per joint, no smoothing."""
    lb, ub = spec.angle_bounds()
    config = mods["OMPLSolverConfig"](algorithm=mods["Algorithm"].RRTConnect, timeout=seconds)

    def plan(start, goal):
        problem = mods["Problem"](np.asarray(start, float), lb, ub, np.asarray(goal, float), cst,
                                  None, np.ones(len(start)) * resolution)
        ret = mods["OMPLSolver"](config).solve(problem)
        return (None if ret.traj is None else np.array(ret.traj.numpy())), ret.time_elapsed

    return plan
