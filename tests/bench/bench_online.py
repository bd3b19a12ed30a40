#!/usr/bin/env python3
"""Benchmark of the on-line problem: one stored body of n primitives (polyccd.Index), n
query bodies of one primitive each, at n = 1k, 4k, 16k, 64k, 256k (each motion class up to
DEFAULT_MAX below). Times the
range structure, the rigid-body broad phase (boxes) and brute force, checks that all three
give the same answers, and prints the fitted exponents of time against n.

A benchmark, not a test: it never asserts on speed. It does check answers: every query's
collides and first contact (lo, hi, exact) must be identical for the three broad phases
(the library's contract); a difference aborts the run with the query written to a
polyccd/1 scene file, since it would be a bug.

Scene classes (one table per class and motion class):
  mesh  A bumpy height-field terrain over a k x k grid of unit cells (2 k^2 triangles,
        k = round(sqrt(n / 2))); heights are two sine bumps (amplitude 1, periods 20 and
        13 cells) plus uniform noise of +-0.05, on the 2^-16 grid. Queries: one-triangle
        meshes, vertices 0.4 to 0.8 from their centroid (about a cell), randomly oriented.
  mol   A slab of balls: a jittered (+-0.3 A) lattice of spacing 3.6 A, 3 layers, 10 % of the
        sites left empty, columns lifted by a smooth bump (amplitude 2 A); radii 1.2 to
        2.0 A (k x k columns, k = round(sqrt(n / 2.7))). Queries: one ball of radius 1.2 to
        2.0 A, its centre 0 to 1.5 A from the body origin (so rotations move it).
Motions of the queries (body origin from p0 to p1: a horizontal run of 1.5 to 3 cells /
4 to 8 A and a drop of 0 to 1 cell / 0 to 3 A; every number on the 2^-16 grid, exact):
  linear    Motion(translation = p0 + (p1 - p0) t), no rotation.
  rotation  the same translation, r(t) = (1, tau(t) a): a fixed unit axis a through the
            body origin, tau linear from tau0 in [-0.5, 0.5] by +-[0.5, 1] (up to ~90 deg).
            A rolling motion: the axis travels with the body origin, so in the stored
            body's frame it is not a rotation about a fixed axis (no point stays fixed).
  poly      translation p0 + (p1 - p0 + B) t - B t^2 (a bend B), rotation a general
            quadratic quaternion w = 1 + w1 t + w2 t^2 (|w1|, |w2| <= 0.3, so w > 0: it never
            vanishes), vector part coefficients up to 0.5 / 0.8.
  axis      a swing (door / arm) about a fixed axis: constant translation p0 (no run),
            r(t) = (1, tau(t) a) with tau as in "rotation" and a random unit axis a tilted
            up to 30 deg from the vertical (uniform on that cap). The query's own points sit
            at a lever arm L from the body origin (the pivot), |L| in the class's run range
            (1.5 to 3 cells / 4 to 8 A), L within 10 deg of horizontal: mesh queries are the
            triangles above moved by L, mol queries one ball centred at L. So the query
            sweeps an arc roughly horizontally over the surface, and the relative motion is
            a rotation about a fixed axis through the pivot (the library's exact
            linearization for that case, range/axis_rotation.h).
Placement: each query's path is then shifted vertically (the constant of its z
translation) so that its closest sampled approach to the surface is a chosen clearance d.
About 90 % are near misses: d in [0.02, 0.2] cells (meshes) / [0.05, 0.5] A (balls),
measured conservatively (lowest query vertex over the highest terrain vertex of the cells
under the query's box; ball centre over the upper envelope of the grown atoms), at 41 / 25
time samples. About 10 % are placed to hit: d in [-0.4, -0.1] / [-0.8, -0.2] (a sampled
point of the triangle below the terrain, the ball centre inside a grown atom), starting at
least 0.02 / 0.05 clear at t = 0 when possible. The hit column counts the exact answers.

Timing: one process, threads = 1 (--threads), gc off; "build" = polyccd.Index(Body(shape))
on a fresh shape (the index's trees are cached per shape); each method is one
ix.query_many(queries, broad_phase=X) call, the Python reading of the results included.
Brute force runs while its time predicted from the previous size (x (n / n_prev)^2; a 20
query pilot at the first size) fits in --brute-seconds (60 s), otherwise "-". Boxes runs in
full while its prediction fits in --budget-seconds (120 s); over budget it runs on a fixed
random sample of (at most) 1000 queries and the total is extrapolated and printed as
"~T est k/n": never as a measurement, and never used in the fitted exponents.

Usage: python tests/bench/bench_online.py [--sizes 1k,4k,16k,64k,256k] [--classes mesh,mol]
           [--motions linear,rotation,poly,axis] [--quick] [--budget-seconds 120]
           [--brute-seconds 60] [--threads 1] [--seed 1] [--dump-dir /tmp]
"""

import argparse
import datetime
import gc
import json
import math
import os
import platform
import sys
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_report import cpu_model, fit_exponent, loaded_libraries, print_table  # noqa: E402
from online_scenes import (CLASSES, HIT_FRACTION, MOTIONS, make_queries,  # noqa: E402
                           make_stored)

METHODS = ("range", "boxes", "brute")
DEFAULT_SIZES = "1k,4k,16k,64k,256k"
# Default sizes stop here per motion class (--sizes applies to every class as given):
# linear motions go to 256k; rotations to 64k (mesh rotations at 256k take ~10 min of
# range time alone); the poly motions to 16k: their time is dominated by a few hits whose
# exact predicates take seconds with either broad phase (not by the broad phase), and
# 64k of them take most of an hour. Axis swings to 64k: range time to 64k is ~3 min for
# both classes, while mesh swings at 256k take ~9 min of range time alone (mol ~2 min).
DEFAULT_MAX = {"linear": 256000, "rotation": 64000, "poly": 16000, "axis": 64000}
QUICK_SIZES = "200,800"
SAMPLE_QUERIES = 1000                # boxes over budget: timed on this many queries
PILOT_QUERIES = 20                   # first size: prediction from this many queries


def parse_size(s):
    s = s.strip().lower()
    mult = 1000 if s.endswith("k") else 1
    try:
        v = int(float(s[:-1] if mult > 1 else s) * mult)
    except ValueError:
        sys.exit(f"--sizes: cannot read {s!r} (examples: 1k, 4k, 200)")
    if v < 20:
        sys.exit(f"--sizes: {s!r} is too small (at least 20)")
    return v


# ---------------------------------------------------------------------------------------
# Running and checking


def answer(r):
    ct = r.first_contact
    return (r.collides, None if ct is None else (ct.lo, ct.hi, ct.exact))


def run_method(ix, queries, method, threads):
    gc.collect()
    was = gc.isenabled()
    gc.disable()
    try:
        t0 = time.perf_counter()
        res = ix.query_many(queries, broad_phase=method, threads=threads)
        dt = time.perf_counter() - t0
    finally:
        if was:
            gc.enable()
    return dt, res


def exact_json(x):
    """A number of the benchmark (a double) as an exact fraction string."""
    return str(Fraction(float(x)))


def dump_case(dump_dir, cls, motion, n, q, stored, raw_q, answers):
    def exact(v):
        if isinstance(v, list):
            return [exact(e) for e in v]
        if isinstance(v, dict):
            return {key: exact(e) if key != "triangles" else e for key, e in v.items()}
        return exact_json(v)
    doc = {"format": "polyccd/1", "name": f"bench_online {cls}/{motion} n={n} query {q}",
           "source": "tests/bench/bench_online.py: broad phases disagree on this query ("
                     + "; ".join(f"{m}: {a}" for m, a in answers.items()) + ")",
           "bodies": [{"name": "stored", **exact(stored["raw"]())}, {"name": f"q{q}", **exact(raw_q)}]}
    path = Path(dump_dir) / f"bench_online_{cls}_{motion}_{n}_q{q}.json"
    path.write_text(json.dumps(doc) + "\n")
    return path


def check_same(ref, res, idx, method, ctx):
    """ref: range answers of all queries; res: answers of method for queries idx."""
    for r, q in zip(res, idx):
        a, b = answer(r), ref[q]
        if a != b:
            cls, motion, n, stored, raw, dump_dir = ctx
            try:
                path = dump_case(dump_dir, cls, motion, n, q, stored, raw[q], {"range": b, method: a})
                where = f"query {q} written to {path}"
            except OSError as e:
                where = f"(could not write the case: {e})"
            print(f"\nERROR: broad phases disagree ({cls}/{motion}, n = {n}, query {q}):\n"
                  f"  range: {b}\n  {method}: {a}\n  {where}\n"
                  "  This is a bug of polyccd (all broad phases must give identical answers).",
                  flush=True)
            sys.exit(3)


def fmt_s(x):
    return "-" if x is None else (f"{x:.3f}" if x < 10 else f"{x:.1f}")


def run_combo(polyccd, cls, motion, sizes, opts):
    print(f"== {cls} / {motion}", flush=True)
    rows, notes, stats_lines = [], [], []
    measured = {m: [] for m in ("build",) + METHODS}
    last = {}                                   # method -> (n, total seconds, measured?)
    for n_req in sizes:
        stored = make_stored(polyccd, cls, n_req, opts.seed)
        n = stored["n"]
        t0 = time.perf_counter()
        queries, raw = make_queries(polyccd, cls, motion, n, opts.seed, stored)
        setup = time.perf_counter() - t0
        shape = stored["make"]()
        gc.collect()
        t0 = time.perf_counter()
        ix = polyccd.Index(polyccd.Body(shape, None, name="stored"))
        build = time.perf_counter() - t0
        measured["build"].append((n, build))
        print(f"   n = {n}: {stored['text']}; {n} queries (setup {setup:.1f} s); build {build:.3f} s",
              flush=True)

        t_range, res_range = run_method(ix, queries, "range", opts.threads)
        ref = [answer(r) for r in res_range]
        measured["range"].append((n, t_range))
        last["range"] = (n, t_range)
        hits = sum(1 for a in ref if a[0])
        at0 = sum(1 for a in ref if a[0] and a[1][1] == 0)
        ctx = (cls, motion, n, stored, raw, opts.dump_dir)
        print(f"   range {t_range:.3f} s, {hits} hits ({at0} at t = 0)", flush=True)
        cells = {"range": (t_range, n, None)}
        results = {"range": res_range}
        for method, budget in (("boxes", opts.budget_seconds), ("brute", opts.brute_seconds)):
            if method in last:
                pn, pt = last[method]
                predicted = pt * (n / pn) ** 2
                how = f"{pt:.3g} s at n = {pn} x (n / {pn})^2"
            elif method in opts.skip:
                predicted, how = math.inf, "skipped"
            else:
                pilot = list(range(0, n, max(1, n // PILOT_QUERIES)))[:PILOT_QUERIES]
                tp, rp = run_method(ix, [queries[q] for q in pilot], method, opts.threads)
                check_same(ref, rp, pilot, method, ctx)
                predicted = tp * n / len(pilot)
                how = f"pilot of {len(pilot)} queries"
            if predicted <= budget:
                t, res = run_method(ix, queries, method, opts.threads)
                check_same(ref, res, range(n), method, ctx)
                cells[method] = (t, n, None)
                results[method] = res
                measured[method].append((n, t))
                last[method] = (n, t)
                print(f"   {method} {t:.3f} s (predicted {predicted:.3g} s from {how})", flush=True)
            elif method == "boxes" and predicted < math.inf:
                # at most SAMPLE_QUERIES, fewer when even those would not fit the budget
                k = max(min(SAMPLE_QUERIES, n, int(budget * n / predicted)), min(100, n))
                idx = sorted(np.random.default_rng([opts.seed, n, 7]).choice(n, k, replace=False).tolist())
                t, res = run_method(ix, [queries[q] for q in idx], method, opts.threads)
                check_same(ref, res, idx, method, ctx)
                est = t * n / k
                cells[method] = (est, n, k)
                results[method] = res
                last[method] = (n, est)
                print(f"   {method}: predicted {predicted:.3g} s ({how}) > budget {budget:g} s: "
                      f"{t:.3f} s on {k} random queries, est. total {est:.1f} s", flush=True)
            else:
                print(f"   {method}: not run (predicted {predicted:.3g} s from {how} > budget {budget:g} s)",
                      flush=True)
        # where the time goes: per-query means of the work counters
        for method, res in results.items():
            tot = {}
            for r in res:
                for key in ("pieces", "candidates", "solved", "static_tests"):
                    tot[key] = tot.get(key, 0) + r.stats[key]
            k = len(res)
            stats_lines.append(f"   n = {n} {method:5} ({k} queries): " + ", ".join(
                f"{key} {v / k:.3g}/q" for key, v in tot.items())
                + f", max candidates {max(r.stats['candidates'] for r in res)}")

        def tcell(m):
            c = cells.get(m)
            if c is None:
                return "-"
            t, _, k = c
            return fmt_s(t) if k is None else f"~{fmt_s(t)} est {k}/{n}"

        def ratio(m):
            c = cells.get(m)
            if c is None:
                return "-"
            r = t_range / c[0]
            return f"{r:.3g}" if c[2] is None else f"~{r:.3g} est"

        def per_q(m):
            c = cells.get(m)
            if c is None:
                return "-"
            ms = c[0] / n * 1e3
            return f"{ms:.3g}" if c[2] is None else f"~{ms:.3g} est"

        rows.append([n, fmt_s(build), fmt_s(t_range), tcell("boxes"), tcell("brute"), ratio("boxes"),
                     ratio("brute"), f"{hits} ({at0} at t=0)", per_q("range"), per_q("boxes"), per_q("brute")])
        del ix, queries, raw, results, res_range
    print()
    print_table(["n", "build s", "range s", "boxes s", "brute s", "range/boxes", "range/brute", "hits",
                 "range ms/q", "boxes ms/q", "brute ms/q"], rows)
    print("   work per query (pieces = time pieces, candidates = feature pairs from the broad phase, "
          "solved = pairs sent to the exact predicates):")
    for line in stats_lines:
        print(line)
    print("   fitted exponent of time vs n (least squares on log-log, measured points only):")
    for m in ("build",) + METHODS:
        pts = measured[m]
        e = fit_exponent(pts)
        used = ", ".join(str(p[0]) for p in pts) or "none"
        print(f"     {m:6} " + (f"{e:.2f}" if e is not None else "n/a ") + f"   (sizes {used})"
              + ("" if e is not None else ": needs two measured sizes"))
    print(flush=True)
    return {"class": cls, "motion": motion, "rows": rows,
            "exponents": {m: fit_exponent(measured[m]) for m in measured}}


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default=None, help=f"comma-separated n (default {DEFAULT_SIZES}, "
                    f"each motion class up to {DEFAULT_MAX})")
    ap.add_argument("--classes", default=",".join(CLASSES))
    ap.add_argument("--motions", default=",".join(MOTIONS))
    ap.add_argument("--quick", action="store_true", help=f"sizes {QUICK_SIZES} (smoke test)")
    ap.add_argument("--budget-seconds", type=float, default=120.0,
                    help="boxes: full run only while predicted to fit (else a sample, estimated)")
    ap.add_argument("--brute-seconds", type=float, default=60.0, help="brute force: run only while predicted to fit")
    ap.add_argument("--skip", default="", help="methods not to run at all (boxes, brute)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--dump-dir", default="/tmp", help="where a disagreeing query is written")
    opts = ap.parse_args()
    sizes = [parse_size(s) for s in (opts.sizes or (QUICK_SIZES if opts.quick else DEFAULT_SIZES)).split(",")]
    classes = [c.strip() for c in opts.classes.split(",") if c.strip()]
    motions = [m.strip() for m in opts.motions.split(",") if m.strip()]
    opts.skip = {s.strip() for s in opts.skip.split(",") if s.strip()}
    for c in classes:
        if c not in CLASSES:
            sys.exit(f"--classes: unknown {c!r} (choose from {', '.join(CLASSES)})")
    for m in motions:
        if m not in MOTIONS:
            sys.exit(f"--motions: unknown {m!r} (choose from {', '.join(MOTIONS)})")
    for s in opts.skip:
        if s not in ("boxes", "brute"):
            sys.exit(f"--skip: unknown {s!r} (boxes, brute)")
    try:
        import polyccd
    except ImportError as e:
        sys.exit(f"cannot import polyccd ({e}); run `make venv`")
    if not hasattr(polyccd, "Index"):
        sys.exit("this polyccd has no Index (the on-line index); rebuild with `make`")

    print("polyccd on-line benchmark: one stored body of n primitives, n one-primitive queries "
          "(Index.query_many), range vs boxes vs brute")
    print(f"date      {datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')}")
    print(f"machine   {cpu_model()}, {os.cpu_count()} logical CPUs, {platform.platform()}")
    print(f"python    {platform.python_version()}, numpy {np.__version__}")
    print(f"polyccd   {polyccd.__version__} ({Path(polyccd.__file__).parent})")
    for path, mtime in loaded_libraries(("_pccd", "libpolyccd")):
        print(f"          loaded {path} (modified {mtime})")
    print(f"sizes     {', '.join(map(str, sorted(sizes)))} (requested; the stored body has about n primitives)")
    print(f"run       classes {', '.join(classes)}; motions {', '.join(motions)}; threads {opts.threads}; "
          f"seed {opts.seed}; budgets: boxes {opts.budget_seconds:g} s, brute {opts.brute_seconds:g} s"
          + (f"; skipped: {', '.join(sorted(opts.skip))}" if opts.skip else ""))
    print(f"queries   ~{HIT_FRACTION:.0%} placed to hit, the rest near misses (see the docstring); "
          "answers of boxes and brute checked equal to range for every query run")
    print(flush=True)
    sizes = sorted(set(sizes))
    summary = []
    for cls in classes:
        for motion in motions:
            combo = [n for n in sizes if opts.sizes or n <= DEFAULT_MAX[motion]]
            summary.append(run_combo(polyccd, cls, motion, combo, opts))
    if len(summary) > 1:
        print("fitted exponents (measured points only):")
        print_table(["class", "motion"] + ["build"] + list(METHODS),
                    [[s["class"], s["motion"]] + [f"{s['exponents'][m]:.2f}" if s["exponents"][m] is not None
                                                  else "n/a" for m in ("build",) + METHODS] for s in summary])
    return 0


if __name__ == "__main__":
    sys.exit(main())
