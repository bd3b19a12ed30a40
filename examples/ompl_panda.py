#!/usr/bin/env python3
"""Plans the Franka Panda around two thin plates with OMPL's RRTConnect, every edge
validated by polyccd's exact check (polyccd.ompl), then checks the returned path twice:
by polyccd (Robot.check_path: every segment of the joint path, exactly) and by dense
sampling (exact static checks of the poses every --step rad along the same joint path).

The scene: a 2 mm wall standing in the plane y = 0 (x 0.25 to 0.75 m, up to z = 0.45 m)
between the start (gripper low on the y < 0 side) and the goal (its mirror image, y > 0),
and a 2 mm shelf at z = 0.85 m above the wall: the arm has to lift its hand over the wall
and below the shelf. The straight joint path from start to goal hits the wall. Robot
versus plates; self-collision is off (--self-collision turns it on: slower).

Needs the "ompl" extra and the robot packages: pip install "polyccd[ompl]"
example-robot-data, once polyccd is installed (tests/requirements.txt has them). Run:
    .venv/bin/python examples/ompl_panda.py [--time 60] [--seed 1]
Prints the planning time, the checks made, the path and both verdicts; exits 1 when no
path was found or a check of the returned path fails.
"""
import argparse
import sys
import time

import numpy as np

FINGER = 0.02   # the finger opening (m), fixed: the 7 arm joints are planned
WALL = ((0.25, -0.001, 0.0), (0.75, 0.001, 0.45))
SHELF = ((0.2, -0.3, 0.85), (0.7, 0.3, 0.852))
# (start, goal) arm joints: joint 1 (the base yaw) at -0.9 / +0.9, the hand at z 0.13 to
# 0.27 m, 0.45 m from the base axis on either side of the wall.
START = (-0.9, 0.3, 0.0, -2.2, 0.0, 2.5, 0.785)
GOAL = (0.9, 0.3, 0.0, -2.2, 0.0, 2.5, 0.785)
BOX_TRIANGLES = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                 [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]


def plate(lo, hi, name):
    """The box [lo, hi] (decimal texts of the doubles, taken exactly) as a polyccd Body."""
    import polyccd
    v = [[repr(float((lo[a], hi[a])[(i >> a) & 1])) for a in range(3)] for i in range(8)]
    return polyccd.Body(polyccd.Mesh(v, BOX_TRIANGLES), name=name)


def scene():
    """(robot, plates): the Panda of example-robot-data read by polyccd.robot.load_urdf."""
    from polyccd.apps._demo_robot import PANDA_URDF, example_robot_file
    from polyccd.robot import load_urdf
    path = example_robot_file(PANDA_URDF)
    if path is None:
        raise SystemExit("ompl_panda: example-robot-data is not installed "
                         "(pip install example-robot-data)")
    return load_urdf(path), [plate(*WALL, "wall"), plate(*SHELF, "shelf")]


def decide_options(robot):
    """{"first_contact": False} when Robot.check has a decide mode (the edge check needs
    only "does anything touch?"; the last-valid form asks for the time anyway), else {}."""
    import inspect
    return ({"first_contact": False}
            if "first_contact" in inspect.signature(robot.check).parameters else {})


def plan(space, start, goal, seconds, simplify=True):
    """RRTConnect from start to goal (arm joint vectors) on a polyccd.ompl.RobotSpace:
    (waypoints or None, planning seconds, simplifying seconds)."""
    from ompl import geometric as og
    ss = space.simple_setup()
    ss.setStartAndGoalStates(space.state(start), space.state(goal))
    ss.setPlanner(og.RRTConnect(space.si))
    t0 = time.perf_counter()
    solved = ss.solve(seconds) and ss.haveExactSolutionPath()
    planning = time.perf_counter() - t0
    if not solved:
        return None, planning, 0.0
    path = ss.getSolutionPath()
    t0 = time.perf_counter()
    if simplify:
        space.simplify(path)
    return space.waypoints(path), planning, time.perf_counter() - t0


def dense_free(robot, space, waypoints, obstacles, step, **options):
    """(poses checked, first colliding pose index or None): exact static checks of the
    poses every `step` rad along polyccd's joint path through the waypoints."""
    poses = space.interpolate_path(waypoints, step)
    for i, q in enumerate(poses):
        if robot.check(q, q, obstacles, **options).collides:
            return len(poses), i
    return len(poses), None


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n\n")[0])
    ap.add_argument("--time", type=float, default=60.0, help="planning time budget (s)")
    ap.add_argument("--seed", type=int, default=1, help="OMPL's random seed")
    ap.add_argument("--step", type=float, default=0.01,
                    help="dense sampling step along the path (rad, largest joint change)")
    ap.add_argument("--check-seconds", type=float, default=10.0,
                    help="time limit of one exact check (polyccd.Limits; a check that "
                    "reaches it rejects the edge)")
    ap.add_argument("--self-collision", action="store_true")
    ap.add_argument("--no-simplify", action="store_true")
    args = ap.parse_args(argv)
    try:
        from ompl import util as ou
    except ImportError:
        raise SystemExit('ompl_panda: needs the "ompl" extra: pip install "polyccd[ompl]" '
                         '(adds it to this installed polyccd)')
    ou.setLogLevel(ou.LogLevel.LOG_WARN)
    ou.RNG.setSeed(args.seed)  # before any OMPL sampler exists
    import polyccd
    from polyccd.ompl import RobotSpace
    robot, plates = scene()
    options = dict(self_collision=args.self_collision,
                   limits=polyccd.Limits(max_seconds=args.check_seconds), **decide_options(robot))
    space = RobotSpace(robot, plates, fixed={"panda_finger_joint1": FINGER}, **options)
    start, goal = np.array(START + (FINGER,)), np.array(GOAL + (FINGER,))
    straight = robot.check(start, goal, plates, self_collision=args.self_collision)
    print(f"ompl_panda: Panda ({len(robot.shapes)} collision meshes), plates wall + shelf "
          f"(2 mm), self-collision {'on' if args.self_collision else 'off'}, "
          f"{'decide' if options.get('first_contact') is False else 'first-contact'} mode; "
          f"the straight "
          f"joint path {'hits ' + straight.contacts[0].b[0] if straight.collides else 'is free'}"
          + (f" at t ~ {straight.first_contact.approx:.4f}" if straight.collides else ""))
    waypoints, planning, simplifying = plan(space, start, goal, args.time,
                                            not args.no_simplify)
    c = space.counts
    print(f"RRTConnect (seed {args.seed}): {'solved' if waypoints else 'NO PATH'} in "
          f"{planning:.1f} s; simplified in {simplifying:.1f} s; exact checks: "
          f"{c['state'][0]} states ({c['state'][2]:.1f} s), {c['motion'][0]} motions "
          f"({c['motion'][1]} colliding, {c['motion'][2]:.1f} s); checks that hit the "
          f"{args.check_seconds:g} s limit: {len(space.errors)}")
    if not waypoints:
        return 1
    for i, q in enumerate(waypoints):
        print(f"  waypoint {i}: [{', '.join(f'{x:+.4f}' for x in q[:7])}]")
    t0 = time.perf_counter()
    exact = space.check_path(waypoints, limits=None)  # no time limit: a verdict
    t1 = time.perf_counter()
    n, hit = dense_free(robot, space, waypoints, plates, args.step,
                        self_collision=args.self_collision)
    t2 = time.perf_counter()
    print(f"polyccd check of every segment ({len(waypoints) - 1}): "
          f"{'FREE' if exact.segment is None else f'COLLIDES in segment {exact.segment}'} "
          f"({t1 - t0:.1f} s)")
    print(f"dense sampling, {n} poses every {args.step:g} rad along the same joint path, "
          f"each checked exactly: {'FREE' if hit is None else f'COLLIDES at pose {hit}'} "
          f"({t2 - t1:.1f} s)")
    return 0 if exact.segment is None and hit is None else 1


if __name__ == "__main__":
    sys.exit(main())
