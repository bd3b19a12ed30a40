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

Clusters: 1 and 2 worker processes (each with a nanny) and 2 worker threads in this
process (cluster(processes=False): no pickling, no copies, no other process).

Where it pays (--sweep): --sweep-tasks tasks of solve_linear_many over a slice of
random vertex-face steps (the arrays scattered once), each task sized to the given
milliseconds of serial CPU time (calibrated here first), on 2 worker processes and on 2
worker threads against the same slices solved serially in this process. Each of
--sweep-repeat rounds times the serial run and then the cluster's, so that a change in
the machine's load hits both alike; the table gives the medians, the median of the
rounds' speed-ups (serial / cluster) with their range, and the CPU share: the serial
run's CPU time over the CPU time of every process of the cluster during its run (1.0:
the cluster spends nothing beyond the work; 2 workers can reach at most twice it), and
the cluster's CPU time outside the tasks' library calls, per task (scheduler, nannies,
event loops, pickling).

Usage: python tests/bench/bench_distributed.py [--queries N] [--repeat R] [--tasks T]
           [--sweep 0.5,2,8,32,128] [--sweep-tasks 24] [--sweep-repeat 5]
"""
import argparse
import os
import statistics
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
    """One answer per (a, b) slice: (how many of its queries collide, the CPU seconds of
    this thread in the call)."""
    out = []
    for a, b in chunk:
        start = time.thread_time()
        hits = int(polyccd.solve_linear_many("vertex-face", t0[a:b], t1[a:b]).collides.sum())
        out.append((hits, time.thread_time() - start))
    return out


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


def sweep_data(n=400_000):
    rng = np.random.default_rng(5)
    size = 10 ** rng.uniform(-2, 0, (n, 1, 1))
    t0 = rng.uniform(-1, 1, (n, 4, 3)) * size
    t1 = t0 + rng.uniform(-1, 1, (n, 4, 3)) * size * 10 ** rng.uniform(-3, 0, (n, 1, 1))
    # The cost per query from the calls' CPU time (the least of 3), not the wall clock,
    # which the machine's load inflates: the tasks' sizes then do not depend on it.
    per_query = min(solve_slices([(0, 50_000)], t0, t1)[0][1] for _ in range(3))
    return t0, t1, per_query / 50_000


def sweep(client, data, ms_list, tasks, repeat):
    """[(ms per task, queries per task, serial s, cluster s, speed-ups, CPU shares, CPU
    beside the tasks' calls per task, same answers)] for each size: medians of `repeat`
    rounds of serial then cluster (speed-ups and shares: one per round)."""
    t0, t1, per_query = data
    n = len(t0)
    f0, f1 = client.scatter([t0], broadcast=True)[0], client.scatter([t1], broadcast=True)[0]
    rows = []
    for ms in ms_list:
        m = max(1, min(n, round(ms / 1e3 / per_query)))
        slices = [(a, a + m) for a in ((k * m) % (n - m + 1) for k in range(tasks))]  # may overlap
        serial, dist, share, beside, same = [], [], [], [], True
        for _ in range(repeat):
            c0, w0 = time.process_time(), time.perf_counter()
            ref = solve_slices(slices, t0, t1)
            serial.append(time.perf_counter() - w0)
            serial_cpu = time.process_time() - c0
            c1, w1 = cluster_cpu(), time.perf_counter()
            got = list(pd.map_chunks(solve_slices, slices, f0, f1, client=client,
                                     chunk_size=1, progress=False))
            dist.append(time.perf_counter() - w1)
            spent = cluster_cpu() - c1
            share.append(serial_cpu / max(spent, 1e-9))
            beside.append((spent - sum(cpu for _, cpu in got)) / tasks)
            same = same and [h for h, _ in got] == [h for h, _ in ref]
        rows.append((ms, m, statistics.median(serial), statistics.median(dist),
                     [s / d for s, d in zip(serial, dist)], share, statistics.median(beside),
                     same))
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
    p.add_argument("--sweep-repeat", type=int, default=5, help="rounds; medians are shown")
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
          f"{os.getloadavg()[0]:.2f}; workloads: best of {args.repeat}")
    serial = {name: best(w[1], args.repeat) for name, w in work.items()}
    ms_list = [float(x) for x in args.sweep.split(",")] if args.sweep else []
    data = sweep_data() if ms_list else None
    # (name, workers, processes): the columns of the tables
    clusters = [("1 process", 1, True), ("2 processes", 2, True), ("2 threads", 2, False)]
    rows = {name: [] for name in work}
    first_call, overhead, swept = {}, {}, {}
    for label, workers, processes in clusters:
        start = time.perf_counter()
        with pd.cluster(workers=workers, processes=processes) as client:
            client.wait_for_workers(workers)
            started = time.perf_counter() - start
            for name, (_, _, dist, key) in work.items():
                if name == "index":
                    first_call[label], _ = best(lambda: dist(client), 1)
                seconds, answers = best(lambda: dist(client), args.repeat)
                same = key(answers) == key(serial[name][1])
                rows[name].append((seconds, same))
            cpu = cluster_cpu()
            wall, _ = best(lambda: list(pd.map_chunks(
                nothing, range(args.tasks), client=client, chunk_size=1,
                progress=False)), args.repeat)
            overhead[label] = (wall, (cluster_cpu() - cpu) / args.repeat)
            if workers == 2 and ms_list:
                swept[label] = sweep(client, data, ms_list, args.sweep_tasks, args.sweep_repeat)
        print(f"LocalCluster of {label} started in {started:.2f} s")
    head = "".join(f" {label + ' s':>13} {'speed-up':>9}" for label, *_ in clusters)
    print(f"\n{'workload':10} {'size':>14} {'serial s':>9}{head}  answers")
    for name, (size, *_rest) in work.items():
        s = serial[name][0]
        cells = "".join(f" {t:13.3f} {s / t:8.2f}x" for t, _ in rows[name])
        same = all(same for _, same in rows[name])
        print(f"{name:10} {size:>14} {s:9.3f}{cells}  {'identical' if same else 'DIFFERENT'}")
    print("index: first call (sends the body, builds its Index on the workers) " +
          ", ".join(f"{first_call[label]:.3f} s on {label}" for label, *_ in clusters))
    print(f"\noverhead per task ({args.tasks} one-item tasks doing nothing, best of "
          f"{args.repeat}): wall / CPU of all the cluster's processes")
    for label, (wall, cpu) in overhead.items():
        print(f"  {label:12} {wall / args.tasks * 1e3:6.2f} ms wall, "
              f"{cpu / args.tasks * 1e3:6.2f} ms CPU")
    if not ms_list:
        return 0
    print(f"\nwhere it pays: {args.sweep_tasks} tasks of solve_linear_many slices against "
          f"serial, medians of {args.sweep_repeat} rounds (speed-up: median [min-max]; "
          f"CPU: serial CPU / the cluster's CPU; beside: the cluster's CPU outside the "
          f"tasks' calls, ms per task)")
    labels = list(swept)
    print(f"{'ms/task':>8} {'queries/task':>12} {'serial s':>9}" +
          "".join(f" {label + ' s':>13} {'speed-up':>20} {'CPU':>5} {'beside':>6}"
                  for label in labels) +
          "  answers")
    for i, ms in enumerate(ms_list):
        line, same = "", True
        for label in labels:
            _, m, s, d, ups, share, beside, ok = swept[label][i]
            line += (f" {d:13.3f} {statistics.median(ups):6.2f}x [{min(ups):4.2f}-{max(ups):4.2f}]"
                     f" {statistics.median(share):5.2f} {beside * 1e3:6.1f}")
            same = same and ok
        serial_s = statistics.median([swept[label][i][2] for label in labels])
        print(f"{ms:8g} {m:12d} {serial_s:9.3f}{line}  {'identical' if same else 'DIFFERENT'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
