#!/usr/bin/env python3
"""Benchmark: a planner-like workload on a real arm. N random joint-space segments of
the Franka Panda (example-robot-data's URDF and collision meshes) among a few fixed
obstacles (boxes and 2 mm plates), each checked by

  polyccd   Robot.check(q0, q1, obstacles, self_collision=False): the exact first contact
            of the links' exact motions over the segment (polyccd.robot);
  discrete  python-fcl collision at a planner's resolution: poses t = k / m, k = 0..m,
            m = ceil(largest joint change / RESOLUTION) (0.05 rad, typical of planners;
            also 0.1 and 0.2 rad by default: --resolution), stopping at
            the first colliding pose as a planner does; fcl.BVHModel (OBBRSS) of the SAME
            triangles polyccd gets (robot meshes and obstacle boxes), one
            DynamicAABBTree manager per side; link poses by Pinocchio's float FK.

Both check the SAME path: polyccd's chains interpolate each revolute joint's half-angle
quaternion (cos, sin)(q/2) linearly (lib/motion/chain.cpp), so the joint values at t
are q0 + 2 atan2(C0 S - S0 C, C0 C + S0 S) with (C, S) interpolated; the discrete
check evaluates that formula in floats (printed: its largest difference from
Robot.joint_values, and Pinocchio's poses against polyccd's exact motions). Robot
versus obstacles only (self-collision off on both sides: polyccd's exact self-collision
of the full meshes takes seconds per segment).

Segments: q0 uniform within the joint limits, q1 = q0 + uniform(-SPAN, SPAN) per joint
clipped to the limits (default SPAN 1 rad), the finger opening fixed at 0.02 m; both
ends must be collision-free (decided exactly by polyccd as a stationary robot), as a
planner's states are. Obstacles: BOXES boxes (5 to 20 cm sides) and PLATES plates (2 mm
thick, 10 to 30 cm wide) axis-aligned, centred 0.3 to 0.75 m from the base axis at
heights 0.1 to 0.8 m; all seeded (--seed).

Reported: time per segment (mean, median, max) of both, segments each reports colliding,
MISSES (polyccd collides, discrete free), and two counts that must be 0, printed loudly
when not: discrete collisions polyccd does not report, and discrete first colliding
poses earlier than polyccd's first contact. A benchmark: it never asserts and is not in
make test. `make bench` runs it; alone: .venv/bin/python tests/bench/bench_robot.py --n 200
"""
import argparse
import math
import random
import statistics
import sys
import time
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np

BOX_TRIANGLES = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                 [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
FINGER = 0.02


def box_vertices(lo, hi):
    return np.array([[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)])


def make_obstacles(rng, boxes, plates):
    """[(name, lo, hi)]: axis-aligned boxes and 2 mm plates near the arm (doubles)."""
    out = []
    for i in range(boxes + plates):
        angle, radius = rng.uniform(-math.pi, math.pi), rng.uniform(0.3, 0.75)
        c = [radius * math.cos(angle), radius * math.sin(angle), rng.uniform(0.1, 0.8)]
        if i < boxes:
            size, name = [rng.uniform(0.05, 0.2) for _ in range(3)], f"box{i}"
        else:
            size, name = [rng.uniform(0.1, 0.3) for _ in range(3)], f"plate{i - boxes}"
            size[rng.randrange(3)] = 0.002
        out.append((name, [c[a] - size[a] / 2 for a in range(3)],
                    [c[a] + size[a] / 2 for a in range(3)]))
    return out


def rpy_matrix(rpy):
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = (math.cos(r), math.sin(r), math.cos(p), math.sin(p),
                              math.cos(y), math.sin(y))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


class Discrete:
    """The planner side: float joint interpolation, Pinocchio FK, python-fcl collision."""

    def __init__(self, robot, urdf, obstacles):
        import fcl
        import pinocchio as pin
        self.fcl, self.pin = fcl, pin
        self.model = pin.buildModelFromUrdf(urdf)
        self.data = self.model.createData()
        self.robot = robot
        links = ET.parse(urdf).getroot()
        origins = {}
        for link in links.findall("link"):
            for i, c in enumerate(link.findall("collision")):
                o = c.find("origin")
                get = o.get if o is not None else (lambda key, default: default)
                xyz = [float(x) for x in get("xyz", "0 0 0").split()]
                rpy = [float(x) for x in get("rpy", "0 0 0").split()]
                origins[(link.get("name"), i)] = (rpy_matrix(rpy), np.array(xyz))
        self.shapes = []  # (frame id, offset R, offset p, CollisionObject)
        for link, i, k, shape in robot.shapes:
            R, p = (origins[(link, i)] if k != robot.link_index[link]
                    else (np.eye(3), np.zeros(3)))
            obj = fcl.CollisionObject(self._bvh(shape.vertices, shape.triangles), fcl.Transform())
            self.shapes.append((self.model.getFrameId(link), R, p, obj))
        self.manager = fcl.DynamicAABBTreeCollisionManager()
        self.manager.registerObjects([s[3] for s in self.shapes])
        self.manager.setup()
        self.obstacles = fcl.DynamicAABBTreeCollisionManager()
        self.obstacles.registerObjects([
            fcl.CollisionObject(self._bvh(box_vertices(lo, hi), BOX_TRIANGLES), fcl.Transform())
            for _, lo, hi in obstacles])
        self.obstacles.setup()
        self.revolute = np.array([robot.joint_types[n] != "prismatic" for n in robot.joints])
        self.q_index = {}
        for jid in range(1, self.model.njoints):
            self.q_index[self.model.names[jid]] = self.model.joints[jid].idx_q

    def _bvh(self, vertices, triangles):
        m = self.fcl.BVHModel()
        m.beginModel(len(vertices), len(triangles))
        m.addSubModel(np.asarray(vertices, dtype=np.float64), np.asarray(triangles, dtype=np.int32))
        m.endModel()
        return m

    def joint_values(self, q0, q1, t):
        """The joint values at t of polyccd's path (see the module comment), floats."""
        h0, h1 = q0 / 2, q1 / 2
        C0, S0 = np.cos(h0), np.sin(h0)
        C = (1 - t) * C0 + t * np.cos(h1)
        S = (1 - t) * S0 + t * np.sin(h1)
        revolute = q0 + 2 * np.arctan2(C0 * S - S0 * C, C0 * C + S0 * S)
        return np.where(self.revolute, revolute, (1 - t) * q0 + t * q1)

    def poses(self, q):
        """[(R, p)] of every robot shape at the joint values q (Pinocchio, floats)."""
        pin = self.pin
        x = pin.neutral(self.model)
        values = dict(zip(self.robot.joints, q))
        for name, idx in self.q_index.items():
            if name in self.robot.mimic_joints:
                leader, mult, off = self.robot.mimic_joints[name]
                x[idx] = mult * values[leader] + off
            else:
                x[idx] = values[name]
        pin.framesForwardKinematics(self.model, self.data, x)
        out = []
        for fid, R, p, _ in self.shapes:
            f = self.data.oMf[fid]
            out.append((f.rotation @ R, f.rotation @ p + f.translation))
        return out

    def pose_collides(self, q):
        fcl = self.fcl
        for (R, p), (_, _, _, obj) in zip(self.poses(q), self.shapes):
            obj.setTransform(fcl.Transform(R, p))
        self.manager.update()
        data = fcl.CollisionData(request=fcl.CollisionRequest())
        self.manager.collide(self.obstacles, data, fcl.defaultCollisionCallback)
        return data.result.is_collision

    def check(self, q0, q1, resolution):
        """(first colliding sample time or None, poses checked)."""
        m = max(1, math.ceil(float(np.max(np.abs(q1 - q0)[self.revolute])) / resolution))
        for k in range(m + 1):
            t = Fraction(k, m)
            if self.pose_collides(self.joint_values(q0, q1, k / m)):
                return t, k + 1
        return None, m + 1


def agreement(robot, discrete, rng, lims):
    """Largest differences (joint values; link positions in m) between the discrete
    side's floats and polyccd's exact path, at a few random segments and times."""
    from polyccd.apps._render import _float_pose
    dq = dx = 0.0
    for _ in range(3):
        q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
        q1 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
        motions = robot.motions(q0, q1)
        for t in (Fraction(1, 3), Fraction(5, 7)):
            v = robot.joint_values(q0, q1, t)
            q = discrete.joint_values(q0, q1, float(t))
            dq = max(dq, max(abs(v[n] - q[j]) for j, n in enumerate(robot.joints)))
            for (R, p), (_, _, k, shape) in zip(discrete.poses(q), robot.shapes):
                Re, pe = _float_pose(motions[k], t)
                w = shape.vertices[:1]
                dx = max(dx, float(np.abs(w @ R.T + p - (w @ Re.T + pe)).max()))
    return dq, dx


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1000, help="segments (default 1000)")
    ap.add_argument("--seed", type=int, default=20261124)
    ap.add_argument("--resolution", type=float, nargs="+", default=[0.05, 0.1, 0.2],
                    help="rad per pose of the discrete checks (default 0.05 0.1 0.2; 0.05 is "
                    "a typical planner resolution)")
    ap.add_argument("--span", type=float, default=1.0, help="largest change per joint (rad)")
    ap.add_argument("--boxes", type=int, default=3)
    ap.add_argument("--plates", type=int, default=3)
    args = ap.parse_args(argv)
    try:
        import fcl  # noqa: F401
        import pinocchio  # noqa: F401
        import yourdfpy  # noqa: F401
    except ImportError as e:
        print(f"bench_robot: skipped ({e.name} is not installed)")
        return 0
    import polyccd as P
    from polyccd.apps._demo_robot import PANDA_URDF, example_robot_file
    from polyccd.robot import load_urdf
    urdf = example_robot_file(PANDA_URDF)
    if urdf is None:
        print("bench_robot: skipped (example-robot-data is not installed)")
        return 0
    robot = load_urdf(urdf)
    rng = random.Random(args.seed)
    boxes = make_obstacles(rng, args.boxes, args.plates)
    obstacles = [P.Body(P.Mesh(box_vertices(lo, hi), BOX_TRIANGLES), name=name)
                 for name, lo, hi in boxes]
    discrete = Discrete(robot, urdf, boxes)
    lims = [robot.limits[n] for n in robot.joints]
    lims[-1] = (FINGER, FINGER)
    dq, dx = agreement(robot, discrete, rng, lims)
    print(f"bench_robot: Panda ({len(robot.shapes)} collision meshes, "
          f"{sum(len(s.triangles) for *_, s in robot.shapes)} triangles), "
          f"{args.boxes} boxes + {args.plates} plates (2 mm), {args.n} segments "
          f"(seed {args.seed}, span {args.span} rad), discrete every "
          f"{' / '.join(map(str, args.resolution))} rad")
    for name, lo, hi in boxes:
        print(f"  {name}: [{', '.join(f'{x:.4f}' for x in lo)}] - "
              f"[{', '.join(f'{x:.4f}' for x in hi)}]")
    print(f"path agreement of the discrete side: joint values {dq:.1e} rad, "
          f"link points {dx:.1e} m (Pinocchio vs polyccd's exact motions)")

    def valid(q):
        return not robot.check(q, q, obstacles, self_collision=False).collides

    res = args.resolution
    exact_times, exact_hits = [], 0
    runs = {r: {"times": [], "hits": 0, "poses": [], "misses": [], "bad": [], "early": []}
            for r in res}
    start_all, rejected = time.perf_counter(), 0
    while len(exact_times) < args.n:
        q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
        q1 = np.array([min(hi, max(lo, x + rng.uniform(-args.span, args.span)))
                       for x, (lo, hi) in zip(q0, lims)])
        if not (valid(q0) and valid(q1)):
            rejected += 1
            continue
        s = len(exact_times)
        t0 = time.perf_counter()
        exact = robot.check(q0, q1, obstacles, self_collision=False)
        exact_times.append(time.perf_counter() - t0)
        exact_hits += exact.collides
        for r, run in runs.items():
            t0 = time.perf_counter()
            sample, poses = discrete.check(q0, q1, r)
            run["times"].append(time.perf_counter() - t0)
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

    def ms(values):
        return (f"{1e3 * statistics.mean(values):9.2f} {1e3 * statistics.median(values):9.2f} "
                f"{1e3 * max(values):9.2f}")
    n = len(exact_times)
    print(f"segment ends drawn and rejected (an end in collision): {rejected}; "
          f"wall time {time.perf_counter() - start_all:.0f} s\n")
    print(f"{'method':<28} {'mean ms':>9} {'median':>9} {'max ms':>9} {'poses':>6} "
          f"{'colliding':>9} {'MISSES':>7} {'unreported':>10} {'earlier':>7}")
    print(f"{'polyccd Robot.check exact':<28} {ms(exact_times)} {'-':>6} {exact_hits:>9} "
          f"{'-':>7} {'-':>10} {'-':>7}")
    for r, run in runs.items():
        print(f"{f'FCL discrete @ {r} rad':<28} {ms(run['times'])} "
              f"{statistics.mean(run['poses']):6.1f} {run['hits']:>9} {len(run['misses']):>7} "
              f"{len(run['bad']):>10} {len(run['early']):>7}")
    print(f"poses: mean poses checked per segment (up to the first colliding one); MISSES: "
          f"polyccd finds a contact, the discrete check none (of {exact_hits} colliding "
          f"segments); unreported: discrete collisions polyccd does not report; earlier: "
          f"a discrete collision before polyccd's first contact (both must be 0)")
    for r, run in runs.items():
        for text in run["misses"][:3]:
            print(f"  missed at {r} rad: {text}")
        for text in run["bad"]:
            print(f"  !!! DISCREPANCY at {r} rad, not reported by polyccd: {text}")
        for text in run["early"]:
            print(f"  !!! DISCREPANCY at {r} rad, earlier than polyccd: {text}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
