#!/usr/bin/env python3
"""Benchmark: exact step sizes inside an IPC simulator's loop (issue 35).

The same scene (ipc_cloth.py: a 10 x 10 mass-spring cloth dropped onto a static cube,
ipctk's barrier, Newton with the IPC paper's backtracking line search), the same
tolerances, run twice; only the CCD step that starts each line search differs:
  ipctk     ipctk.compute_collision_free_stepsize (Tight Inclusion, tolerance 1e-6,
            conservative rescaling 0.8)
  polyccd   0.8 x polyccd.collision_free_stepsize (the exact first contact time, rounded
            down to a double; 1.0 without contact), the same 0.8 gap
Per run: time steps, Newton iterations, CCD calls, CCD CPU time, total CPU time, the
histograms of the CCD steps and of the accepted line-search steps, and penetrations:
every accepted update is checked exactly with polyccd.check_step (a benchmark, not a
test: it asserts nothing about speed; it exits 1 when a run penetrates).
Both run on one thread (ipctk.set_num_threads(1), polyccd threads=1): CPU times compare.

`make bench` runs this file. Usage: python tests/bench/bench_ipc_loop.py [--steps N]
"""
import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

import ipctk
import polyccd

sys.path.insert(0, str(Path(__file__).resolve().parent))
import ipc_cloth  # noqa: E402

BINS = [0.0, 1e-3, 1e-2, 0.1, 0.5, 0.8, 1.0, 1.0 + 1e-12]
BIN_NAMES = ["<1e-3", "<1e-2", "<0.1", "<0.5", "<0.8", "<1", "=1"]


def histogram(values):
    counts, _ = np.histogram(values, bins=BINS)
    return " ".join(f"{n:4d}" for n in counts)


def run(name, scene, prm):
    mesh = ipctk.CollisionMesh(scene.rest, scene.edges, scene.faces)
    step = (ipc_cloth.ipctk_stepsize(mesh) if name == "ipctk"
            else ipc_cloth.polyccd_stepsize(scene))
    x, stats = ipc_cloth.Stepper(scene, prm, step).run()
    return x, stats


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--steps", type=int, default=30, help="time steps of 0.01 s (default 30)")
    args = p.parse_args(argv)
    ipctk.set_num_threads(1)
    scene = ipc_cloth.cloth_on_cube()
    prm = ipc_cloth.Params(steps=args.steps)
    print(f"polyccd {polyccd.__version__}, ipctk {ipctk.__version__}, {os.cpu_count()} CPUs, "
          f"load {os.getloadavg()[0]:.2f}, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    print(f"scene: cloth {scene.ncloth} vertices / {len(scene.cloth_faces)} triangles on a "
          f"cube; h = {prm.h}, {prm.steps} steps, dhat = {prm.dhat}, Newton tolerance "
          f"{prm.tol_velocity} m/s")
    results = {name: run(name, scene, prm) for name in ("ipctk", "polyccd")}
    print(f"\n{'step size from':15} {'steps':>5} {'Newton':>6} {'CCD calls':>9} "
          f"{'CCD CPU s':>9} {'CCD ms/call':>11} {'total CPU s':>11} {'penetrations':>12}")
    for name, (_, st) in results.items():
        print(f"{name:15} {st.steps:5d} {st.newton:6d} {st.ccd_calls:9d} {st.ccd_cpu:9.3f} "
              f"{st.ccd_cpu / max(1, st.ccd_calls) * 1e3:11.3f} {st.total_cpu:11.2f} "
              f"{st.penetrations:12d}")
    print(f"\nhistograms {'':14} {' '.join(f'{b:>4}' for b in BIN_NAMES)}")
    for name, (_, st) in results.items():
        print(f"{name:8} CCD step      {histogram(st.ccd_steps)}")
        print(f"{name:8} accepted step {histogram(st.accepted)}")
    (xa, _), (xb, _) = results["ipctk"], results["polyccd"]
    print(f"\nlargest distance between the two runs' final cloths: "
          f"{np.max(np.linalg.norm(xa - xb, axis=1)):.3g} m")
    return 1 if any(st.penetrations for _, st in results.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
