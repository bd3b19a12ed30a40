#!/usr/bin/env python3
"""Benchmark of the broad phases where bounding boxes cannot help (issue 26): the two-body
adversarial families of adversarial_families.py (slivers, plates, fans, needles, balls;
N = |B1| + |B2| primitives, both bodies large), timed with polyccd.check for each
broad phase (range, bvh, boxes, auto); the on-line adversarial families of
online_families.py (issue 31: tneedles, shells, turned; N stored triangles in a
polyccd.Index, --queries one-triangle queries, so a cell's time is per-query time times
a constant); and the on-line families of bench_online.py (terrain, molecule slab; n
stored primitives, n one-primitive queries), where auto must stay near the fastest
method. Prints the time table and the fitted exponent of time against N per method and
family, in one run; the exponents table adds auto's per-query exponent (the two-body and
bench_online families answer N queries: their exponent minus 1; online_families: the
exponent itself), against the paper's on-line bound n^0.6 per query.

A benchmark, not a test: it never asserts on speed. It checks answers: every method's
collides and first contact (lo, hi, exact) must equal the others' on every family and
size (the library's contract); a difference aborts the run.

Budget: a method runs at a size while its time predicted from the previous size
(x (N / N_prev)^2) fits in --budget-seconds (30 s), and stops for good once one of its
sizes took more than --cap-seconds (30 s); otherwise "-" and it is not fitted. The
exponents are fitted on N >= --fit-from (1k), or, for a method that reached fewer than
two such sizes (bvh, boxes), on every size it reached; each states its sizes.
Timing: one process, threads 1, gc off, the process's CPU time (--clock cpu, the default:
on a machine shared with other processes elapsed time varied up to 2x between adjacent
runs of the same code) or elapsed time (--clock wall); each cell is one polyccd.check (two-body) or one
Index.query_many (on-line) call, the Python reading of the results included. The on-line
families use the "linear" motions of bench_online.py. With --repeat R every cell is run R
times (round robin over the methods at each size, so that a burst of load from other
processes hits every method alike; the first round prints): the table shows the minimum,
and the exponents table the fit of the minima with, in brackets, the lowest and highest
exponent fitted on the r-th runs alone (r = 1..R): the spread that load gives a fit.

Usage: python tests/bench/bench_adversarial.py [--sizes 125,250,500,1k,2k,4k,8k,16k]
           [--families slivers,plates,fans,needles,balls,tneedles,shells,turned,terrain,mol]
           [--methods range,bvh,boxes,auto] [--motion translation|axis|general]
           [--budget-seconds 30] [--cap-seconds 30] [--repeat 1] [--fit-from 1k]
           [--clock cpu|wall] [--queries 200] [--json FILE] [--tables-of FILE]
"""

import argparse
import gc
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import adversarial_families as af  # noqa: E402
import online_families as of  # noqa: E402
from bench_bodies import fit_exponent  # noqa: E402

ONLINE = {"terrain": "mesh", "mol": "mol"}   # bench_online.py's classes
METHODS = ("range", "bvh", "boxes", "auto")


def parse_size(s):
    s = s.strip().lower()
    return int(float(s[:-1]) * 1000) if s.endswith("k") else int(s)


def answer(r):
    ct = r.first_contact
    return (r.collides, None if ct is None else (ct.lo, ct.hi, ct.exact))


CLOCK = {"wall": time.perf_counter, "cpu": time.process_time}
clock = CLOCK["cpu"]


def timed(fn):
    gc.collect()
    gc.disable()
    try:
        t0 = clock()
        res = fn()
        return clock() - t0, res
    finally:
        gc.enable()


def case_runner(polyccd, family, n, motion, queries=200):
    """fn(method) -> (seconds, answers, stats) for one family and size."""
    if family in of.FAMILIES:                   # one stored body of n triangles, `queries` queries
        stored, qs = of.make(polyccd, family, n, queries)
        ix = polyccd.Index(stored)

        def run(method):
            dt, res = timed(lambda: ix.query_many(qs, broad_phase=method, threads=1))
            cand = sum(r.stats["candidates"] for r in res)
            return dt, [answer(r) for r in res], {"candidates": cand}
        return run
    if family in ONLINE:
        import bench_online as bo
        cls = ONLINE[family]
        stored = bo.make_stored(polyccd, cls, n, 1)
        ix = polyccd.Index(polyccd.Body(stored["make"]()))
        queries, _ = bo.make_queries(polyccd, cls, "linear", n, 1, stored)

        def run(method):
            dt, res = timed(lambda: ix.query_many(queries, broad_phase=method, threads=1))
            cand = sum(r.stats["candidates"] for r in res)
            return dt, [answer(r) for r in res], {"candidates": cand}
        return run
    bodies = af.make(polyccd, family, n, motion=motion)

    def run(method):
        dt, r = timed(lambda: polyccd.check(bodies, broad_phase=method, threads=1))
        return dt, [answer(r)], {"candidates": r.stats["candidates"], "static": r.stats["static_tests"]}
    return run


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="125,250,500,1k,2k,4k,8k,16k")
    ap.add_argument("--families", default=",".join(af.FAMILIES + of.FAMILIES + tuple(ONLINE)))
    ap.add_argument("--queries", type=int, default=200, help="queries per size (online_families.py)")
    ap.add_argument("--methods", default=",".join(METHODS))
    ap.add_argument("--budget-seconds", type=float, default=30.0)
    ap.add_argument("--cap-seconds", type=float, default=30.0,
                    help="a method stops once one of its sizes took longer than this")
    ap.add_argument("--motion", default="translation", choices=af.MOTIONS,
                    help="body 1's motion in the two-body families (adversarial_families.py)")
    ap.add_argument("--json", default=None, help="write every measurement here")
    ap.add_argument("--repeat", type=int, default=1, help="each cell: the minimum of this many runs")
    ap.add_argument("--fit-from", default="1k",
                    help="fit on N >= this (a method with fewer than two such sizes: on all it reached)")
    ap.add_argument("--tables-of", default=None, help="only print the tables of a --json file")
    ap.add_argument("--clock", default="cpu", choices=sorted(CLOCK),
                    help="cpu: the process's CPU time (threads 1; what other processes' load "
                         "does not change), wall: elapsed time")
    opts = ap.parse_args()
    global clock
    clock = CLOCK[opts.clock]
    sizes = [parse_size(s) for s in opts.sizes.split(",")]
    methods = opts.methods.split(",")
    if opts.tables_of:
        with open(opts.tables_of) as f:
            out = json.load(f)
        sizes = sorted({int(n) for res in out.values() for m in methods for n in res.get(m, {})})
        return print_tables(out, sizes, methods, parse_size(opts.fit_from))
    import polyccd
    out = {}
    print(f"bench_adversarial: sizes {sizes}, methods {methods}, motion {opts.motion}, "
          f"budget {opts.budget_seconds} s, cap {opts.cap_seconds} s, repeat {opts.repeat}, threads 1, "
          f"clock {opts.clock}")
    for family in opts.families.split(","):
        times = {m: {} for m in methods}
        last, capped = {}, set()
        for n in sizes:
            run = case_runner(polyccd, family, n, opts.motion, opts.queries)
            ref = None
            todo = [m for m in methods if m not in capped and not (
                m in last and last[m][1] * (n / last[m][0]) ** 2 > opts.budget_seconds)]
            runs = {m: [] for m in todo}
            for r in range(opts.repeat):   # round robin: load bursts hit every method alike
                for m in todo:
                    dt, ans, st = run(m)
                    runs[m].append(dt)
                    if r > 0:
                        continue
                    if ref is None:
                        ref = (m, ans)
                    elif ans != ref[1]:
                        bad = next(i for i, (a, b) in enumerate(zip(ans, ref[1])) if a != b)
                        print(f"ERROR: {family} N = {n}: {m} and {ref[0]} disagree (item {bad}: "
                              f"{ans[bad]} vs {ref[1][bad]}): a bug of polyccd")
                        sys.exit(1)
                    print(f"  {family:8s} N = {n:6d}  {m:5s} {dt:9.3f} s  {st}", flush=True)
            for m in todo:
                last[m] = (n, min(runs[m]))
                times[m][n] = runs[m]
                if opts.cap_seconds is not None and min(runs[m]) > opts.cap_seconds:
                    capped.add(m)
        out[family] = {m: {str(n): t for n, t in times[m].items()} for m in methods}
    print_tables(out, sizes, methods, parse_size(opts.fit_from))
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump(out, f, indent=1)


def runs_of(cell):
    """A cell's times: a list (--repeat), or one number (older --json files)."""
    return cell if isinstance(cell, list) else [cell]


def fitted(res, m, lo):
    """(exponent of the minima, (lowest, highest) over the r-th runs, (N_lo, N_hi)) or None:
    over the sizes >= lo, or all the sizes m reached when fewer than two are >= lo."""
    cells = sorted((int(n), runs_of(c)) for n, c in res.get(m, {}).items())
    if sum(n >= lo for n, _ in cells) >= 2:    # else every size it reached (bvh, boxes)
        cells = [(n, r) for n, r in cells if n >= lo]
    e = fit_exponent([(n, min(r)) for n, r in cells])
    if e is None:
        return None
    reps = min(len(r) for _, r in cells)
    each = [fit_exponent([(n, r[i]) for n, r in cells]) for i in range(reps)]
    return e, (min(each), max(each)), (cells[0][0], cells[-1][0])


def size_name(n):
    return f"{n // 1000}k" if n >= 1000 and n % 1000 == 0 else str(n)


def print_tables(out, sizes, methods, fit_from):
    print("\nTime (s) per family, method and N (the minimum of the runs); '-': not run (budget, cap)")
    head = "| family | method | " + " | ".join(f"N={n}" for n in sizes) + " |"
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for family, res in out.items():
        for m in methods:
            cells = [f"{min(runs_of(res[m][str(n)])):.3f}" if str(n) in res.get(m, {}) else "-"
                     for n in sizes]
            print(f"| {family} | {m} | " + " | ".join(cells) + " |")
    print(f"\nFitted exponents (least squares of log time on log N over the sizes measured, "
          f"N >= {fit_from} where a method reached two such sizes, else all it reached: the fit "
          f"of the minima [lowest-highest fit of single runs] (sizes fitted))")
    print("| family | " + " | ".join(methods) + " | auto / fastest (worst size) | auto per query |")
    print("|" + "---|" * (len(methods) + 3))
    for family, res in out.items():
        ex = []
        for m in methods:
            f = fitted(res, m, fit_from)
            ex.append("-" if f is None else
                      f"{f[0]:.2f} [{f[1][0]:.2f}-{f[1][1]:.2f}] ({size_name(f[2][0])}-{size_name(f[2][1])})")
        worst = None
        if "auto" in methods:
            for n in sizes:
                ts = [min(runs_of(res[m][str(n)])) for m in methods if str(n) in res.get(m, {})]
                if str(n) in res.get("auto", {}) and ts:
                    r = min(runs_of(res["auto"][str(n)])) / min(ts)
                    worst = r if worst is None else max(worst, r)
        fa = fitted(res, "auto", fit_from) if "auto" in methods else None
        per_query = "-" if fa is None else f"{fa[0] - (0 if family in of.FAMILIES else 1):.2f}"
        print(f"| {family} | " + " | ".join(ex) + f" | {'-' if worst is None else f'{worst:.2f}'} | {per_query} |")


if __name__ == "__main__":
    main()
