#!/usr/bin/env python3
"""Benchmark: polyccd.apps.distributed on an embedded dask LocalCluster of 1 and 2 worker
processes against the serial run, and the overhead of one task.

`make bench` runs this file. A benchmark, not a test: it never asserts on speed, only
that every distributed answer equals the serial one (else the speed would mean nothing).
Workloads (one process each, the serial time measured in this process, one thread):
  index    one stored plate, N query balls all falling through it (Index.query_many
           serially; polyccd.apps.distributed.index_map on the cluster)
  queries  the shared query set, one task per CSV file (polyccd queries; queries_map)
  corpus   every case of corpus/ (polyccd corpus; corpus_map)
Each distributed time is the best of --repeat runs on a cluster already started
(starting it is timed separately; the index workload's first call, which sends the
stored body and builds its Index on the workers, is shown apart: later calls reuse
both). The overhead per task is the time of map_chunks of a function doing nothing
over --tasks one-item chunks on 1 worker, divided by --tasks, with the CPU time of all
the cluster's processes per task beside it (the part a loaded machine cannot hide).

Where it pays (--sweep): --sweep-tasks tasks of solve_linear_many over a slice of
random vertex-face steps (the arrays scattered once), each task sized to the given
milliseconds of serial work (calibrated here first), on 2 workers against the same
slices solved serially in this process: the speed-up as a function of work per task.

Usage: python tests/bench/bench_distributed.py [--queries N] [--repeat R] [--tasks T]
           [--sweep 0.5,2,8,32,128] [--sweep-tasks 24]
"""
import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np
import psutil

import polyccd
import polyccd.apps.distributed as pd
from polyccd import Body, Index, Mesh, Motion, Spheres
from polyccd.apps._corpus import check_case, files_under
from polyccd.apps._queries import run_file

REPO = Path(__file__).resolve().parents[2]


def query_dir():
    env = os.environ.get("POLYCCD_QUERY_DIR")
    return Path(env) if env else (REPO / ".." / "shared" / "data" / "ccd-queries").resolve()


def index_workload(n):
    plate = Body(Mesh([[-4, -4, 0], [4, -4, 0], [-4, 4, 0], [4, 4, 0]],
                      [[0, 1, 3], [0, 3, 2]]), name="plate")
    ball = Spheres([[0, 0, 0]], ["1/4"])
    queries = [Body(ball, Motion.linear([k % 7 - 3, 0, 1 + k % 5], [k % 7 - 3, k % 3, -1]))
               for k in range(n)]
    return plate, queries


def nothing(chunk):
    return [None] * len(chunk)


def solve_slices(chunk, t0, t1):
    """One answer per (a, b) slice: how many of its queries collide."""
    return [int(polyccd.solve_linear_many("vertex-face", t0[a:b], t1[a:b]).collides.sum())
            for a, b in chunk]


def cluster_cpu():
    """CPU seconds of this process and all its children (the embedded cluster)."""
    me = psutil.Process()
    total = 0.0
    for p in [me] + me.children(recursive=True):
        try:
            t = p.cpu_times()
            total += t.user + t.system
        except psutil.Error:
            pass
    return total


def sweep(client, ms_list, tasks, repeat):
    """[(ms per task, queries per task, serial s, 2 workers s, same)] for each size."""
    rng = np.random.default_rng(5)
    n = 400_000
    size = 10 ** rng.uniform(-2, 0, (n, 1, 1))
    t0 = rng.uniform(-1, 1, (n, 4, 3)) * size
    t1 = t0 + rng.uniform(-1, 1, (n, 4, 3)) * size * 10 ** rng.uniform(-3, 0, (n, 1, 1))
    per_query, _ = best(lambda: solve_slices([(0, 50_000)], t0, t1), repeat)
    per_query /= 50_000
    f0, f1 = client.scatter([t0], broadcast=True)[0], client.scatter([t1], broadcast=True)[0]
    rows = []
    for ms in ms_list:
        m = max(1, min(n, round(ms / 1e3 / per_query)))
        slices = [(a, a + m) for a in ((k * m) % (n - m + 1) for k in range(tasks))]  # may overlap
        serial, ref = best(lambda: solve_slices(slices, t0, t1), repeat)
        dist, got = best(lambda: list(pd.map_chunks(solve_slices, slices, f0, f1, client=client,
                                                    chunk_size=1, progress=False)), repeat)
        rows.append((ms, m, serial, dist, got == ref))
    return rows


def best(fn, repeat):
    times, out = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return min(times), out


def main(argv=None):
    p = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.splitlines()[0])
    p.add_argument("--queries", type=int, default=10000)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--tasks", type=int, default=1000)
    p.add_argument("--sweep", default="0.5,2,8,32,128", help="ms of work per task")
    p.add_argument("--sweep-tasks", type=int, default=24)
    args = p.parse_args(argv)

    plate, queries = index_workload(args.queries)
    csvs = files_under([query_dir()], "*.csv")
    cases = files_under([REPO / "corpus"], "*.json")
    strip = lambda r: (r.as_json()["positives"], r.mismatches)  # noqa: E731
    work = {
        "index": (f"{len(queries)} queries",
                  lambda: Index(plate).query_many(queries),
                  lambda c: list(pd.index_map(plate, queries, client=c, progress=False)),
                  lambda a: a),
        "queries": (f"{len(csvs)} files",
                    lambda: [run_file(f) for f in csvs],
                    lambda c: list(pd.queries_map(csvs, client=c, progress=False)),
                    lambda a: [strip(r) for r in a]),
        "corpus": (f"{len(cases)} cases",
                   lambda: [check_case(f) for f in cases],
                   lambda c: list(pd.corpus_map(cases, client=c, progress=False)),
                   lambda a: a),
    }
    print(f"polyccd {polyccd.__version__}, polyccd.apps.distributed on dask "
          f"{pd._distributed.__version__}, {os.cpu_count()} CPUs, load "
          f"{os.getloadavg()[0]:.2f}; best of {args.repeat}")
    serial = {name: best(w[1], args.repeat) for name, w in work.items()}
    rows = {name: [] for name in work}
    first_call = {}
    for workers in (1, 2):
        start = time.perf_counter()
        with pd.cluster(workers=workers) as client:
            client.wait_for_workers(workers)
            started = time.perf_counter() - start
            for name, (_, _, dist, key) in work.items():
                if name == "index":
                    first_call[workers], _ = best(lambda: dist(client), 1)
                seconds, answers = best(lambda: dist(client), args.repeat)
                same = key(answers) == key(serial[name][1])
                rows[name].append((seconds, same))
            if workers == 1:
                cpu = cluster_cpu()
                overhead, _ = best(lambda: list(pd.map_chunks(
                    nothing, range(args.tasks), client=client, chunk_size=1,
                    progress=False)), args.repeat)
                overhead_cpu = (cluster_cpu() - cpu) / args.repeat
            else:
                swept = sweep(client, [float(x) for x in args.sweep.split(",")],
                              args.sweep_tasks, args.repeat)
        print(f"LocalCluster of {workers} worker process(es) started in {started:.2f} s")
    print(f"\n{'workload':10} {'size':>14} {'serial s':>9} {'1 worker s':>11} {'speed-up':>9} "
          f"{'2 workers s':>12} {'speed-up':>9}  answers")
    for name, (size, *_rest) in work.items():
        s = serial[name][0]
        (t1, same1), (t2, same2) = rows[name]
        print(f"{name:10} {size:>14} {s:9.3f} {t1:11.3f} {s / t1:8.2f}x {t2:12.3f} "
              f"{s / t2:8.2f}x  {'identical' if same1 and same2 else 'DIFFERENT'}")
    print(f"index: first call (sends the body, builds its Index on the workers) "
          f"{first_call[1]:.3f} s on 1 worker, {first_call[2]:.3f} s on 2")
    print(f"\noverhead per task (1 worker, {args.tasks} one-item tasks doing nothing): "
          f"{overhead / args.tasks * 1e3:.2f} ms wall, "
          f"{overhead_cpu / args.tasks * 1e3:.2f} ms CPU of all processes")
    print(f"\nwhere it pays: {args.sweep_tasks} tasks of solve_linear_many slices, "
          f"2 workers against serial")
    print(f"{'ms/task':>8} {'queries/task':>12} {'serial s':>9} {'2 workers s':>12} "
          f"{'speed-up':>9}  answers")
    for ms, m, s, d, same in swept:
        print(f"{ms:8g} {m:12d} {s:9.3f} {d:12.3f} {s / d:8.2f}x  "
              f"{'identical' if same else 'DIFFERENT'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
