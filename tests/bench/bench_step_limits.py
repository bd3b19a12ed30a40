"""Benchmark (issue 33): a step of about a million triangles checked with
Limits(max_seconds=S) ends within S plus the time Python takes to hand the arrays
over, building included (pccd_step_add_mesh_cfg_d and the step's trees count work
steps and check the clock; before issue 33 the building was outside the limits:
996k triangles with max_seconds=1 took 2.17 s on the first call).

    .venv/bin/python tests/bench/bench_step_limits.py --side 708 --seconds 1 --repeat 3

The mesh: a side x side grid (2 (side - 1)^2 triangles; 708: 999,698) in z = 0, each
vertex moving up by a seeded random amount below one cell (a crumpling sheet: many
candidate pairs, far more than a second of exact work). Each repeat builds a new step
(a fresh connectivity array, so check_step's handle cache is missed, as on a first
call). Reported: wall and CPU seconds of each call, and the outcome (LimitError's
message, or the answer when the limit is not reached). A benchmark: it never asserts.
"""
import argparse
import os
import time

import numpy as np

import polyccd as P


def sheet(side, seed):
    i, j = np.meshgrid(np.arange(side), np.arange(side), indexing="ij")
    v0 = np.stack([i.ravel(), j.ravel(), np.zeros(side * side)], axis=1).astype(np.float64)
    rng = np.random.default_rng(seed)
    v1 = v0 + np.stack([rng.uniform(-0.6, 0.6, side * side), rng.uniform(-0.6, 0.6, side * side),
                        rng.uniform(0, 0.6, side * side)], axis=1)
    a = (i[:-1, :-1] * side + j[:-1, :-1]).ravel()
    faces = np.concatenate([np.stack([a, a + 1, a + side], 1), np.stack([a + 1, a + side + 1, a + side], 1)])
    return v0, v1, faces.astype(np.int64)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--side", type=int, default=708)
    ap.add_argument("--seconds", type=float, default=1.0)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--seed", type=int, default=33)
    a = ap.parse_args()
    v0, v1, faces = sheet(a.side, a.seed)
    print(f"# {len(faces)} triangles, {len(v0)} vertices, max_seconds={a.seconds}; "
          f"load {os.getloadavg()[0]:.1f}")
    for r in range(a.repeat):
        f = faces.copy()
        f[0, 0], f[0, 1] = f[0, 1], f[0, 0]  # another connectivity: no cached handle
        if r % 2:
            f[0, 0], f[0, 1] = f[0, 1], f[0, 0]
        f = f.copy()
        w0, c0 = time.perf_counter(), time.process_time()
        try:
            res = P.check_step(v0, v1, f, limits=P.Limits(max_seconds=a.seconds))
            out = f"answered: collides={res.collides}"
        except P.LimitError as e:
            out = f"LimitError: {str(e)[:110]}"
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        print(f"repeat {r}: wall {wall:.2f} s, cpu {cpu:.2f} s ({wall / a.seconds:.2f} x max_seconds): {out}")


if __name__ == "__main__":
    main()
