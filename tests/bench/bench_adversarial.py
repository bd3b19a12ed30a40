#!/usr/bin/env python3
"""Benchmark of the broad phases where bounding boxes cannot help (issue 26): the two-body
adversarial families of adversarial_families.py (slivers, plates, fans, needles, balls;
N = |B1| + |B2| primitives, both bodies large), timed with polyccd.check for each
broad phase (range, bvh, boxes, auto), and the on-line families of bench_online.py
(terrain, molecule slab; n stored primitives, n one-primitive queries, polyccd.Index),
where auto must stay near the fastest method. Prints the time table and the fitted
exponent of time against N per method and family, in one run.

A benchmark, not a test: it never asserts on speed. It checks answers: every method's
collides and first contact (lo, hi, exact) must equal the others' on every family and
size (the library's contract); a difference aborts the run.

Budget: a method runs at a size while its time predicted from the previous size
(x (N / N_prev)^2) fits in --budget-seconds (60 s); otherwise "-" and it is not fitted.
Timing: one process, threads 1, gc off; each cell is one polyccd.check (two-body) or one
Index.query_many (on-line) call, the Python reading of the results included. The on-line
families use the "linear" motions of bench_online.py.

Usage: python tests/bench/bench_adversarial.py [--sizes 1k,2k,4k,8k,16k]
           [--families slivers,plates,fans,needles,balls,terrain,mol]
           [--methods range,bvh,boxes,auto] [--motion translation|axis|general]
           [--budget-seconds 60] [--repeat 1] [--json FILE] [--tables-of FILE]
"""

import argparse
import gc
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import adversarial_families as af  # noqa: E402
from bench_bodies import fit_exponent  # noqa: E402

ONLINE = {"terrain": "mesh", "mol": "mol"}   # bench_online.py's classes
METHODS = ("range", "bvh", "boxes", "auto")


def parse_size(s):
    s = s.strip().lower()
    return int(float(s[:-1]) * 1000) if s.endswith("k") else int(s)


def answer(r):
    ct = r.first_contact
    return (r.collides, None if ct is None else (ct.lo, ct.hi, ct.exact))


def timed(fn):
    gc.collect()
    gc.disable()
    try:
        t0 = time.perf_counter()
        res = fn()
        return time.perf_counter() - t0, res
    finally:
        gc.enable()


def case_runner(polyccd, family, n, motion):
    """fn(method) -> (seconds, answers, stats) for one family and size."""
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
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="1k,2k,4k,8k,16k")
    ap.add_argument("--families", default=",".join(af.FAMILIES + tuple(ONLINE)))
    ap.add_argument("--methods", default=",".join(METHODS))
    ap.add_argument("--budget-seconds", type=float, default=60.0)
    ap.add_argument("--motion", default="translation", choices=af.MOTIONS,
                    help="body 1's motion in the two-body families (adversarial_families.py)")
    ap.add_argument("--json", default=None, help="write every measurement here")
    ap.add_argument("--repeat", type=int, default=1, help="each cell: the minimum of this many runs")
    ap.add_argument("--fit-from", default="1k", help="the second exponent column fits N >= this")
    ap.add_argument("--tables-of", default=None, help="only print the tables of a --json file")
    opts = ap.parse_args()
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
          f"budget {opts.budget_seconds} s, threads 1")
    for family in opts.families.split(","):
        times = {m: {} for m in methods}
        last = {}
        for n in sizes:
            run = case_runner(polyccd, family, n, opts.motion)
            ref = None
            for m in methods:
                if m in last and last[m][1] * (n / last[m][0]) ** 2 > opts.budget_seconds:
                    continue
                dt, ans, st = run(m)
                for _ in range(opts.repeat - 1):      # the minimum over --repeat runs
                    dt = min(dt, run(m)[0])
                last[m] = (n, dt)
                times[m][n] = dt
                if ref is None:
                    ref = (m, ans)
                elif ans != ref[1]:
                    bad = next(i for i, (a, b) in enumerate(zip(ans, ref[1])) if a != b)
                    print(f"ERROR: {family} N = {n}: {m} and {ref[0]} disagree (item {bad}: "
                          f"{ans[bad]} vs {ref[1][bad]}): a bug of polyccd")
                    sys.exit(1)
                print(f"  {family:8s} N = {n:6d}  {m:5s} {dt:9.3f} s  {st}", flush=True)
        out[family] = {m: {str(n): t for n, t in times[m].items()} for m in methods}
    print_tables(out, sizes, methods, parse_size(opts.fit_from))
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump(out, f, indent=1)


def exponent(res, m, lo=0):
    return fit_exponent(sorted((int(n), t) for n, t in res.get(m, {}).items() if int(n) >= lo))


def print_tables(out, sizes, methods, fit_from):
    print("\nTime (s) per family, method and N; '-': over budget (not run)")
    head = "| family | method | " + " | ".join(f"N={n}" for n in sizes) + " |"
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for family, res in out.items():
        for m in methods:
            cells = [f"{res[m][str(n)]:.3f}" if str(n) in res.get(m, {}) else "-" for n in sizes]
            print(f"| {family} | {m} | " + " | ".join(cells) + " |")
    print(f"\nFitted exponents (least squares of log time on log N over the measured sizes: "
          f"all / N >= {fit_from}; '-': fewer than two sizes)")
    print("| family | " + " | ".join(methods) + " | auto / fastest (worst size) |")
    print("|" + "---|" * (len(methods) + 2))

    def fmt(e):
        return "-" if e is None else f"{e:.2f}"
    for family, res in out.items():
        ex = [f"{fmt(exponent(res, m))} / {fmt(exponent(res, m, fit_from))}" for m in methods]
        worst = None
        if "auto" in methods:
            for n in sizes:
                ts = [res[m][str(n)] for m in methods if str(n) in res.get(m, {})]
                if str(n) in res.get("auto", {}) and ts:
                    r = res["auto"][str(n)] / min(ts)
                    worst = r if worst is None else max(worst, r)
        print(f"| {family} | " + " | ".join(ex) + f" | {fmt(worst)} |")


if __name__ == "__main__":
    main()
