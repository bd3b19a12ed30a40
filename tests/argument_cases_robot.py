"""The public callables of polyccd.robot and polyccd.ompl for the typed-argument
property tests (argument_cases.py has the conventions and the acceptances): a small
two-joint arm written here (boxes: no mesh files), and its OMPL space."""
import functools

import numpy as np
from hypothesis import strategies as st

import polyccd as P
from argument_cases import SCENE_OPTIONS, THREADS, Case
from argument_values import _point_lists, choices
from arm_urdf import arm_urdf

ARM = arm_urdf(3)
SRDF = '<robot name="arm"><disable_collisions link1="base" link2="lower" reason="x"/></robot>'
POST = P.Body(P.Mesh.box([0.1, 0.1, 1]), P.Motion.linear([1.5, 0.5, 0], [1.5, 0.5, 0]), name="post")
Q0, Q1 = [0.0, 0.0], [0.5, 0.3]
SEGMENT = {"q0": "numbers", "q1": "numbers"}
ROWS = _point_lists(2)  # not a list of the arm's joint vectors


def raising(method):
    """method, raising its RobotBatch's first per-segment error (named "segments[k]" or
    "states[k]": where in Q0 / Q1 / Q the bad row is)."""
    @functools.wraps(method)
    def call(**kw):
        out = method(**kw)
        out.raise_first()
        return out
    return call


def robot_cases(tmp):
    """(cases, robot) with the URDF and SRDF written under tmp."""
    from polyccd.robot import load_urdf
    urdf, srdf = tmp / "arm.urdf", tmp / "arm.srdf"
    urdf.write_text(ARM)
    srdf.write_text(SRDF)
    robot = load_urdf(str(urdf))
    check_kinds = {**SEGMENT, "obstacles": "bodies", "self_collision": "bool", "allowed": "bodies",
                   **{k: v for k, v in SCENE_OPTIONS.items() if k != "want_exact"},
                   "first_contact": "bool", "filter": "bool", "joint_limits": choices("error", "ignore")}
    cases = [
        Case("load_urdf", load_urdf, lambda: {"path": str(urdf), "geometry": "visual", "srdf": str(srdf)},
             {"path": "path", "geometry": choices("collision", "visual"), "srdf": "path", "limits": "limits"}),
        Case("Robot.allowed_from_srdf", robot.allowed_from_srdf, lambda: {"path": str(srdf)}, {"path": "path"},
             {"path": ("srdf",)}),
        Case("Robot.bodies", robot.bodies, lambda: {"q0": Q0, "q1": Q1}, SEGMENT),
        Case("Robot.chain_values", robot.chain_values, lambda: {"q": Q0, "place": "q"},
             {"q": "numbers", "place": "str"}),
        Case("Robot.check", robot.check, lambda: {"q0": Q0, "q1": Q1, "obstacles": [POST]}, check_kinds, THREADS),
        Case("Robot.check_many", raising(robot.check_many),
             lambda: {"Q0": [Q0, Q1], "Q1": [Q1, Q0], "obstacles": [POST]},
             {"Q0": ROWS, "Q1": ROWS, **{k: v for k, v in check_kinds.items() if k not in (
                 "q0", "q1", "all_contacts", "broad_phase")}, "results": "bool"},
             {**THREADS, **dict.fromkeys(("Q0", "Q1"), ("segments", "Q0, Q1"))}),
        Case("Robot.check_states", raising(robot.check_states), lambda: {"Q": [Q0, Q1], "obstacles": [POST]},
             {"Q": ROWS, **{k: v for k, v in check_kinds.items() if k not in (
                 "q0", "q1", "all_contacts", "broad_phase", "time_tolerance", "first_contact")},
              "results": "bool"},
             {**THREADS, "Q": ("states",)}),
        Case("Robot.check_joint_limits", robot.check_joint_limits, lambda: {"q0": Q0, "q1": Q1},
             {**SEGMENT, "joint_limits": choices("error", "ignore")}),
        Case("Robot.check_path", robot.check_path, lambda: {"waypoints": [Q0, Q1, Q0], "obstacles": [POST]},
             {"waypoints": "points", "obstacles": "bodies"}),
        Case("Robot.joint_values", robot.joint_values, lambda: {"q0": Q0, "q1": Q1, "t": "1/2"},
             {**SEGMENT, "t": "number"}),
        Case("Robot.link_motions", robot.link_motions, lambda: {"q0": Q0, "q1": Q1}, SEGMENT),
        Case("Robot.motions", robot.motions, lambda: {"q0": Q0, "q1": Q1}, SEGMENT),
    ]
    return cases, robot


def ompl_cases(robot):
    """The cases of polyccd.ompl (the caller skips them without ompl)."""
    import ompl.base as ob
    import ompl.geometric as og
    from polyccd import ompl as O
    space = O.RobotSpace(robot, [POST])
    path = og.PathGeometric(space.si)
    for q in (Q0, Q1):
        path.append(space.state(q))
    state = {"space": space, "states": (space.state(Q0), space.state(Q1))}
    checker, validator = O.StateValidityChecker(space), O.MotionValidator(space)
    return [
        Case("joint_path", O.joint_path, lambda: {"revolute": [True, False], "q0": Q0, "q1": Q1, "t": 0.5},
             {"revolute": "numbers", "q0": "numbers", "q1": "numbers", "t": "number"},
             dict.fromkeys(("revolute", "q0", "q1"), ("revolute, q0, q1",))),  # lengths that differ
        Case("joint_space", O.joint_space, lambda: {"names": ["a", "b"], "bounds": [(-1, 1), (0, 2)]},
             {"names": "bodies", "bounds": "points"}),
        Case("simplify", O.simplify, lambda: {"si": space.si, "path": og.PathGeometric(path), "rounds": 1},
             {"si": "body", "path": "body", "rounds": "int"}),
        Case("RobotSpace", O.RobotSpace, lambda: {"robot": robot, "obstacles": [POST], "joints": ["shoulder"],
                                                  "fixed": {"elbow": 0.1}, "bounds": {"shoulder": (-1, 1)}},
             {"robot": "body", "obstacles": "bodies", "joints": "bodies", "fixed": "body", "bounds": "body"}),
        Case("StateValidityChecker", O.StateValidityChecker, lambda: {"space": space}, {"space": "body"}),
        Case("StateValidityChecker.isValid", checker.isValid, lambda: {"state": state["states"][0]},
             {"state": "body"}),
        Case("MotionValidator", O.MotionValidator, lambda: {"space": space}, {"space": "body"}),
        Case("MotionValidator.checkMotion", validator.checkMotion,
             lambda: {"s1": state["states"][0], "s2": state["states"][1], "last_valid": [None, 0.0]},
             {"s1": "body", "s2": "body", "last_valid": "body"}),
        Case("MotionValidator.checkMotionWithLastValid", validator.checkMotionWithLastValid,
             lambda: {"s1": state["states"][0], "s2": state["states"][1], "state": space.state(Q0)},
             {"s1": "body", "s2": "body", "state": "motion"}),
        Case("RobotSpace.q", space.q, lambda: {"state": state["states"][0]}, {"state": "body"}),
        Case("RobotSpace.state", space.state, lambda: {"q": Q1, "out": None}, {"q": "numbers", "out": "motion"}),
        Case("RobotSpace.joint_path", space.joint_path, lambda: {"q0": Q0, "q1": Q1, "t": 0.25},
             {"q0": "numbers", "q1": "numbers", "t": "number"}),
        Case("RobotSpace.interpolate", space.interpolate,
             lambda: {"s1": state["states"][0], "s2": state["states"][1], "t": 0.5},
             {"s1": "body", "s2": "body", "t": "number", "out": "motion"}),
        Case("RobotSpace.waypoints", space.waypoints, lambda: {"path": path}, {"path": "body"}),
        Case("RobotSpace.interpolate_path", space.interpolate_path, lambda: {"path": [Q0, Q1], "step": 0.5},
             {"path": "points", "step": "number"}),
        Case("RobotSpace.check_path", space.check_path, lambda: {"path": [Q0, Q1]}, {"path": "points"},
             {"path": ("waypoints",)}),  # Robot.check_path's argument, as its docstring says
        Case("RobotSpace.simplify", space.simplify, lambda: {"path": og.PathGeometric(path), "rounds": 1},
             {"path": "body", "rounds": "int"}),
        Case("RobotSpace.is_valid", space.is_valid, lambda: {"q": Q0}, {"q": "numbers"}),
        Case("RobotSpace.motion_valid", space.motion_valid, lambda: {"q1": Q0, "q2": Q1},
             {"q1": "numbers", "q2": "numbers"}),
        Case("RobotSpace.last_valid", space.last_valid, lambda: {"q1": Q0, "q2": Q1},
             {"q1": "numbers", "q2": "numbers"}),
    ], (ob, np, st)
