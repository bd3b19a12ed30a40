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
(starting it is timed separately). The overhead per task is the time of map_chunks of a
function doing nothing over --tasks one-item chunks on 1 worker, divided by --tasks.

Usage: python tests/bench/bench_distributed.py [--queries N] [--repeat R] [--tasks T]
"""
import argparse
import os
import sys
import time
from pathlib import Path

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
    for workers in (1, 2):
        start = time.perf_counter()
        with pd.cluster(workers=workers) as client:
            client.wait_for_workers(workers)
            started = time.perf_counter() - start
            for name, (_, _, dist, key) in work.items():
                seconds, answers = best(lambda: dist(client), args.repeat)
                same = key(answers) == key(serial[name][1])
                rows[name].append((seconds, same))
            if workers == 1:
                overhead, _ = best(lambda: list(pd.map_chunks(
                    nothing, range(args.tasks), client=client, chunk_size=1,
                    progress=False)), args.repeat)
        print(f"LocalCluster of {workers} worker process(es) started in {started:.2f} s")
    print(f"\n{'workload':10} {'size':>14} {'serial s':>9} {'1 worker s':>11} {'speed-up':>9} "
          f"{'2 workers s':>12} {'speed-up':>9}  answers")
    for name, (size, *_rest) in work.items():
        s = serial[name][0]
        (t1, same1), (t2, same2) = rows[name]
        print(f"{name:10} {size:>14} {s:9.3f} {t1:11.3f} {s / t1:8.2f}x {t2:12.3f} "
              f"{s / t2:8.2f}x  {'identical' if same1 and same2 else 'DIFFERENT'}")
    print(f"\noverhead per task (1 worker, {args.tasks} one-item tasks doing nothing): "
          f"{overhead / args.tasks * 1e3:.2f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
