#!/usr/bin/env python3
"""Benchmark: thread scaling of the three batch calls through the Python API (issue 35),
the whole call timed (conversions and result building included), not only its C core.

  linear   polyccd.solve_linear_many on --linear random vertex-face steps (default 200k;
           tests/test_batch.py's simulation-like steps: sizes 0.01 to 1, moves 1e-3 to 1
           of the size)
  step     polyccd.check_step (first contact, as a simulator asks) on one frame of a
           --grid x --grid cloth (2 (g-1)^2 triangles; default g = 101: 20,000
           triangles), every vertex moved by a smooth fold plus noise of 0.7 cell, so
           that neighbours cross (the frame has contacts)
  index    polyccd.Index.query_many of --queries one-triangle bodies (default 400) over
           bench_online's terrain of 2 x 10^4 triangles, rotating motions

Each call runs at every --threads count (default 1,2), best of --repeat: the wall time
and the process CPU time (all threads). The answers of every thread count must be
identical to those of threads = 1 (else the run stops with exit 1: a bug). The ratio
column is wall(threads) / wall(1): on an idle machine, the issue asks for <= 0.6 at 2
threads; on a loaded one the wall times mean little (the load is printed), and
CPU(threads) / CPU(1) near 1 only says that no work was added. caller/1 is the CPU
time of the calling thread against threads = 1: the conversions, checks and result
building that do not run on the pool stay on it, so on a loaded machine it estimates
the idle wall ratio (Amdahl; about 0.5 at 2 threads when everything scales).

Usage: python tests/bench/bench_threads.py [--threads 1,2] [--repeat 5] [--only linear,step,index]
"""
import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

import polyccd

sys.path.insert(0, str(Path(__file__).resolve().parent))
import online_scenes  # noqa: E402


def linear_work(n, seed=1):
    rng = np.random.default_rng(seed)
    size = 10 ** rng.uniform(-2, 0, (n, 1, 1))
    t0 = rng.uniform(-1, 1, (n, 4, 3)) * size
    t1 = t0 + rng.uniform(-1, 1, (n, 4, 3)) * size * 10 ** rng.uniform(-3, 0, (n, 1, 1))

    def call(threads):
        return polyccd.solve_linear_many("vertex-face", t0, t1, threads=threads)

    def key(b):
        return (b.collides.tobytes(), b.lo.tobytes(), b.hi.tobytes(), b.exact.tobytes(),
                tuple(b.stage))
    return f"{n} vertex-face queries", call, key


def cloth_frame(g, seed=2):
    """(V0, V1, F): a g x g grid over [0, 1]^2, and a step folding it."""
    u = np.linspace(0.0, 1.0, g)
    x, y = np.meshgrid(u, u, indexing="ij")
    V0 = np.stack([x, y, 0.02 * np.sin(9 * x) * np.cos(7 * y)], axis=-1).reshape(-1, 3)
    rng = np.random.default_rng(seed)
    fold = np.stack([-0.3 * np.clip(x - 0.5, 0, None) ** 2, 0 * x,
                     0.8 * np.clip(x - 0.5, 0, None) ** 2 * np.sin(3 * y)], axis=-1)
    V1 = V0 + fold.reshape(-1, 3) + rng.uniform(-1, 1, V0.shape) * (0.7 / g)
    idx = np.arange(g * g).reshape(g, g)
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[:-1, 1:], idx[1:, 1:]
    F = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3),
                        np.stack([a, d, c], -1).reshape(-1, 3)]).astype(np.int64)
    return V0, V1, F


def step_work(g):
    V0, V1, F = cloth_frame(g)

    def call(threads):
        return polyccd.check_step(V0, V1, F, threads=threads)

    def key(r):
        c = r.contacts
        return (r.collides, r.first_contact, r.stepsize, tuple(c.kind), c.indices.tobytes(),
                c.lo.tobytes(), c.hi.tobytes(), c.exact.tobytes())
    return f"cloth {len(F)} triangles", call, key


def index_work(nq, seed=3):
    stored = online_scenes.make_stored(polyccd, "mesh", 20000, seed)
    ix = polyccd.Index(polyccd.Body(stored["make"]()))
    queries, _ = online_scenes.make_queries(polyccd, "mesh", "rotation", nq, seed, stored)

    def call(threads):
        return ix.query_many(queries, threads=threads)

    def key(rs):
        return [(r.collides, r.first_contact, r.pairs, r.first) for r in rs]
    return f"{nq} queries, {stored['n']} triangles", call, key


def timed(call, threads, repeat):
    walls, cpus, mains, out = [], [], [], None
    for _ in range(repeat):
        w, c, m = time.perf_counter(), time.process_time(), time.thread_time()
        out = call(threads)
        walls.append(time.perf_counter() - w)
        cpus.append(time.process_time() - c)
        mains.append(time.thread_time() - m)
    return min(walls), min(cpus), min(mains), out


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--threads", default="1,2")
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--linear", type=int, default=200000)
    p.add_argument("--grid", type=int, default=101)
    p.add_argument("--queries", type=int, default=400)
    p.add_argument("--only", default="linear,step,index")
    a = p.parse_args(argv)
    threads = [int(t) for t in a.threads.split(",")]
    if threads[0] != 1:
        threads = [1] + threads
    makers = {"linear": lambda: linear_work(a.linear), "step": lambda: step_work(a.grid),
              "index": lambda: index_work(a.queries)}
    print(f"polyccd {polyccd.__version__}, {os.cpu_count()} CPUs, load "
          f"{os.getloadavg()[0]:.2f} at start, best of {a.repeat}, "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    print(f"{'call':8} {'workload':34} {'threads':>7} {'wall s':>8} {'CPU s':>8} "
          f"{'wall/1':>7} {'CPU/1':>6} {'caller/1':>8}  answers")
    status = 0
    for name in a.only.split(","):
        what, call, key = makers[name]()
        call(1)  # warm: caches, the pool's first start
        ref = None
        for th in threads:
            wall, cpu, main_cpu, out = timed(call, th, a.repeat)
            k = key(out)
            if ref is None:
                ref = (wall, cpu, k, main_cpu)
            same = k == ref[2]
            status |= 0 if same else 1
            print(f"{name:8} {what:34} {th:7d} {wall:8.4f} {cpu:8.4f} {wall / ref[0]:6.2f}x "
                  f"{cpu / ref[1]:5.2f}x {main_cpu / ref[3]:7.2f}x  "
                  f"{'identical' if same else 'DIFFERENT'}", flush=True)
    print(f"load {os.getloadavg()[0]:.2f} at the end")
    return status


if __name__ == "__main__":
    sys.exit(main())
