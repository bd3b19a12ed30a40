#!/usr/bin/env python3
"""Benchmark: planning time of RRTConnect on the C++ OMPL validators
(bindings/ompl/polyccd_ompl.hpp, no Python per check) against plainmp's planner and
polyccd.ompl from Python, on the problems of bench_planning.py, in one process:

  polyccd C++     OMPL 1.5's RRTConnect (the system libompl, which plainmp links too) on
                  Robot_checks: tests/bench/bench_planning_ompl.cpp, built as a shared
                  library (make bench-planning-ompl) and called through ctypes; the robot
                  and plates reach it as tests/ompl/scene_file.py's file;
  polyccd.ompl    polyccd.ompl.RobotSpace (lean validators) with PyPI ompl's RRTConnect,
                  a Python callback per check (bench_planning.py's "polyccd");
  plainmp R       plainmp 0.3.6's RRTConnect, its spheres, its box motion validator at R
                  rad (tests/bench/plainmp_side.py; PLAINMP_SITE: its site-packages).

Queries: bench_planning.queries (the example's over the wall, below the shelf, and
seeded variations; --slot: the first query ends in a slot 16 mm wider than the hand,
planning_slot.py). Each query is planned --runs times by every method in turn. Time: the
solve alone (the C++ side times it inside; the Python sides around the call), wall and
CPU; then both polyccd sides simplify with OMPL's checked simplifiers (not counted). Every
returned path is checked by polyccd along the path its planner executes: exactly
(Robot.check_path, polyccd's joint path through the waypoints) and densely (exact static
checks of poses every --dense rad: polyccd's joint path for the polyccd sides, the linear
path for plainmp). A benchmark: it never asserts. Run (after make bench-planning-ompl):
  PLAINMP_SITE=... .venv/bin/python tests/bench/bench_planning_cpp.py --queries 10 --runs 3 --slot
"""
import argparse
import ctypes
import json
import os
import random
import statistics
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "examples"))
sys.path.insert(0, os.path.join(ROOT, "tests", "ompl"))
D = ctypes.POINTER(ctypes.c_double)


class CppSide:
    """The C++ planner of one scene file, through ctypes."""

    def __init__(self, lib_path, scene, seed, check_seconds, dims):
        lib = ctypes.CDLL(lib_path)
        lib.bench_planning_seed.argtypes = [ctypes.c_ulong]
        lib.bench_planning_open.restype = ctypes.c_void_p
        lib.bench_planning_open.argtypes = [ctypes.c_char_p, ctypes.c_double, ctypes.c_int]
        lib.bench_planning_error.restype = ctypes.c_char_p
        lib.bench_planning_plan.argtypes = [ctypes.c_void_p, D, D, ctypes.c_double, D,
                                            ctypes.POINTER(ctypes.c_ulonglong), D, ctypes.c_size_t,
                                            ctypes.POINTER(ctypes.c_size_t)]
        lib.bench_planning_close.argtypes = [ctypes.c_void_p]
        lib.bench_planning_seed(seed)
        self.lib, self.dims = lib, dims
        self.handle = lib.bench_planning_open(scene.encode(), check_seconds, 0)
        if not self.handle:
            raise SystemExit(f"bench_planning_cpp: {lib.bench_planning_error().decode()}")

    def plan(self, start, goal, seconds, cap=4096):
        times, counts = (ctypes.c_double * 4)(), (ctypes.c_ulonglong * 3)()
        out, n = (ctypes.c_double * (cap * self.dims))(), ctypes.c_size_t()
        a = (ctypes.c_double * self.dims)(*start)
        b = (ctypes.c_double * self.dims)(*goal)
        rc = self.lib.bench_planning_plan(self.handle, a, b, seconds, times, counts, out, cap,
                                          ctypes.byref(n))
        if rc < 0:
            raise SystemExit(f"bench_planning_cpp: {self.lib.bench_planning_error().decode()}")
        path = None if rc == 0 else np.array(out[:min(n.value, cap) * self.dims]).reshape(-1, self.dims)
        return path, times[0], times[1], dict(states=counts[0], motions=counts[1], errors=counts[2])


def python_plan(space, start, goal, seconds):
    """polyccd.ompl: (waypoints or None, solve wall s, solve CPU s, counts)."""
    from ompl import geometric as og
    from polyccd.ompl import simplify
    before = {k: v[0] for k, v in space.counts.items()}
    ss = og.SimpleSetup(space.si)
    ss.setStartAndGoalStates(space.state(start), space.state(goal))
    ss.setPlanner(og.RRTConnect(space.si))
    w0, c0 = time.perf_counter(), time.process_time()
    ok = bool(ss.solve(seconds)) and ss.haveExactSolutionPath()
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    counts = {f"{k}s": space.counts[k][0] - before[k] for k in space.counts}  # the solve's
    path = None
    if ok:
        p = ss.getSolutionPath()
        simplify(space.si, p)
        path = np.array(space.waypoints(p))[:, space._index]
    return path, wall, cpu, counts


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n\n")[0])
    ap.add_argument("--queries", type=int, default=10)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--seed", type=int, default=20261125)
    ap.add_argument("--time", type=float, default=30.0, help="planning budget per plan (s)")
    ap.add_argument("--resolution", type=float, nargs="+", default=[0.05], help="plainmp's (rad)")
    ap.add_argument("--spread", type=float, default=0.4)
    ap.add_argument("--dense", type=float, default=0.002, help="dense check step (rad)")
    ap.add_argument("--check-seconds", type=float, default=10.0)
    ap.add_argument("--slot", action="store_true", help="the first query ends in a slot")
    ap.add_argument("--lib", default=os.path.join(ROOT, "build", "bench", "libbench_planning_ompl.so"))
    ap.add_argument("--json", help="write the runs here")
    ap.add_argument("--from-json", help="print the table of an earlier --json file")
    args = ap.parse_args(argv)
    if args.from_json:
        with open(args.from_json) as f:
            summarize(json.load(f)["runs"])
        return 0
    if not os.path.exists(args.lib):
        print(f"bench_planning_cpp: skipped ({args.lib} is not built: make bench-planning-ompl)")
        return 0
    import planning_slot
    if not planning_slot.ompl_ready("bench_planning_cpp", args.seed, ["yourdfpy"]):
        return 0
    import polyccd as P
    from polyccd.apps._demo_robot import PANDA_URDF, example_robot_file
    from polyccd.ompl import RobotSpace
    import ompl_panda as ex
    import scene_file
    from bench_planning import linear_path, plainmp_planners, queries
    robot, plates, boxes, slot_goal, _ = planning_slot.problem(args.seed, args.slot)
    fixed = {"panda_finger_joint1": ex.FINGER}
    options = dict(self_collision=False, limits=P.Limits(max_seconds=args.check_seconds),
                   first_contact=False)
    rspace = RobotSpace(robot, plates, fixed=fixed, **options)
    qs = queries(robot, rspace, plates, args.queries, random.Random(args.seed), args.spread)
    if slot_goal is not None:
        qs = [(qs[0][0], slot_goal)] + qs[1:]
    qs = [(a[rspace._index], b[rspace._index]) for a, b in qs]  # the 7 planned joints
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "scene.txt")
        scene_file.write(path, robot, plates, rspace.joints, fixed, qs)
        cpp = CppSide(args.lib, path, args.seed, args.check_seconds, len(rspace.joints))
    sides = {"polyccd C++": cpp, "polyccd.ompl": rspace}
    sides.update(plainmp_planners(argparse.Namespace(no_plainmp=False, resolution=args.resolution,
                                                     time=args.time),
                                  example_robot_file(PANDA_URDF), boxes))
    full = lambda q: np.append(q, ex.FINGER)  # noqa: E731
    print(f"bench_planning_cpp: Panda, wall + shelf{' + slot' if args.slot else ''}, {len(qs)} "
          f"queries x {args.runs} runs, {', '.join(sides)}; load {os.getloadavg()[0]:.1f}", flush=True)
    runs = []
    for qi, (start, goal) in enumerate(qs):
        for run in range(args.runs):
            for method, side in sides.items():
                counts = {}
                if side is cpp:
                    path, wall, cpu, counts = cpp.plan(start, goal, args.time)
                elif side is rspace:
                    path, wall, cpu, counts = python_plan(rspace, full(start), full(goal), args.time)
                else:
                    w0, c0 = time.perf_counter(), time.process_time()
                    path, own = side.plan(start, goal)
                    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
                    counts = {"own_seconds": own}
                row = dict(query=qi, run=run, method=method, solved=path is not None,
                           wall=wall, cpu=cpu, **counts)
                if path is not None:
                    w = [full(q) for q in path]
                    row["waypoints"] = len(w)
                    row["exact_collides"] = robot.check_path(w, plates, self_collision=False,
                                                             first_contact=False).segment is not None
                    poses = (rspace.interpolate_path(w, args.dense) if method.startswith("polyccd")
                             else linear_path(w, args.dense))
                    dense = robot.check_states(np.array(poses), plates, self_collision=False,
                                               joint_limits="ignore")
                    row["dense_poses"] = len(poses)
                    row["dense_collides"] = bool(dense.collides.any() or not dense.ok.all())
                runs.append(row)
                print(f"  query {qi} run {run} {method:<13} {'solved' if path is not None else 'FAILED'}"
                      f" {1e3 * wall:9.2f} ms wall {1e3 * cpu:9.2f} ms CPU"
                      + (f", {row['waypoints']} waypoints, collides: exact {row['exact_collides']}, "
                         f"dense {row['dense_collides']}" if path is not None else ""), flush=True)
    print(f"load after: {os.getloadavg()}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"args": vars(args), "runs": runs}, f, indent=1)
    summarize(runs)
    return 0


def summarize(runs):
    rows, base = [], None
    print(f"\n{'method':<14} {'solved':>7} {'wall med ms':>11} {'mean':>8} {'max':>8} {'CPU med ms':>10} "
          f"{'/ plainmp: wall':>15} {'CPU':>6} {'colliding: exact':>16} {'dense':>6}")
    for method in dict.fromkeys(r["method"] for r in runs):
        mine = [r for r in runs if r["method"] == method]
        ok = [r for r in mine if r["solved"]]
        wall, cpu = [r["wall"] for r in mine], [r["cpu"] for r in mine]
        row = dict(method=method, solved=len(ok), plans=len(mine),
                   wall_median=statistics.median(wall), wall_mean=statistics.mean(wall),
                   wall_max=max(wall), cpu_median=statistics.median(cpu),
                   exact_colliding=sum(r["exact_collides"] for r in ok),
                   dense_colliding=sum(r["dense_collides"] for r in ok))
        if "own_seconds" in mine[0]:
            own = [r["own_seconds"] for r in mine if r["own_seconds"] is not None]
            row["own_median"] = statistics.median(own) if own else float("nan")
        for kind in ("states", "motions"):  # checks during the solve, mean per plan
            if kind in mine[0]:
                row[f"{kind}_per_plan"] = statistics.mean(r[kind] for r in mine)
        if "states" in mine[0]:  # CPU per check in the solve, all plans together
            row["cpu_us_per_check"] = 1e6 * sum(cpu) / max(1, sum(r["states"] + r["motions"] for r in mine))
        if base is None and method.startswith("plainmp"):
            base = row
        rows.append(row)
    for row in rows:
        ratio = (f"{row['wall_median'] / base['wall_median']:14.1f}x "
                 f"{row['cpu_median'] / base['cpu_median']:5.1f}x" if base else f"{'-':>15} {'-':>6}")
        print(f"{row['method']:<14} {row['solved']:>3} / {row['plans']:<3} {1e3 * row['wall_median']:11.2f} "
              f"{1e3 * row['wall_mean']:8.2f} {1e3 * row['wall_max']:8.1f} {1e3 * row['cpu_median']:10.2f} "
              f"{ratio} {row['exact_colliding']:>10} / {row['solved']:<3} {row['dense_colliding']:>3} / {row['solved']}")
    for row in rows:
        extra = [f"{k} {v:.1f}" for k, v in row.items() if k.endswith(("_per_plan", "_per_check"))]
        if "own_median" in row:
            extra.append(f"plainmp's own time_elapsed median {1e3 * row['own_median']:.2f} ms")
        if extra:
            print(f"{row['method']}: " + ", ".join(extra))
    print("wall / CPU: the solve (failed plans at their budget); C++: timed inside, this thread's "
          "CPU; Python sides: around the call, the process's CPU. colliding: returned paths "
          "(of the solved) in contact along the executed path, by polyccd's exact check_path "
          "and by exact static checks every --dense rad (plainmp: its linear path)")
    return rows


if __name__ == "__main__":
    sys.exit(main())
