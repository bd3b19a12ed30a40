#!/usr/bin/env python3
"""Benchmark: motion planning of the Franka Panda among thin plates with OMPL's RRTConnect,
the same planner under different edge checks, and plainmp's planner:

  polyccd   polyccd.ompl.RobotSpace: every state by polyccd's exact static check, every
            edge by Robot.check over polyccd's joint path (the half-angle interpolation);
            each check capped by polyccd.Limits(max_seconds=--check-seconds), a check that
            reaches it rejecting the edge;
  discrete  OMPL's own DiscreteMotionValidator (the SpaceInformation's default) at 0.05 rad:
            states every 0.05 rad of joint-space distance (L2, OMPL's validSegmentCount)
            along OMPL's linear interpolation, each checked by python-fcl (BVHModels of the
            same link meshes and plates, link poses by Pinocchio: bench_robot.Discrete);
  plainmp   (when importable: tests/bench/plainmp_side.py) plainmp 0.3.6's own RRTConnect,
            its sphere model and box motion validator at each --resolution, its C++ loop;
  polyccd callback  (--callback) the polyccd space checking through Robot.check per OMPL
            callback, the path before the lean validators (and a line of CPU us per
            callback of both on the same states and edges).
--slot adds a narrow passage (tests/bench/planning_slot.py): two upright plates 8 mm on
either side of the hand at a goal pose; the first query ends there.

Both plan the 7 arm joints (fingers at 0.02 m) within the URDF limits, robot versus
plates (no self-collision on either side), then simplify with the same checked
simplifiers (polyccd.ompl.simplify: reduceVertices, collapseCloseVertices). Queries: the
example's (examples/ompl_panda.py: over a 2 mm wall, below a 2 mm shelf) and --queries - 1
random variations of it (every arm joint of start and goal moved by up to --spread rad,
seeded): start and goal free, the straight path between them colliding.
Each query is planned --runs times by each method (OMPL is seeded once per process,
--seed; runs continue its random stream, the methods alternate).

Each returned path is then checked along the path its planner executes:
  by polyccd  Robot.check_path over the waypoints (exact; this is polyccd's joint path,
              which for the discrete planner's waypoints differs from the linear
              interpolation it executes by up to a few hundredths of a rad mid-segment);
  by dense sampling  FCL at poses every --dense rad (largest joint change) along the
              executed path: polyccd's joint path for polyccd, linear for discrete.
Reported per method: success rate, planning time (solve; and with simplifying), edges
checked, and how many returned paths collide by each check. A benchmark: it never
asserts. Run: .venv/bin/python tests/bench/bench_planning.py [--plot docs/bench_planning.png]
"""
import argparse
import json
import math
import os
import random
import statistics
import sys
import time
import weakref

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "examples"))


def linear_path(waypoints, step):
    """Poses every `step` rad (largest joint change) along the linear interpolation."""
    out = [waypoints[0]]
    for a, b in zip(waypoints, waypoints[1:]):
        n = max(1, math.ceil(float(np.max(np.abs(b - a))) / step))
        out.extend(a + (b - a) * (k / n) for k in range(1, n + 1))
    return out


class DiscreteSpace:
    """OMPL's RealVectorStateSpace over the same joints, FCL state validity, OMPL's default
    DiscreteMotionValidator at `resolution` rad."""

    def __init__(self, rspace, fcl_side, resolution):
        from ompl import base as ob
        from polyccd.ompl import joint_space
        self.space = joint_space(rspace.joints, rspace.bounds)  # the same space, OMPL's own checks
        self.si = ob.SpaceInformation(self.space)
        self.rspace, self.fcl = rspace, fcl_side
        self.counts = {"state": [0, 0, 0.0]}
        me = weakref.proxy(self)  # no reference cycle through OMPL's SpaceInformation
        self.si.setStateValidityChecker(lambda state: me._valid(state))
        # longest valid segment = fraction * maximum extent = resolution (rad, L2)
        self.si.setStateValidityCheckingResolution(resolution / self.space.getMaximumExtent())
        self.si.setup()

    def _valid(self, state):
        t0 = time.perf_counter()
        hit = self.fcl.pose_collides(self.rspace.q(state))
        c = self.counts["state"]
        c[0], c[1], c[2] = c[0] + 1, c[1] + hit, c[2] + time.perf_counter() - t0
        return not hit

    def state(self, q):
        return self.rspace.state(q, self.si.allocState())


class PlainmpSide:
    """plainmp's own RRTConnect (its sphere model, its box motion validator at a
    resolution, its C++ loop: tests/bench/plainmp_side.py) on the same wall and shelf."""

    def __init__(self, plan):
        self.plan, self.counts = plan, {}


def plainmp_planners(args, urdf, boxes):
    """{"plainmp R": PlainmpSide} for R in --resolution, or {} (a line says why)."""
    if args.no_plainmp:
        return {}
    import plainmp_side
    mods, why = plainmp_side.load()
    if mods is None:
        print(f"bench_planning: plainmp skipped ({why})")
        return {}
    spec, cst = plainmp_side.panda(mods, urdf, boxes, False)
    return {f"plainmp {r}": PlainmpSide(plainmp_side.planner(mods, spec, cst, r, args.time))
            for r in args.resolution}


def callback_cost(lean, legacy, rng, n=300):
    """CPU us per isValid / checkMotion callback of the lean path and of Robot.check per
    callback, on the same random states and short edges (0.1 rad a joint), interleaved."""
    lo, hi = np.array(lean.bounds).T
    times = {"lean": [0.0, 0.0], "Robot.check": [0.0, 0.0]}
    for _ in range(n):
        s0 = np.array([rng.uniform(a, b) for a, b in zip(lo, hi)])
        s1 = np.clip(s0 + np.array([rng.uniform(-0.1, 0.1) for _ in s0]), lo, hi)
        a, b = lean.state(s0), lean.state(s1)
        for name, space in (("lean", lean), ("Robot.check", legacy)):
            for i, call in enumerate((lambda: space.validity_checker.isValid(a),
                                      lambda: space.motion_validator.checkMotion(a, b))):
                t0 = time.process_time()
                call()
                times[name][i] += time.process_time() - t0
    print("callbacks, CPU us each (same states and edges, interleaved): " + ", ".join(
        f"{k} isValid {1e6 * v[0] / n:.0f} checkMotion {1e6 * v[1] / n:.0f}" for k, v in times.items()))


def plan(si, state, start, goal, seconds, simplify):
    from ompl import geometric as og
    ss = og.SimpleSetup(si)
    ss.setStartAndGoalStates(state(start), state(goal))
    ss.setPlanner(og.RRTConnect(si))
    t0 = time.perf_counter()
    ok = bool(ss.solve(seconds)) and ss.haveExactSolutionPath()
    solve = time.perf_counter() - t0
    if not ok:
        return None, solve, solve
    path = ss.getSolutionPath()
    simplify(si, path)
    return path, solve, time.perf_counter() - t0


def queries(robot, rspace, plates, n, rng, spread):
    """The example's query, then random variations of it (each arm joint of start and goal
    moved by up to `spread` rad, within the limits): both ends free, the straight path
    colliding."""
    import ompl_panda as ex
    out = [(np.array(ex.START + (ex.FINGER,)), np.array(ex.GOAL + (ex.FINGER,)))]
    lo, hi = np.array(rspace.bounds).T
    while len(out) < n:
        a, b = (np.append(np.clip(np.array(q) + [rng.uniform(-spread, spread) for _ in q],
                                  lo, hi), ex.FINGER) for q in (ex.START, ex.GOAL))
        if (rspace.is_valid(a) and rspace.is_valid(b)
                and robot.check(a, b, plates, self_collision=False).collides):
            out.append((a, b))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n\n")[0])
    ap.add_argument("--queries", type=int, default=3)
    ap.add_argument("--runs", type=int, default=3, help="plans per query and method")
    ap.add_argument("--seed", type=int, default=20261125)
    ap.add_argument("--time", type=float, default=60.0, help="planning budget per plan (s)")
    ap.add_argument("--resolution", type=float, nargs="+", default=[0.05],
                    help="the discrete sides' resolutions (rad; default 0.05)")
    ap.add_argument("--spread", type=float, default=0.4, help="query variations (rad)")
    ap.add_argument("--dense", type=float, default=0.002, help="dense sampling step (rad)")
    ap.add_argument("--check-seconds", type=float, default=10.0)
    ap.add_argument("--callback", action="store_true",
                    help="also polyccd through Robot.check per OMPL callback (before the lean path)")
    ap.add_argument("--no-plainmp", action="store_true", help="leave plainmp's planner out")
    ap.add_argument("--slot", action="store_true",
                    help="add a slot 16 mm taller than the hand; the first query ends in it")
    ap.add_argument("--json", help="write the runs here")
    ap.add_argument("--plot", help="write a PNG of the table here")
    ap.add_argument("--from-json", help="print and plot the runs of an earlier --json file")
    args = ap.parse_args(argv)
    if args.from_json:
        with open(args.from_json) as f:
            runs = json.load(f)["runs"]
        table = summarize(runs, args)
        if args.plot:
            plot(table, args.plot, args)
        return 0
    import planning_slot  # the narrow passage: a slot around the hand at a goal
    if not planning_slot.ompl_ready("bench_planning", args.seed, ["fcl", "pinocchio", "yourdfpy"]):
        return 0
    import polyccd as P
    from polyccd.apps._demo_robot import PANDA_URDF, example_robot_file
    from polyccd.ompl import RobotSpace, simplify
    import ompl_panda as ex
    from bench_robot import Discrete
    robot, plates, boxes, slot_goal, more = planning_slot.problem(args.seed, args.slot)
    if args.slot:
        print(f"slot: {', '.join(f'{n} {np.round(a, 4).tolist()} - {np.round(b, 4).tolist()}' for n, a, b in more)}"
              f" (8 mm each side of the hand at the first query's goal)")
    fcl_side = Discrete(robot, example_robot_file(PANDA_URDF), boxes)
    options = dict(self_collision=False, limits=P.Limits(max_seconds=args.check_seconds),
                   **ex.decide_options(robot))
    rspace = RobotSpace(robot, plates, fixed={"panda_finger_joint1": ex.FINGER}, **options)
    sides = {"polyccd": rspace}
    if args.callback:  # the same space checking through Robot.check per callback
        legacy = RobotSpace(robot, plates, fixed={"panda_finger_joint1": ex.FINGER}, **options)
        legacy._lean = False
        sides["polyccd callback"] = legacy
    for r in args.resolution:
        sides[f"discrete {r}"] = DiscreteSpace(rspace, fcl_side, r)
    sides.update(plainmp_planners(args, example_robot_file(PANDA_URDF), boxes))
    rng = random.Random(args.seed)
    if args.callback:
        callback_cost(rspace, legacy, random.Random(args.seed))
    qs = queries(robot, rspace, plates, args.queries, rng, args.spread)
    if slot_goal is not None:  # the slot's query replaces the example's: its start into the slot
        qs = [(qs[0][0], slot_goal)] + qs[1:]
    print(f"bench_planning: Panda, wall + shelf (2 mm), {len(qs)} queries x {args.runs} runs, "
          f"polyccd {'decide' if options.get('first_contact') is False else 'first-contact'} "
          f"mode, "
          f"RRTConnect {args.time:g} s budget; discrete at {' / '.join(map(str, args.resolution))} rad; dense "
          f"sampling every {args.dense} rad; seed {args.seed}", flush=True)
    runs = []
    for qi, (start, goal) in enumerate(qs):
        for run in range(args.runs):
            for method, side in sides.items():
                before = {k: list(v) for k, v in side.counts.items()}
                if isinstance(side, PlainmpSide):  # its own planner and checks, no simplifying
                    t0 = time.perf_counter()
                    path = side.plan(start[:7], goal[:7])[0]
                    solve = total = time.perf_counter() - t0
                    path = None if path is None else [np.append(q, ex.FINGER) for q in path]
                else:
                    path, solve, total = plan(side.si, side.state, start, goal, args.time, simplify)
                row = dict(query=qi, run=run, method=method, solved=path is not None,
                           solve=solve, total=total)
                for kind in side.counts:
                    row[f"{kind}s"] = side.counts[kind][0] - before[kind][0]  # checks made
                    row[f"{kind}_seconds"] = side.counts[kind][2] - before[kind][2]
                if path is not None:
                    w = rspace.waypoints(path)
                    row["waypoints"] = len(w)
                    exact = robot.check_path(w, plates, self_collision=False)
                    row["polyccd_collides"] = exact.segment is not None
                    row["path"] = [[float(x) for x in q] for q in w]
                    half = rspace.interpolate_path(w, args.dense)
                    poses = half if method.startswith("polyccd") else linear_path(w, args.dense)
                    row["dense_poses"] = len(poses)
                    row["dense_collides"] = any(fcl_side.pose_collides(q) for q in poses)
                    # the same waypoints joined by polyccd's joint path, sampled likewise:
                    # polyccd's verdict and FCL's on one path
                    row["dense_half_angle_collides"] = (
                        row["dense_collides"] if method.startswith("polyccd")
                        else any(fcl_side.pose_collides(q) for q in half))
                runs.append(row)
                print(f"  query {qi} run {run} {method:<13} "
                      + ("solved" if path is not None else "FAILED")
                      + f" {solve:7.2f} s (+simplify {total - solve:6.2f} s)"
                      + (f", {row['waypoints']} waypoints, collides: polyccd "
                         f"{row['polyccd_collides']}, dense {row['dense_collides']}"
                         if path is not None else ""), flush=True)
    table = summarize(runs, args)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"args": vars(args), "runs": runs, "table": table}, f, indent=1)
    if args.plot:
        plot(table, args.plot, args)
    return 0


def summarize(runs, args):
    rows = []
    print(f"\n{'method':<22} {'solved':>8} {'solve s med':>11} {'mean':>7} {'max':>7} "
          f"{'+simplify med':>13} {'colliding paths: polyccd':>24} {'dense':>6} "
          f"{'dense (half-angle)':>18}")
    for method in dict.fromkeys(r["method"] for r in runs):
        mine = [r for r in runs if r["method"] == method]
        ok = [r for r in mine if r["solved"]]
        solve = [r["solve"] for r in mine]
        total = [r["total"] for r in ok] or [float("nan")]
        name = {"polyccd": "polyccd exact", "polyccd callback": "polyccd, Robot.check"}.get(
            method, f"{method} rad ({'plainmp' if method.startswith('plainmp') else 'FCL'})")
        row = dict(method=name, solved=len(ok), plans=len(mine),
                   solve_median=statistics.median(solve), solve_mean=statistics.mean(solve),
                   solve_max=max(solve), total_median=statistics.median(total),
                   polyccd_colliding=sum(r["polyccd_collides"] for r in ok),
                   dense_colliding=sum(r["dense_collides"] for r in ok),
                   dense_half_angle=sum(r.get("dense_half_angle_collides", False) for r in ok))
        for kind in ("state", "motion"):  # wall us per check, all plans together
            n = sum(r.get(f"{kind}s", 0) for r in mine)
            row[f"{kind}_us"] = 1e6 * sum(r.get(f"{kind}_seconds", 0) for r in mine) / n if n else None
        rows.append(row)
        print(f"{name:<22} {len(ok):>3} / {len(mine):<2} {row['solve_median']:11.2f} "
              f"{row['solve_mean']:7.2f} {row['solve_max']:7.2f} {row['total_median']:13.2f} "
              f"{row['polyccd_colliding']:>18} / {len(ok):<3} {row['dense_colliding']:>4} / {len(ok):<3}"
              f"{row['dense_half_angle']:>12} / {len(ok)}")
    for row in rows:
        if row.get("state_us"):
            print(f"{row['method']}: us per check (wall), state {row['state_us']:.0f}"
                  + (f", motion {row['motion_us']:.0f}" if row.get("motion_us") else ""))
    print("solve: RRTConnect's solve() (s, failed plans included at their budget); "
          "+simplify: solve and the checked simplifiers; colliding paths: returned paths "
          "(of the solved ones) in contact with a plate somewhere along the path executed "
          "(polyccd: its check of the waypoints joined by polyccd's joint path; dense: FCL "
          "every --dense rad along the executed path; dense (half-angle): FCL along polyccd's "
          "joint path through the same waypoints, the path polyccd's verdict is about)")
    return rows


def plot(table, path, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [r["method"].replace("polyccd exact", "polyccd").replace("discrete ", "FCL ")
             .replace(" rad (FCL)", " rad") for r in table]
    fig, ax = plt.subplots(1, 3, figsize=(11, 3.4))
    colors = ["tab:blue", "tab:orange", "tab:red", "tab:brown", "tab:gray"][:len(names)]
    ax[0].bar(names, [r["solve_median"] for r in table], color=colors)
    ax[0].set_ylabel("median solve time (s, log)")
    ax[0].set_yscale("log")
    ax[1].bar(names, [r["solved"] / r["plans"] for r in table], color=colors)
    ax[1].set_ylabel("success rate")
    ax[1].set_ylim(0, 1.05)
    x = np.arange(len(names))
    ax[2].bar(x - 0.2, [r["polyccd_colliding"] for r in table], 0.4,
              label="by polyccd (half-angle path)")
    ax[2].bar(x + 0.2, [r["dense_colliding"] for r in table], 0.4,
              label=f"dense FCL {args.dense} rad (executed path)")
    ax[2].set_xticks(x, names)
    ax[2].set_ylabel(f"returned paths colliding (of {table[0]['plans']})")
    ax[2].set_ylim(0, max(2, max(max(r["polyccd_colliding"], r["dense_colliding"])
                                 for r in table) + 1))
    ax[2].legend(fontsize=8)
    for a in ax:
        a.tick_params(axis="x", labelsize=8)
    fig.suptitle(f"Panda RRTConnect among 2 mm plates: {table[0]['plans']} plans per method",
                 fontsize=10)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=110)
    print(f"plot: {path}")


if __name__ == "__main__":
    sys.exit(main())
