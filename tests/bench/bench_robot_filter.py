#!/usr/bin/env python3
"""Benchmark: the C time of a robot check per segment (issue 30, the filter's own cost),
without the Python call around it. bench_robot.py's arms, obstacles and segment rule
(seeded: q0 uniform in the limits, q1 = q0 + uniform(-SPAN, SPAN) clipped, both ends
collision-free), then each segment repeated REPEAT times in one Robot.check_many call:
its CPU time / REPEAT is the segment's time (the call's fixed Python cost, ~75 us,
spread over the repeats). Printed per arm and self-collision setting: the mean over all
segments, and mean and median of the free and of the colliding ones.

Comparing two builds in the same run (absolute times are noisy on a shared machine):
run it twice, the second time with LD_LIBRARY_PATH=DIR, DIR holding another build's
libpolyccd.so.0 (the bindings find it through RUNPATH, which LD_LIBRARY_PATH overrides).

A benchmark: it never asserts and is not in make test. Alone:
.venv/bin/python tests/bench/bench_robot_filter.py --n 150 [--first-contact]
"""
import argparse
import random
import statistics
import sys
import time

import numpy as np

from robot_fcl import BOX_TRIANGLES, FINGER, box_vertices, make_obstacles

ARMS = {"panda": ("panda_description/urdf/panda.urdf", "panda_description/srdf/panda.srdf"),
        "ur5": ("ur_description/urdf/ur5_robot.urdf", "ur_description/srdf/ur5.srdf")}


def segments(P, robot, obstacles, lims, rng, n, span, self_collision):
    """n segments with both ends collision-free (bench_robot.py's rule)."""
    def valid(q):
        return not robot.check(q, q, obstacles, first_contact=False,
                               self_collision=self_collision).collides
    q0s, q1s = [], []
    while len(q0s) < n:
        q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
        q1 = np.array([min(hi, max(lo, x + rng.uniform(-span, span))) for x, (lo, hi) in zip(q0, lims)])
        if valid(q0) and valid(q1):
            q0s.append(q0)
            q1s.append(q1)
    return np.array(q0s), np.array(q1s)


def ms(values):
    if not values:
        return "    -        -   "
    return f"{1e3 * statistics.mean(values):8.3f} {1e3 * statistics.median(values):8.3f}"


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=150, help="segments per arm and setting")
    ap.add_argument("--repeat", type=int, default=10, help="copies of a segment per call")
    ap.add_argument("--seed", type=int, default=20261124)
    ap.add_argument("--span", type=float, default=1.0)
    ap.add_argument("--first-contact", action="store_true", help="first-contact mode (default: decide)")
    args = ap.parse_args(argv)
    import polyccd as P
    from polyccd.apps._demo_robot import example_robot_file
    from polyccd.robot import load_urdf
    print(f"{'arm':<6} {'self':<4} {'all mean':>9} {'free mean':>9} {'median':>8} "
          f"{'hit mean':>9} {'median':>8}  (ms per segment, CPU)")
    for name, (urdf, srdf) in ARMS.items():
        robot = load_urdf(example_robot_file(urdf), srdf=example_robot_file(srdf))
        rng = random.Random(args.seed)
        boxes = make_obstacles(rng, 3, 3)
        obstacles = [P.Body(P.Mesh(box_vertices(lo, hi), BOX_TRIANGLES), name=n) for n, lo, hi in boxes]
        lims = [robot.limits[n] or (-np.pi, np.pi) for n in robot.joints]
        if name == "panda":
            lims[-1] = (FINGER, FINGER)
        for sc in (False, True):
            Q0, Q1 = segments(P, robot, obstacles, lims, random.Random(args.seed + sc), args.n, args.span, sc)
            kw = dict(first_contact=args.first_contact, self_collision=sc)
            hit = robot.check_many(Q0, Q1, obstacles, **kw).collides
            per = []
            for k in range(len(Q0)):
                a, b = np.repeat(Q0[k:k + 1], args.repeat, 0), np.repeat(Q1[k:k + 1], args.repeat, 0)
                t0 = time.process_time()
                robot.check_many(a, b, obstacles, **kw)
                per.append((time.process_time() - t0) / args.repeat)
            free = [t for t, h in zip(per, hit) if not h]
            coll = [t for t, h in zip(per, hit) if h]
            print(f"{name:<6} {'on' if sc else 'off':<4} {1e3 * statistics.mean(per):9.3f} {ms(free)} "
                  f"{ms(coll)}  ({len(free)} free, {len(coll)} colliding)", flush=True)


if __name__ == "__main__":
    sys.exit(main())
