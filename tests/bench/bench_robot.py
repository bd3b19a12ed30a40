#!/usr/bin/env python3
"""Benchmark: a planner-like workload on real arms. N random joint-space segments of the
Franka Panda and of the UR5 (example-robot-data's URDFs, collision meshes and SRDFs)
among a few fixed obstacles (boxes and 2 mm plates), each checked by (--min-distance D: also
with min_distance=D, in the same run, and the ratio of the means printed)

  polyccd decide  Robot.check(q0, q1, obstacles, first_contact=False): does anything touch
                  on [0, 1]? (pccd_robot_check in decide mode: the links' interval poses
                  straight from the joint path filter the pairs, exact link motions only
                  for the pairs left, stop at the first certified contact);
  polyccd first   Robot.check(...): the exact first contact (the default);
  FCL discrete    python-fcl collision at a planner's resolution: poses t = k / m,
                  k = 0..m, m = ceil(largest joint change / RESOLUTION) (0.05 rad, typical
                  of planners; also 0.1 and 0.2 rad by default: --resolution), stopping
                  at the first colliding pose as a planner does; fcl.BVHModel (OBBRSS) of
                  the SAME triangles polyccd gets, one DynamicAABBTree manager per side;
                  link poses by Pinocchio's float FK (tests/bench/robot_fcl.py).

Self-collision off (robot versus obstacles) and on: then both sides skip the same link
pairs, the adjacent ones and the SRDF's disable_collisions (polyccd: load_urdf(srdf=...);
FCL: a self-collision pass of the robot's manager with those pairs skipped).

Both check the SAME path: polyccd's chains interpolate each revolute joint's half-angle
quaternion (cos, sin)(q/2) linearly (lib/motion/chain.cpp), so the joint values at t
are q0 + 2 atan2(C0 S - S0 C, C0 C + S0 S) with (C, S) interpolated; the discrete
check evaluates that formula in floats (printed: its largest difference from
Robot.joint_values, and Pinocchio's poses against polyccd's exact motions).

Segments: q0 uniform within the joint limits, q1 = q0 + uniform(-SPAN, SPAN) per joint
clipped to the limits (default SPAN 1 rad), the Panda's finger opening fixed at 0.02 m;
both ends must be collision-free (decided exactly by polyccd as a stationary robot, with
the mode's self-collision setting), as a planner's states are. Obstacles: BOXES boxes
(5 to 20 cm sides) and PLATES plates (2 mm thick, 10 to 30 cm wide) axis-aligned, centred
0.3 to 0.75 m from the base axis at heights 0.1 to 0.8 m; all seeded (--seed).

Times: CPU time of the process by default (time.process_time: on a shared, loaded
machine wall time mostly measures waiting for a core; both sides are single-threaded
here), wall time with --clock wall.

Reported per arm and self-collision setting: time per segment (mean, median, max) of
each method, segments each reports colliding, MISSES (polyccd collides, discrete free),
and counts that must be 0, printed loudly when not: decide and first-contact modes
disagreeing, discrete collisions polyccd does not report, and discrete first colliding
poses earlier than polyccd's first contact. At the end a markdown table of the ratios
(docs/benchmarks-robots.md). A benchmark: it never asserts and is not in make test. `make
bench` runs it; alone: .venv/bin/python tests/bench/bench_robot.py --n 200
"""
import argparse
import random
import statistics
import sys
import time

import numpy as np

from robot_fcl import BOX_TRIANGLES, FINGER, Discrete, agreement, box_vertices, make_obstacles

ARMS = {"panda": ("panda_description/urdf/panda.urdf", "panda_description/srdf/panda.srdf"),
        "ur5": ("ur_description/urdf/ur5_robot.urdf", "ur_description/srdf/ur5.srdf")}


def ms(values):
    return (f"{1e3 * statistics.mean(values):9.2f} {1e3 * statistics.median(values):9.2f} "
            f"{1e3 * max(values):9.2f}")


def run_arm(P, load_urdf, example_robot_file, name, self_collision, args, summary):
    """One arm, one self-collision setting: the segments, the table, rows for summary."""
    clock = time.process_time if args.clock == "cpu" else time.perf_counter
    urdf, srdf = (example_robot_file(f) for f in ARMS[name])
    robot = load_urdf(urdf, srdf=srdf)
    allowed = robot.adjacent_pairs() | robot.allowed_from_srdf(srdf)
    rng = random.Random(args.seed)
    boxes = make_obstacles(rng, args.boxes, args.plates)
    obstacles = [P.Body(P.Mesh(box_vertices(lo, hi), BOX_TRIANGLES), name=n) for n, lo, hi in boxes]
    discrete = Discrete(robot, urdf, boxes, allowed if self_collision else None)
    lims = [robot.limits[n] or (-np.pi, np.pi) for n in robot.joints]
    if name == "panda":
        lims[-1] = (FINGER, FINGER)
    dq, dx = agreement(robot, discrete, rng, lims)
    sc = "on" if self_collision else "off"
    print(f"\n{name}: {len(robot.shapes)} collision meshes, "
          f"{sum(len(s.triangles) for *_, s in robot.shapes)} triangles; self-collision {sc}"
          f"{f' ({len(allowed)} link pairs allowed: adjacent + SRDF)' if self_collision else ''}; "
          f"path agreement of the discrete side: joint values {dq:.1e} rad, link points "
          f"{dx:.1e} m")
    options = dict(self_collision=self_collision)

    def valid(q):
        return not robot.check(q, q, obstacles, first_contact=False, **options).collides

    res = args.resolution
    modes = {"decide": dict(first_contact=False), "first": dict()}
    if args.min_distance:  # issue 33: the same segments with a minimum distance, same run
        limit = P.Limits(max_seconds=args.md_max_seconds)
        modes["decide md"] = dict(first_contact=False, min_distance=args.min_distance, limits=limit)
        modes["first md"] = dict(min_distance=args.min_distance, limits=limit)
    ended = {m: 0 for m in modes}
    times = {m: [] for m in modes}
    hits = {m: 0 for m in modes}
    disagree = []
    runs = {r: {"times": [], "hits": 0, "poses": [], "misses": [], "bad": [], "early": []}
            for r in res}
    start_all, rejected = time.perf_counter(), 0
    while len(times["first"]) < args.n:
        q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
        q1 = np.array([min(hi, max(lo, x + rng.uniform(-args.span, args.span)))
                       for x, (lo, hi) in zip(q0, lims)])
        if not (valid(q0) and valid(q1)):
            rejected += 1
            continue
        s = len(times["first"])
        out = {}
        for m, kw in modes.items():
            t0 = clock()
            try:
                out[m] = robot.check(q0, q1, obstacles, **options, **kw)
            except P.LimitError:  # --md-max-seconds: counted, its time kept
                ended[m] += 1
                out[m] = None
            times[m].append(clock() - t0)
            hits[m] += out[m] is not None and out[m].collides
        exact = out["first"]
        if out["decide"].collides != exact.collides:
            disagree.append(f"segment {s}: q0 = {q0.tolist()}, q1 = {q1.tolist()}")
        for r, run in runs.items():
            t0 = clock()
            sample, poses = discrete.check(q0, q1, r)
            run["times"].append(clock() - t0)
            run["poses"].append(poses)
            run["hits"] += sample is not None
            if exact.collides and sample is None:
                c = exact.contacts[0]
                run["misses"].append(f"segment {s}: {c.a[0]} {c.a[1]} - {c.b[0]} {c.b[1]} "
                                     f"at t ~ {exact.first_contact.approx:.6f}")
            if sample is not None and not exact.collides:
                run["bad"].append(f"segment {s}: q0 = {q0.tolist()}, q1 = {q1.tolist()}, "
                                  f"discrete collides at t = {sample}")
            if sample is not None and exact.collides and sample < exact.first_contact.lo:
                run["early"].append(f"segment {s}: q0 = {q0.tolist()}, q1 = {q1.tolist()}, "
                                    f"sample t = {sample}, polyccd {exact.first_contact}")
        if (s + 1) % 100 == 0:
            print(f"  {s + 1} segments, {time.perf_counter() - start_all:.0f} s", flush=True)
    print(f"segment ends drawn and rejected (an end in collision): {rejected}; "
          f"wall time {time.perf_counter() - start_all:.0f} s")
    print(f"{'method':<28} {'mean ms':>9} {'median':>9} {'max ms':>9} {'poses':>6} "
          f"{'colliding':>9} {'MISSES':>7} {'unreported':>10} {'earlier':>7}")
    for m in modes:
        print(f"{f'polyccd {m}':<28} {ms(times[m])} {'-':>6} {hits[m]:>9} {'-':>7} {'-':>10} {'-':>7}"
              f"{f'  ({ended[m]} ended by the limit)' if ended[m] else ''}")
    if args.min_distance:
        mean = statistics.mean
        print(f"min_distance {args.min_distance} / none, same segments: decide "
              f"{mean(times['decide md']) / mean(times['decide']):.2f}x, first "
              f"{mean(times['first md']) / mean(times['first']):.2f}x (means)")
    for r, run in runs.items():
        print(f"{f'FCL discrete @ {r} rad':<28} {ms(run['times'])} "
              f"{statistics.mean(run['poses']):6.1f} {run['hits']:>9} {len(run['misses']):>7} "
              f"{len(run['bad']):>10} {len(run['early']):>7}")
    for text in disagree:
        print(f"  !!! DISCREPANCY: decide and first-contact modes disagree: {text}")
    for r, run in runs.items():
        for text in run["misses"][:3]:
            print(f"  missed at {r} rad: {text}")
        for text in run["bad"]:
            print(f"  !!! DISCREPANCY at {r} rad, not reported by polyccd: {text}")
        for text in run["early"]:
            print(f"  !!! DISCREPANCY at {r} rad, earlier than polyccd: {text}")
    fcl = runs[min(res)]["times"]
    summary.append((name, sc, times, fcl, min(res), {r: len(runs[r]["misses"]) for r in res},
                    hits["first"]))


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1000, help="segments per arm and setting (default 1000)")
    ap.add_argument("--seed", type=int, default=20261124)
    ap.add_argument("--resolution", type=float, nargs="+", default=[0.05, 0.1, 0.2],
                    help="rad per pose of the discrete checks (default 0.05 0.1 0.2; 0.05 is "
                    "a typical planner resolution)")
    ap.add_argument("--span", type=float, default=1.0, help="largest change per joint (rad)")
    ap.add_argument("--boxes", type=int, default=3)
    ap.add_argument("--plates", type=int, default=3)
    ap.add_argument("--clock", choices=["cpu", "wall"], default="cpu",
                    help="time per check: process CPU time (default) or wall time")
    ap.add_argument("--arms", nargs="+", default=sorted(ARMS), choices=sorted(ARMS))
    ap.add_argument("--self-collision", nargs="+", default=["off", "on"], choices=["off", "on"])
    ap.add_argument("--min-distance", type=float, default=0,
                    help="also check every segment with this min_distance (issue 33), same run")
    ap.add_argument("--md-max-seconds", type=float, default=60,
                    help="max_seconds of each min_distance check (default 60)")
    args = ap.parse_args(argv)
    try:
        import fcl  # noqa: F401
        import pinocchio  # noqa: F401
        import yourdfpy  # noqa: F401
    except ImportError as e:
        print(f"bench_robot: skipped ({e.name} is not installed)")
        return 0
    import polyccd as P
    from polyccd.apps._demo_robot import example_robot_file
    from polyccd.robot import load_urdf
    if any(example_robot_file(f) is None for arm in args.arms for f in ARMS[arm]):
        print("bench_robot: skipped (example-robot-data is not installed)")
        return 0
    print(f"bench_robot: {args.n} segments per arm and setting (seed {args.seed}, span "
          f"{args.span} rad), {args.boxes} boxes + {args.plates} plates (2 mm), discrete every "
          f"{' / '.join(map(str, args.resolution))} rad; {args.clock} time")
    summary = []
    for name in args.arms:
        for sc in args.self_collision:
            run_arm(P, load_urdf, example_robot_file, name, sc == "on", args, summary)
    print("\n| arm | self-collision | polyccd decide mean / median ms | polyccd first mean / "
          "median ms | FCL @ res mean / median ms | decide / FCL (mean, median) | first / FCL "
          "mean | colliding | FCL misses (0.05 / 0.1 / 0.2) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, sc, times, fcl, r, misses, hits in summary:
        d, f = times["decide"], times["first"]
        mean, med = statistics.mean, statistics.median
        print(f"| {name} | {sc} | {1e3 * mean(d):.2f} / {1e3 * med(d):.2f} | "
              f"{1e3 * mean(f):.2f} / {1e3 * med(f):.2f} | {r}: {1e3 * mean(fcl):.2f} / "
              f"{1e3 * med(fcl):.2f} | {mean(d) / mean(fcl):.2f}x, {med(d) / med(fcl):.2f}x | "
              f"{mean(f) / mean(fcl):.2f}x | {hits} | "
              f"{' / '.join(str(misses[x]) for x in sorted(misses))} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
