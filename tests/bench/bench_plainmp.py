#!/usr/bin/env python3
"""Benchmark: polyccd's exact robot edge check against plainmp's sphere-model check
(plainmp 0.3.6, C++ core, SIMD sphere-vs-SDF tests; issue 30), on the Franka Panda, in
one process, the segments interleaved.

The same robot and obstacles for both: example-robot-data's panda.urdf (plainmp through
a PandaSpec whose urdf_path_override returns it; plainmp's own sphere model of the
links, polyccd the collision meshes), the boxes and 2 mm plates of bench_robot.py
(robot_fcl.make_obstacles: polyccd meshes, plainmp BoxSDFs of the same corners). Each
segment (q0 uniform in the limits, q1 = q0 + uniform(-SPAN, SPAN) clipped, the finger
opening fixed at 0.02 m, both ends collision-free for polyccd) is checked by, in turn:

  plainmp R     the states q0 + (q1 - q0) k / m, m = ceil(|q1 - q0|_2 / R) (OMPL's
                Euclidean resolution, plainmp's examples use R = 0.05 rad; also 0.005),
                each by SphereCollisionCst.is_valid from Python, stopping at the first
                invalid state as a planner does;
  polyccd decide  Robot.check(q0, q1, obstacles, first_contact=False), one call each;
  polyccd first   Robot.check(q0, q1, obstacles): the exact first contact;
and after the loop all segments at once by Robot.check_many (decide and first contact;
per-segment cost = the batch's CPU time / n).

Self-collision off (robot versus boxes) and on (plainmp: its conf's self-collision
pairs; polyccd: every pair but the adjacent and SRDF ones). Times: CPU time
(time.process_time), single thread on both sides.

Disagreements are counted both ways (plainmp free where polyccd collides: a miss;
plainmp colliding where polyccd is free) and each is checked densely and exactly: the
1,001 states of polyccd's joint path at t = k / 1000 (Robot.joint_values) and the 1,001
of the straight line plainmp samples, each decided by Robot.check_states (exact at that
pose). Printed: how many of each kind dense states confirm.

plainmp is optional: without it this prints one line and exits 0. plainmp builds from an
sdist (needs libompl-dev, libboost-filesystem-dev, ~10 min); a separate venv works too:
PLAINMP_SITE=<its site-packages> (appended to sys.path). Run: .venv/bin/python
tests/bench/bench_plainmp.py --n 1000 (make bench runs it with --n 200).
"""
import argparse
import os
import random
import statistics
import sys
import time
import numpy as np

import plainmp_side
from robot_fcl import BOX_TRIANGLES, FINGER, box_vertices, make_obstacles

URDF = "panda_description/urdf/panda.urdf"
SRDF = "panda_description/srdf/panda.srdf"


def dense(robot, obstacles, q0, q1, options, n=1000):
    """(polyccd's path, the straight line): any of the n + 1 states in contact, exactly."""
    t = np.arange(n + 1) / n
    names = robot.joints
    path = np.array([[v[j] for j in names] for v in (robot.joint_values(q0, q1, x / n) for x in range(n + 1))])
    line = q0[None, :] + t[:, None] * (q1 - q0)[None, :]
    return tuple(bool(robot.check_states(Q, obstacles, joint_limits="ignore", **options).collides.any())
                 for Q in (path, line))


def us(values):
    return f"{1e6 * statistics.mean(values):8.1f} / {1e6 * statistics.median(values):8.1f}"


def run(args, mods, robot, urdf, self_collision):
    import polyccd as P
    rng = random.Random(args.seed)
    boxes = make_obstacles(rng, args.boxes, args.plates)
    obstacles = [P.Body(P.Mesh(box_vertices(lo, hi), BOX_TRIANGLES), name=n) for n, lo, hi in boxes]
    _, cst = plainmp_side.panda(mods, urdf, boxes, self_collision)
    options = dict(self_collision=self_collision)
    lims = [robot.limits[n] for n in robot.joints]
    lims[-1] = (FINGER, FINGER)
    clock = time.process_time
    names = ["plainmp 0.05", "plainmp 0.005", "polyccd decide", "polyccd first"]
    times = {k: [] for k in names}
    hits = {k: 0 for k in names}
    segs, answers = [], []
    while len(segs) < args.n:
        q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
        q1 = np.array([min(hi, max(lo, x + rng.uniform(-args.span, args.span)))
                       for x, (lo, hi) in zip(q0, lims)])
        if robot.check_states([q0, q1], obstacles, **options).collides.any():
            continue
        row = {}
        for name in names:
            t0 = clock()
            if name.startswith("plainmp"):
                got = plainmp_side.edge_collides(cst, q0[:7], q1[:7], float(name.split()[1]))
            else:
                got = robot.check(q0, q1, obstacles, first_contact=name.endswith("first"),
                                  **options).collides
            times[name].append(clock() - t0)
            hits[name] += got
            row[name] = got
        segs.append((q0, q1))
        answers.append(row)
    Q0, Q1 = np.array([s[0] for s in segs]), np.array([s[1] for s in segs])
    batch = {}
    for mode in ("decide", "first"):
        t0 = clock()
        b = robot.check_many(Q0, Q1, obstacles, first_contact=mode == "first", **options)
        batch[mode] = (clock() - t0) / len(segs)
        assert list(b.collides) == [a[f"polyccd {mode}"] for a in answers], "batch != one by one"
    sc = "on" if self_collision else "off"
    print(f"\npanda, self-collision {sc}: {len(segs)} segments (span {args.span} rad), "
          f"{len(boxes)} obstacles; CPU us per segment, mean / median; segments colliding")
    for name in names:
        print(f"  {name:16s} {us(times[name])}   {hits[name]:5d}")
    for mode in ("decide", "first"):
        print(f"  check_many {mode:6s} {1e6 * batch[mode]:8.1f} (batch / n)")
    ref = times["plainmp 0.05"]
    ratios = {k: (statistics.mean(times[k]) / statistics.mean(ref),
                  statistics.median(times[k]) / statistics.median(ref)) for k in names}
    print("  ratios to plainmp 0.05 (mean, median): " +
          ", ".join(f"{k} {a:.2f} {b:.2f}" for k, (a, b) in ratios.items()) +
          f", check_many decide {batch['decide'] / statistics.mean(ref):.2f}, "
          f"first {batch['first'] / statistics.mean(ref):.2f}")
    for res in ("0.05", "0.005"):
        miss = [k for k, a in enumerate(answers) if a["polyccd decide"] and not a[f"plainmp {res}"]]
        extra = [k for k, a in enumerate(answers) if a[f"plainmp {res}"] and not a["polyccd decide"]]
        found = {"miss": [0, 0], "extra": [0, 0]}
        for kind, ks in (("miss", miss), ("extra", extra)):
            for k in ks[:args.dense]:
                a, b = dense(robot, obstacles, *segs[k], options)
                found[kind][0] += a
                found[kind][1] += b
        print(f"  plainmp {res}: misses {len(miss)} (dense states in contact on polyccd's path "
              f"{found['miss'][0]}, on the line {found['miss'][1]}, of {min(len(miss), args.dense)} "
              f"checked); extra {len(extra)} (dense: {found['extra'][0]} / {found['extra'][1]})")
    wrong = sum(a["polyccd decide"] != a["polyccd first"] for a in answers)
    if wrong:
        print(f"  !!! decide and first-contact modes disagree on {wrong} segments")
    return {k: (statistics.mean(v), statistics.median(v)) for k, v in times.items()}, batch


def python_cost(robot, n=2000):
    """CPU us per segment of Robot.check and of check_many with nothing to check (no
    obstacle, self-collision off): the Python around the C call, and the C call's floor."""
    lims = [robot.limits[j] for j in robot.joints]
    Q = np.array([[random.uniform(lo, hi) for lo, hi in lims] for _ in range(n)])
    t0 = time.process_time()
    for k in range(n):
        robot.check(Q[k], Q[k], (), self_collision=False, first_contact=False)
    one = (time.process_time() - t0) / n
    t0 = time.process_time()
    robot.check_many(Q, Q, (), self_collision=False)
    many = (time.process_time() - t0) / n
    print(f"\nnothing to check (no obstacle, self-collision off), CPU us per segment: "
          f"Robot.check {1e6 * one:.1f}, check_many {1e6 * many:.2f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1000)
    ap.add_argument("--span", type=float, default=1.0)
    ap.add_argument("--boxes", type=int, default=4)
    ap.add_argument("--plates", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--dense", type=int, default=20, help="disagreements checked densely, per kind")
    ap.add_argument("--self-collision", choices=["off", "on", "both"], default="both")
    args = ap.parse_args()
    mods, why = plainmp_side.load()
    if mods is None:
        print(f"bench_plainmp: skipped, plainmp is not importable ({why}); "
              f"pip install plainmp (tests/bench/requirements-plainmp.txt) or set PLAINMP_SITE")
        return
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
    from test_robot_fk import robots_dir
    from polyccd.robot import load_urdf
    root = robots_dir()
    if root is None:
        print("bench_plainmp: skipped, example-robot-data is not installed")
        return
    urdf = os.path.join(root, URDF)
    robot = load_urdf(urdf, srdf=os.path.join(root, SRDF))
    print(f"plainmp vs polyccd, Panda ({urdf}), load {os.getloadavg()[0]:.1f}")
    python_cost(robot)
    for sc in {"off": [False], "on": [True], "both": [False, True]}[args.self_collision]:
        run(args, mods, robot, urdf, sc)


if __name__ == "__main__":
    main()
