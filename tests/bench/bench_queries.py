#!/usr/bin/env python3
"""Benchmark: polyccd against Tight Inclusion (ipctk) on the public CCD queries.

`make bench` runs this file. A benchmark, not a test: it never asserts on speed or on
answers (false positives / negatives are reported, not judged) and never runs in
`make test`. The only assertions are about the input: every coordinate of the CSV
(num/den with den a power of two) must convert to a float64 exactly.

In ONE process, on the same queries (default: every CSV under
$POLYCCD_QUERY_DIR, default ../shared/data/ccd-queries relative to the repo root;
2,824 queries), with the inputs prepared beforehand as float64 arrays and the same loop
for every method (time.perf_counter_ns around each single call, garbage collector off),
it measures (queries grouped by kind, vertex-face first, so every method calls one
function per kind without a dispatch in the timed region):
  polyccd-decide  polyccd.collides_linear(kind, p_t0, p_t1)
  polyccd-time    polyccd.solve_linear(kind, p_t0, p_t1, time_tolerance="1e-6")
  TI              ipctk.tight_inclusion.point_triangle_ccd / edge_edge_ccd(8 points,
                  min_distance=0, tolerance=1e-6, max_iterations=1_000_000)
Each method runs --repeat rounds (default 3; method order rotated per round, after an
untimed warm-up on the first 100 queries of each kind); a query's time is its minimum over the rounds, its answer the one of
the first round. Prints machine info, a table of false positives / negatives and
median / mean / p99 microseconds per query, the polyccd/TI ratios, which engine stage
(Result.stage) decided the queries, and a per-scene breakdown.

Usage: python tests/bench/bench_queries.py [--repeat N] [--limit N] [--no-ti] [--json FILE]
"""

import argparse
import csv
import datetime
import gc
import json
import os
import platform
import sys
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_report import cpu_model, pkg_version, print_table  # noqa: E402

REPO = Path(__file__).resolve().parents[2]
KIND_POINTS = {"vertex-face": 4, "edge-edge": 4}
STAGES = ("bounds", "bernstein", "interval", "exact")


# ---------------------------------------------------------------------------------------
# Input


def query_dir():
    env = os.environ.get("POLYCCD_QUERY_DIR")
    return Path(env) if env else (REPO / ".." / "shared" / "data" / "ccd-queries").resolve()


def exact_double(num, den):
    """num/den (den a power of two) as a float64, asserting the conversion is exact."""
    assert den > 0 and den & (den - 1) == 0, f"denominator {den} is not a power of two"
    x = float(Fraction(num, den))  # correctly rounded
    assert Fraction(x) == Fraction(num, den), f"{num}/{den} is not exactly a double"
    return x


class Query:
    __slots__ = ("scene", "kind", "file", "index", "truth", "p_t0", "p_t1", "points8")

    def __init__(self, scene, kind, file, index, truth, p_t0, p_t1):
        self.scene, self.kind, self.file, self.index = scene, kind, file, index
        self.truth = truth
        self.p_t0 = p_t0  # (4, 3) float64, C-contiguous
        self.p_t1 = p_t1
        # Tight Inclusion's 8 separate points (t0 rows then t1 rows), each its own array
        self.points8 = tuple(np.ascontiguousarray(r) for r in np.vstack([p_t0, p_t1]))


def load_queries(root):
    files = sorted(root.rglob("*.csv"))
    if not files:
        sys.exit(f"no *.csv under {root} (set POLYCCD_QUERY_DIR)")
    queries = []
    for path in files:
        kind = path.parent.name
        if kind not in KIND_POINTS:
            sys.exit(f"{path}: folder name {kind!r} is not vertex-face or edge-edge")
        rel = path.relative_to(root)
        scene = rel.parts[0] if len(rel.parts) > 2 else "."
        with open(path, newline="") as f:
            rows = [[int(c) for c in row] for row in csv.reader(f) if row]
        assert len(rows) % 8 == 0, f"{path}: {len(rows)} rows, not a multiple of 8"
        for i in range(0, len(rows), 8):
            block = rows[i : i + 8]
            truths = {r[6] for r in block}
            assert len(truths) == 1 and truths <= {0, 1}, f"{path} query {i // 8}: truth {truths}"
            pts = np.array(
                [[exact_double(r[0], r[1]), exact_double(r[2], r[3]), exact_double(r[4], r[5])] for r in block],
                dtype=np.float64,
            )
            queries.append(
                Query(scene, kind, str(rel), i // 8, truths.pop() == 1,
                      np.ascontiguousarray(pts[:4]), np.ascontiguousarray(pts[4:]))
            )
    return queries


# ---------------------------------------------------------------------------------------
# Measurement


def timed_loop(fn, arglists, kw):
    """The one loop every method goes through: perf_counter_ns around each single call."""
    n = len(arglists)
    times = np.empty(n, dtype=np.int64)
    outs = [None] * n
    clock = time.perf_counter_ns
    for i in range(n):
        args = arglists[i]
        try:
            t0 = clock()
            r = fn(*args, **kw)
            t1 = clock()
        except Exception as e:  # recorded as an error of that method, never hidden
            t1 = clock()
            r = e
        times[i] = t1 - t0
        outs[i] = r
    return times, outs


class Method:
    """A method = one callable per kind; the queries are grouped by kind (load order within
    a kind), and each group runs through timed_loop with its callable and arguments."""

    def __init__(self, name, segments, decision):
        self.name = name
        self.segments = segments  # [(fn, arglists, kw)], one per kind, in query order
        self.decision = decision  # output -> bool
        self.times = None  # min over rounds, ns
        self.outs = None  # outputs of the first round

    def run_round(self, limit=None):
        times, outs = [], []
        for fn, args, kw in self.segments:
            t, o = timed_loop(fn, args[:limit] if limit else args, kw)
            times.append(t)
            outs += o
        if limit:
            return
        times = np.concatenate(times)
        if self.times is None:
            self.times, self.outs = times, outs
        else:
            np.minimum(self.times, times, out=self.times)


def kind_groups(queries):
    """[(kind, [queries of that kind])], in the order the queries list has them."""
    groups = []
    for q in queries:
        if not groups or groups[-1][0] != q.kind:
            groups.append((q.kind, []))
        groups[-1][1].append(q)
    return groups


def polyccd_methods(polyccd, queries):
    groups = kind_groups(queries)
    decide = [(polyccd.collides_linear, [(k, q.p_t0, q.p_t1) for q in g], {}) for k, g in groups]
    solve = [(polyccd.solve_linear, [(k, q.p_t0, q.p_t1) for q in g], {"time_tolerance": "1e-6"})
             for k, g in groups]
    return [
        Method("polyccd-decide", decide, lambda r: bool(r)),
        Method("polyccd-time", solve, lambda r: bool(r.collides)),
    ]


def ti_method(ti, queries):
    """Tight Inclusion as ipctk 1.6 exposes it: point_triangle_ccd(v, f0, f1, f2 at t0, the
    same at t1, ...) / edge_edge_ccd(ea0, ea1, eb0, eb1 at t0, the same at t1, ...);
    returns (collides, toi, tolerance)."""
    kw = {"min_distance": 0.0, "tolerance": 1e-6, "max_iterations": 1_000_000}
    fns = {"vertex-face": ti.point_triangle_ccd, "edge-edge": ti.edge_edge_ccd}
    segs = [(fns[k], [q.points8 for q in g], kw) for k, g in kind_groups(queries)]
    return Method("TI", segs, lambda r: bool(r[0]))


# ---------------------------------------------------------------------------------------
# Reporting


def summarize(method, queries):
    dec = [method.decision(o) if not isinstance(o, Exception) else o for o in method.outs]
    fp = fn_ = err = 0
    for q, d in zip(queries, dec):
        if isinstance(d, Exception):
            err += 1
        elif d and not q.truth:
            fp += 1
        elif not d and q.truth:
            fn_ += 1
    us = method.times / 1000.0
    return {
        "method": method.name,
        "queries": len(queries),
        "false_positives": fp,
        "false_negatives": fn_,
        "errors": err,
        "median_us": float(np.median(us)),
        "mean_us": float(np.mean(us)),
        "p99_us": float(np.percentile(us, 99)),
        "max_us": float(np.max(us)),
        "over_1ms": int(np.count_nonzero(us > 1000.0)),
        "over_100ms": int(np.count_nonzero(us > 100000.0)),
        "decisions": dec,
    }


def ratio(x):
    return f"{x:.2f}x" if x >= 0.1 else f"{x:.2g}x"


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=int(os.environ.get("POLYCCD_BENCH_REPEAT", "3")))
    ap.add_argument("--limit", type=int, default=0, help="only the first N queries (0 = all)")
    ap.add_argument("--no-ti", action="store_true", help="skip Tight Inclusion")
    ap.add_argument("--json", metavar="FILE", help="also write the summary as JSON")
    opts = ap.parse_args()

    try:
        import polyccd
    except ImportError as e:
        sys.exit(f"cannot import polyccd ({e}); run `make venv` (make bench does)")
    ti = None
    ti_note = "skipped (--no-ti)"
    if not opts.no_ti:
        try:
            import ipctk.tight_inclusion as ti
        except ImportError as e:
            ti_note = f"not available ({e}); pip install -r tests/bench/requirements.txt"

    root = query_dir()
    queries = load_queries(root)
    if opts.limit > 0:
        queries = queries[: opts.limit]
    queries.sort(key=lambda q: q.kind != "vertex-face")  # group by kind (stable)

    print("polyccd benchmark: exact CCD vs Tight Inclusion, same queries, one process")
    print(f"date      {datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')}")
    print(f"machine   {cpu_model()}, {os.cpu_count()} logical CPUs, {platform.platform()}")
    print(f"python    {platform.python_version()} ({platform.python_implementation()}), "
          f"numpy {np.__version__}")
    print(f"polyccd   {polyccd.__version__} ({Path(polyccd.__file__).parent})")
    print(f"ipctk     {pkg_version('ipctk') if ti else ti_note}")
    npos = sum(q.truth for q in queries)
    print(f"queries   {len(queries)} from {root} ({npos} colliding, "
          f"{sum(q.kind == 'vertex-face' for q in queries)} vertex-face, "
          f"{sum(q.kind == 'edge-edge' for q in queries)} edge-edge); every coordinate an exact double")
    print(f"timing    time.perf_counter_ns around each call; min over {opts.repeat} round(s); "
          f"gc disabled; untimed warm-up on 100 queries per kind")
    print()

    methods = polyccd_methods(polyccd, queries)
    if ti is not None:
        methods.append(ti_method(ti, queries))

    # warm-up (untimed): first-call costs
    for m in methods:
        m.run_round(limit=100)
    gc_was = gc.isenabled()
    gc.disable()
    try:
        for rnd in range(max(1, opts.repeat)):
            k = rnd % len(methods)
            for m in methods[k:] + methods[:k]:
                m.run_round()
    finally:
        if gc_was:
            gc.enable()

    # stages of the decide-only path (untimed; collides_linear returns only a bool)
    decide_stage = []
    for q in queries:
        try:
            decide_stage.append(polyccd.solve_linear(q.kind, q.p_t0, q.p_t1, want_time=False).stage)
        except Exception as e:
            decide_stage.append(f"error: {type(e).__name__}")

    summaries = [summarize(m, queries) for m in methods]
    rows = [
        (s["method"], s["queries"], s["false_positives"], s["false_negatives"], s["errors"],
         f"{s['median_us']:.2f}", f"{s['mean_us']:.2f}", f"{s['p99_us']:.2f}", f"{s['max_us']:.1f}",
         s["over_1ms"], s["over_100ms"])
        for s in summaries
    ]
    print_table(("method", "queries", "false pos", "false neg", "errors", "median us", "mean us",
                 "p99 us", "max us", "> 1 ms", "> 100 ms"), rows)
    print()
    by = {s["method"]: s for s in summaries}
    if "TI" in by:
        t = by["TI"]
        for name in ("polyccd-decide", "polyccd-time"):
            s = by[name]
            med, mean = s["median_us"] / t["median_us"], s["mean_us"] / t["mean_us"]
            print(f"{name}/TI: median {ratio(med)}, mean {ratio(mean)}"
                  f"   (TI/{name}: median {ratio(1 / med)}, mean {ratio(1 / mean)})")
    else:
        print(f"ratios polyccd/TI: n/a (Tight Inclusion {ti_note})")
    print()

    # engine stages; the decide-only path's stages come from an untimed
    # solve_linear(want_time=False) (collides_linear returns only a bool), its times from
    # the collides_linear measurement of the same query
    stage_time = [o.stage if not isinstance(o, Exception) else f"error: {type(o).__name__}"
                  for o in methods[1].outs]
    for label, stages, m in (("polyccd-time: Result.stage of solve_linear(time_tolerance=1e-6)",
                              stage_time, methods[1]),
                             ("polyccd-decide: Result.stage of solve_linear(want_time=False)",
                              decide_stage, methods[0])):
        names = list(STAGES) + sorted({s for s in stages if s not in STAGES})
        print(f"engine stage that decided the query, {label}:")
        srows = []
        for st in names:
            idx = [i for i, s in enumerate(stages) if s == st]
            col = sum(queries[i].truth for i in idx)
            us = m.times[idx] / 1000.0
            srows.append((st, len(idx), col, len(idx) - col,
                          f"{np.median(us):.2f}" if idx else "-",
                          f"{np.mean(us):.2f}" if idx else "-",
                          f"{100.0 * us.sum() / (m.times.sum() / 1000.0):.1f}" if idx else "-"))
        srows.append(("total", len(stages), sum(q.truth for q in queries),
                      sum(not q.truth for q in queries), f"{np.median(m.times) / 1000.0:.2f}",
                      f"{np.mean(m.times) / 1000.0:.2f}", "100.0"))
        print_table(("stage", "queries", "colliding", "not colliding", "median us",
                     "mean us", "% of time"), srows)
        print()

    # per scene and kind
    groups = {}
    for i, q in enumerate(queries):
        groups.setdefault((q.scene, q.kind), []).append(i)
    grows = []
    for (scene, kind), idx in sorted(groups.items()):
        row = [f"{scene}/{kind}", len(idx), sum(queries[i].truth for i in idx)]
        for s, m in zip(summaries, methods):
            fp = sum(1 for i in idx if s["decisions"][i] is True and not queries[i].truth)
            fn_ = sum(1 for i in idx if s["decisions"][i] is False and queries[i].truth)
            row += [f"{fp}/{fn_}", f"{np.median(m.times[idx]) / 1000.0:.2f}"]
        grows.append(tuple(row))
    hdr = ["scene/kind", "queries", "colliding"]
    for m in methods:
        hdr += [f"{m.name} FP/FN", f"{m.name} med us"]
    print("per scene:")
    print_table(hdr, grows)

    errors = [(m.name, queries[i], o) for m in methods for i, o in enumerate(m.outs)
              if isinstance(o, Exception)]
    if errors:
        print()
        print(f"{len(errors)} calls raised; the first ones:")
        for name, q, e in errors[:10]:
            print(f"  {name} {q.file} query {q.index}: {type(e).__name__}: {e}")

    if opts.json:
        out = {
            "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
            "cpu": cpu_model(),
            "python": platform.python_version(),
            "polyccd": polyccd.__version__,
            "ipctk": pkg_version("ipctk") if ti else None,
            "repeat": opts.repeat,
            "methods": [{k: v for k, v in s.items() if k != "decisions"} for s in summaries],
            "stages_time": {st: stage_time.count(st) for st in set(stage_time)},
            "stages_decide": {st: decide_stage.count(st) for st in set(decide_stage)},
        }
        Path(opts.json).write_text(json.dumps(out, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
