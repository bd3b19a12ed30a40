"""What solids cost (docs/solids.md, "Cost"): CPU seconds of polyccd.check and
Robot.check with the same shapes as solids and as surfaces, in one run.

    .venv/bin/python tests/bench/bench_solids.py [--balls 1000] [--segments 10]

1. The worst case of the containment test: 1,000 small balls in the corners of the
   bounding box of a solid sphere of 20,480 triangles (trimesh icosphere, radius 10),
   none inside, so every ball passes the box test and is tested (the library's (y, z)
   grid); the surfaces are apart. Best of 3.
2. A robot: the Franka Panda of example-robot-data (every link mesh is closed, so all
   are solids) over random joint segments with two solid obstacle boxes, first contact
   and decide mode, against the same robot and boxes as surfaces (the answers must be
   equal: no ball or link is inside another at the segments' starts).
Needs trimesh; part 2 needs yourdfpy and example-robot-data (tests/requirements.txt).
"""
import argparse
import glob
import os
import random
import sys
import time

import numpy as np

import polyccd as P


def cpu(fn, repeat=1):
    best = None
    for _ in range(repeat):
        t = time.process_time()
        out = fn()
        dt = time.process_time() - t
        best = dt if best is None else min(best, dt)
    return best, out


def balls_in_corners(n):
    import trimesh
    sphere = trimesh.creation.icosphere(subdivisions=5, radius=10)
    rng = np.random.default_rng(1)
    centers = rng.uniform(8, 9.5, size=(n, 3)) * rng.choice([-1, 1], size=(n, 3))
    balls = P.Body(P.Spheres(centers, np.full(n, 0.05)), P.Motion.linear([0, 0, 0], [0.01, 0, 0]))
    for solid in (False, True):
        body = P.Body(P.Mesh.from_trimesh(sphere, solid=solid))
        dt, r = cpu(lambda: P.check([body, balls]), repeat=3)
        print("%-8s %d balls vs %d triangles: %.4f s cpu, collides %s"
              % ("solid" if solid else "surface", n, body.shape.n_triangles, dt, r.collides))


def panda(segments):
    from polyccd.robot import load_urdf
    roots = glob.glob(os.path.join(sys.prefix, "**", "share", "example-robot-data", "robots"),
                      recursive=True)
    if not roots:
        print("panda: example-robot-data is not installed")
        return
    robot = load_urdf(os.path.join(roots[0], "panda_description/urdf/panda.urdf"))
    solid = list(robot.shapes)
    surface = [(l, i, k, P.Mesh(s.exact_vertices(), s.triangles) if isinstance(s, P.Mesh) else s)
               for l, i, k, s in solid]
    rng = random.Random(1)
    lo = [-2.8, -1.7, -2.8, -3.0, -2.8, 0.0, -2.8, 0, 0]
    hi = [2.8, 1.7, 2.8, -0.1, 2.8, 3.7, 2.8, 0.04, 0.04]
    n = len(robot.joints)
    segs = []
    for _ in range(segments):
        q0 = [rng.uniform(lo[k], hi[k]) for k in range(n)]
        segs.append((q0, [min(hi[k], max(lo[k], q0[k] + rng.uniform(-0.3, 0.3))) for k in range(n)]))
    answers = {}
    for name, shapes in (("surface", surface), ("solid", solid)):
        robot.shapes = shapes
        obstacles = [P.Body(P.Mesh.box([0.3, 0.3, 0.3], solid=name == "solid"), pose=((0.5, 0.2, 0.4), (1, 0, 0, 0))),
                     P.Body(P.Mesh.box([2, 2, 0.1], solid=name == "solid"), pose=((0, 0, -0.1), (1, 0, 0, 0)))]

        def run():
            return [(r.collides, r.first_contact.lo if r.collides else None)
                    for q0, q1 in segs for r in (robot.check(q0, q1, obstacles),
                                                 robot.check(q0, q1, obstacles, first_contact=False))]
        dt, answers[name] = cpu(run)
        print("%-8s panda, %d segments x 2 modes: %.2f s cpu, %d checks colliding"
              % (name, segments, dt, sum(c for c, _ in answers[name])))
    print("same answers:", answers["solid"] == answers["surface"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--balls", type=int, default=1000)
    ap.add_argument("--segments", type=int, default=10)
    args = ap.parse_args()
    print("load:", os.getloadavg())
    balls_in_corners(args.balls)
    panda(args.segments)


if __name__ == "__main__":
    main()
