#!/usr/bin/env python3
"""Benchmark: polyccd's hierarchy broad phase (broad_phase "bvh", the scenes' default)
against python-fcl on real meshes and molecules: two copies of one body, one moving.

A benchmark, not a test: it never asserts. Each polyccd answer is also computed with the
box broad phase (an independent candidate source; same exact narrow phase) and the two
must be equal ("same" column); FCL's answers are printed, never trusted.

Meshes: real meshes of Debian's libcgal-demo (polyccd.apps._data.cgal_data_file; read
by trimesh, process=False), centred on their bounding box and scaled by a power of two
so the longest side is in (1/2, 1] (exact: the doubles are the bodies' coordinates).
Body A stays at the origin; body B is the same mesh. E = A's x extent.
  far:   B translates from (3E, 0, 0) to (2.5E, 0, 0)            (no contact)
  hit:   B translates from (1.5E, 0, 0) to (0.5E, 0, 0)           (contact)
  near:  as hit, but stopping 2^-20 E (about 1e-6 E) before the exact first contact x_c
         (x_c from polyccd's exact answer to hit; the path ends before it: no contact)
  rot:   B starts at (1.1E, 0, 0) and turns about the vertical axis through
         (1.1E, E, 0), direction -z, by up to 2 atan(1/2) = 53.13 deg (polyccd:
         Motion.axis_rotation, tau 0 -> 1/2, composed with the start offset; FCL: CCDM_SCREW
         between the same start and end poses, at constant angular speed: the same poses,
         another time parametrization, so FCL's times are compared after mapping ours
         through angle(t) / angle(1))
FCL: fcl.BVHModel (OBBRSS) objects, continuousCollide with ContinuousCollisionRequest(
num_max_iterations=10, toc_err=1e-4, GST_LIBCCD), CCDM_TRANS for translations (FCL's screw
without rotation is wrong, see bench_bodies.py), CCDM_SCREW for rot; FCL-CA = conservative
advancement, FCL-naive = CCDC_NAIVE (10 discrete samples).

Molecules: the atom sets of bench_bodies.py (1t7i first 1000 atoms, 1mvm, 1IYE 2 x 2),
Bondi radii; hit / near (gap 1.0e-6 A) exactly as bench_bodies.py (exact truth), far (B
10 extents away, moving 1 A), rot (B beside A turning about a vertical axis through a
pivot 1 extent off, as rot above). FCL: one Sphere object per atom, a numpy prefilter of
swept boxes (translation: exact boxes; rotation: the chord's box grown by the sagitta),
then continuousCollide per surviving pair (counted in FCL's time).

Minimum separation (--delta D, default 1e-3; "0": not run): the mesh rows again with
min_distance = D (exact rational text), the first time the surfaces are within D. Cases:
far, hit and rot as above (the same motions), and near-D: the hit path stopped 2^-20 E
before the first time within D (from polyccd's answer to hit at D; no contact at D).
Columns: bvh with D (1 thread; boxes with D must give the same answer), bvh without D on
the same motion (its ratio: the cost of D), and FCL-CA / FCL-naive on the same motion
(FCL has no minimum-separation CCD: the nearest comparable figure, timed like above).
Brute force with D (the reference of tests/test_min_distance.py) is quadratic: not run.

Timing: perf_counter_ns per query, min over --repeat rounds, gc off, one process. A
query under FAST_NS (50 us; far-apart pairs) is also timed in --repeat batches of
about 1 ms of calls each (the mean per call of a batch), for every method alike: a
lone reading of a few-microsecond call is mostly cold caches and Python's not yet
specialized bytecode (polyccd.check's 2nd-6th single calls of a far pair: 13, 10, 9,
7, 6 us; a batch: 4.5 us). Body builds: polyccd.Mesh / Spheres (which build the
hierarchy) against fcl.BVHModel (mesh).

Usage: python tests/bench/bench_bvh.py [--quick] [--sizes 1k,5k,...] [--repeat N] [--no-fcl]
       [--delta D]
"""
import argparse
import datetime
import gc
import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_report as BR  # noqa: E402  (machine, versions, tables, formats)
import bodies_cases as BC  # noqa: E402  (the molecules of bench_bodies.py)
import bodies_methods as BM  # noqa: E402  (FCL requests, timing)

MESHES = {"1k": "helmet.off", "5k": "elephant.off", "20k": "camel.off", "35k": "man.off",
          "75k": "bunny00.off", "89k": "refined_elephant.off"}
MOLS = {"1k": "mol-1k", "5k": "mol-5k", "30k": "mol-30k"}
QUICK = ("1k",)
VARIANTS = ("far", "hit", "near", "rot")
FCL_ROT_MAX_ATOMS = 5000
from bvh_timing import (TAU1, THETA1, fcl_time_of, fmt, load_mesh, poly_answer,  # noqa: E402
                        poses, quat_z, rotz, stop_short, time_fcl, time_poly, timed)


def mesh_rows(polyccd, fcl, label, opts, scaling):
    V, F = load_mesh(MESHES[label])
    E = float(V[:, 0].max() - V[:, 0].min())
    best_p = best_f = None
    for _ in range(3):
        t0 = time.perf_counter_ns()
        mesh = polyccd.Mesh(V, F)
        t1 = time.perf_counter_ns()
        best_p = t1 - t0 if best_p is None else min(best_p, t1 - t0)
        if fcl:
            t1 = time.perf_counter_ns()
            bvh = BM.fcl_bvh(fcl, V, F)
            best_f = min(best_f or 1 << 62, time.perf_counter_ns() - t1)
    print(f"== mesh {label}: {MESHES[label]}, {len(F)} triangles x 2, E = {E:.6g}; build polyccd "
          f"{fmt(best_p)} ms, FCL BVHModel {fmt(best_f)} ms (ratio "
          f"{best_p / best_f:.2f})" if fcl else "")
    scaling.setdefault(("mesh", "build polyccd"), []).append((len(F), best_p / 1e6))
    if fcl:
        scaling.setdefault(("mesh", "build FCL"), []).append((len(F), best_f / 1e6))
        reqs = {mt: BM.fcl_requests(fcl, mt) for mt in ("CCDM_TRANS", "CCDM_SCREW")}
    rows = []
    A = polyccd.Body(mesh, None, name="A")
    hit_x = None
    for v in VARIANTS:
        if v == "near":
            m_hit = poses(E, "hit")[0]
            r = polyccd.check([A, polyccd.Body(mesh, m_hit, name="B")])
            motion, start, end, mt, hit_x = stop_short(polyccd, E, r.first_contact.lo)
        else:
            motion, start, end, mt = poses(E, v)
        bodies = [A, polyccd.Body(mesh, motion, name="B")]
        row = {"variant": v}
        gc.disable()
        try:
            time_polyccd(polyccd, bodies, row, opts)
            if fcl:
                time_fcl(fcl, bvh, start, end, reqs[mt], opts.repeat, row)
        finally:
            gc.enable()
        rows.append(row)
        n = 2 * len(F)
        for m in ("t1", "t2", "boxes", "FCL-CA", "FCL-naive"):
            if m in row:
                scaling.setdefault(("mesh " + v, m), []).append((n, row[m] / 1e6))
    drows = []
    if opts.delta != "0":
        drows = delta_rows(polyccd, fcl, A, mesh, E, opts, reqs if fcl else None, bvh if fcl else None)
        for r in drows:
            scaling.setdefault((f"mesh {r['variant']} (delta)", "bvh+delta"), []).append((2 * len(F), r["td"] / 1e6))
    return rows, hit_x, drows


def delta_rows(polyccd, fcl, A, mesh, E, opts, reqs, bvh):
    """The rows of the minimum-separation table (see Minimum separation above)."""
    D = opts.delta
    rows = []
    for v in ("far", "hit", "near-D", "rot"):
        if v == "near-D":
            m_hit = poses(E, "hit")[0]
            r = polyccd.check([A, polyccd.Body(mesh, m_hit, name="B")], min_distance=D)
            motion, start, end, mt, _ = stop_short(polyccd, E, r.first_contact.lo)
        else:
            motion, start, end, mt = poses(E, v)
        bodies = [A, polyccd.Body(mesh, motion, name="B")]
        row = {"variant": v}
        gc.disable()
        try:
            row["td"], r = time_poly(polyccd, bodies, 1, opts.repeat, min_distance=D)
            row["ans"], row["time"] = poly_answer(r)
            row["stats"] = dict(r.stats)
            row["t0"], r0 = time_poly(polyccd, bodies, 1, opts.repeat)
            row["ans0"] = poly_answer(r0)
            row["boxes"], rb = time_poly(polyccd, bodies, 1, 1, "boxes", min_distance=D)
            row["same"] = poly_answer(rb)[0] == row["ans"]
            if fcl:
                time_fcl(fcl, bvh, start, end, reqs[mt], opts.repeat, row)
        finally:
            gc.enable()
        rows.append(row)
    return rows


def show_delta_rows(rows, delta):
    def ans(a, t):
        if not a[0]:
            return "miss"
        exact = a[1][2]
        return str(exact) if exact is not None and len(str(exact)) <= 12 else f"{t:.6g}"
    out = []
    for r in rows:
        fa = r.get("FCL-CA ans")
        out.append([r["variant"], ans(r["ans"], r["time"]), ans(*r["ans0"]), fmt(r["td"]), fmt(r["t0"]),
                    f"{r['td'] / r['t0']:.3g}", fmt(r["boxes"]), "yes" if r["same"] else "NO",
                    fmt(r.get("FCL-CA")), fmt(r.get("FCL-naive")),
                    "n/a" if fa is None else ("miss" if not fa[0] else f"{fa[1]:.4g}"),
                    r["stats"].get("solved", "?"), r["stats"].get("candidates", "?")])
    print(f"min_distance = {delta}: bvh with delta against bvh without it on the same motions")
    BR.print_table(["case", "answer at delta", "answer at 0", "bvh+delta ms", "bvh ms", "ratio",
                    "boxes+delta ms", "same", "FCL-CA ms", "FCL-naive ms", "CA t", "solved",
                    "candidates"], out)


def time_polyccd(polyccd, bodies, row, opts):
    """polyccd's columns of a row: 1 and 2 threads (default broad phase), boxes, answers."""
    for th in (1, 2):
        ns, r = time_poly(polyccd, bodies, th, opts.repeat)
        row[f"t{th}"] = ns
        row["ans"], row["time"] = poly_answer(r)
        row["stats"] = dict(r.stats)
    ns, rb = time_poly(polyccd, bodies, 1, 1, "boxes")
    row["boxes"] = ns
    row["same"] = poly_answer(rb)[0] == row["ans"]


def mol_rows(polyccd, fcl, label, opts, scaling):
    case = BC.mol_case(MOLS[label])
    C, R, off = case["centers"], case["radii"], case["offset"]
    t0 = time.perf_counter_ns()
    shape = polyccd.Spheres(C, R)
    build = time.perf_counter_ns() - t0
    ext = float((C.max(axis=0) - C.min(axis=0)).max())
    print(f"== molecule {label}: {len(C)} atoms x 2 ({case['source']}); build polyccd {fmt(build)} ms")
    A = polyccd.Body(shape, None, name="A")
    offx = [float(o) for o in case["offset_exact"]]
    rows = []
    for v in VARIANTS:
        if v in ("hit", "near"):
            L = case["variants"][v]["L"]
            motion = polyccd.Motion.linear(offx, [offx[0] - float(L), offx[1], offx[2]])
            shift = (off, off - np.array([float(L), 0.0, 0.0]))
        elif v == "far":
            far = np.array([math.ldexp(1.0, math.ceil(math.log2(10 * ext))), 0.0, 0.0])
            motion = polyccd.Motion.linear(list(off + far), list(off + far - [1.0, 0, 0]))
            shift = (off + far, off + far - [1.0, 0, 0])
        else:
            P = [offx[0], offx[1] + ext, offx[2]]
            motion = polyccd.Motion.axis_rotation([0, 0, -1], P, 0, TAU1).compose([1, 0, 0, 0], offx, side="body")
            shift = None
        bodies = [A, polyccd.Body(shape, motion, name="B")]
        row = {"variant": v}
        gc.disable()
        try:
            time_polyccd(polyccd, bodies, row, opts)
            # FCL's rotation query loops over every swept-box pair in Python (30 s at 5k
            # atoms): skipped above FCL_ROT_MAX_ATOMS.
            if fcl and (shift is not None or len(C) <= FCL_ROT_MAX_ATOMS):
                for name in ("FCL-CA", "FCL-naive"):
                    ns, out = timed(fcl_mol(fcl, C, R, shift, offx, ext, name), opts.repeat)
                    row[name] = ns
                    row[name + " ans"] = out
        finally:
            gc.enable()
        rows.append(row)
        for m in ("t1", "t2", "boxes", "FCL-CA", "FCL-naive"):
            if m in row:
                scaling.setdefault(("molecule " + v, m), []).append((2 * len(C), row[m] / 1e6))
    return rows


def fcl_mol(fcl, C, R, shift, offx, ext, name):
    """FCL's query: prefilter of swept boxes, then continuousCollide per pair (bench_bodies)."""
    eps = 1e-9
    if shift is not None:
        mt, s0, s1 = "CCDM_TRANS", shift[0], shift[1]
        B0, B1 = C + s0, C + s1
        blo, bhi = np.minimum(B0, B1), np.maximum(B0, B1)
    else:
        mt = "CCDM_SCREW"
        P = np.array([offx[0], offx[1] + ext, offx[2]])
        B0 = C + np.array(offx)
        B1 = (B0 - P) @ rotz(THETA1).T + P
        rho = np.linalg.norm((B0 - P)[:, :2], axis=1)
        sag = rho * (1 - math.cos(THETA1 / 2)) + eps
        blo, bhi = np.minimum(B0, B1) - sag[:, None], np.maximum(B0, B1) + sag[:, None]
    blo, bhi = blo - R[:, None] - eps, bhi + R[:, None] + eps
    alo, ahi = C - R[:, None] - eps, C + R[:, None] + eps
    req = BM.fcl_requests(fcl, mt)[name]
    geoms = [fcl.Sphere(float(r)) for r in R]
    objA = [fcl.CollisionObject(g, fcl.Transform(c)) for g, c in zip(geoms, C)]
    endA = [fcl.Transform(c) for c in C]
    if shift is not None:
        objB = [fcl.CollisionObject(g, fcl.Transform(c)) for g, c in zip(geoms, B0)]
        endB = [fcl.Transform(c) for c in B1]
    else:
        q = quat_z(THETA1)
        objB = [fcl.CollisionObject(g, fcl.Transform(c)) for g, c in zip(geoms, B0)]
        endB = [fcl.Transform(q, c) for c in B1]

    def run():
        ia = np.nonzero(np.all(ahi >= blo.min(axis=0), axis=1) & np.all(alo <= bhi.max(axis=0), axis=1))[0]
        ib = np.nonzero(np.all(bhi >= alo.min(axis=0), axis=1) & np.all(blo <= ahi.max(axis=0), axis=1))[0]
        hit, toc, tested = False, 1.0, 0
        for j in ib:
            ok = ia[np.all(ahi[ia] >= blo[j], axis=1) & np.all(alo[ia] <= bhi[j], axis=1)]
            for i in ok.tolist():
                tested += 1
                res = fcl.ContinuousCollisionResult()
                fcl.continuousCollide(objA[i], endA[i], objB[j], endB[j], req, res)
                if res.is_collide:
                    hit, toc = True, min(toc, float(res.time_of_contact))
        return hit, (toc if hit else None), tested
    return run


def show_rows(rows, rot_map):
    out = []
    for r in rows:
        ans = r["ans"]
        exact = ans[1][2] if ans[0] else None
        short = exact is not None and len(str(exact)) <= 12
        t = "-" if not ans[0] else (str(exact) if short else f"{r['time']:.6g}" + (" (exact)" if exact is not None else ""))
        fca = r.get("FCL-CA ans")
        fnv = r.get("FCL-naive ans")
        pt = r["time"] if ans[0] else None
        if pt is not None and r["variant"] == "rot" and rot_map:
            pt = fcl_time_of(pt)

        def ftxt(a):
            if a is None:
                return "n/a"
            return "miss" if not a[0] else f"{a[1]:.4g}"
        out.append([r["variant"], "hit " + t if ans[0] else "miss", fmt(r["t1"]), fmt(r["t2"]), fmt(r["boxes"]),
                    "yes" if r["same"] else "NO", fmt(r.get("FCL-CA")), fmt(r.get("FCL-naive")),
                    f"{r['t1'] / r['FCL-CA']:.3g}" if "FCL-CA" in r else "n/a",
                    f"{r['t1'] / r['FCL-naive']:.3g}" if "FCL-naive" in r else "n/a",
                    f"{pt:.4g}" if pt is not None else "miss", ftxt(fca), ftxt(fnv),
                    r["stats"].get("solved", "?")])
    BR.print_table(["case", "polyccd answer", "bvh t=1 ms", "bvh t=2 ms", "boxes ms", "same",
                    "FCL-CA ms", "FCL-naive ms", "bvh/CA", "bvh/naive", "t (FCL clock)", "CA t", "naive t",
                    "solved"], out)


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--sizes", help="comma-separated from " + ", ".join(dict.fromkeys(list(MESHES) + list(MOLS))))
    ap.add_argument("--repeat", type=int, default=int(os.environ.get("POLYCCD_BENCH_REPEAT", "3")))
    ap.add_argument("--no-fcl", action="store_true")
    ap.add_argument("--no-molecules", action="store_true")
    ap.add_argument("--delta", default="1e-3", help='min_distance of the delta table ("0": none)')
    opts = ap.parse_args()
    sizes = opts.sizes.split(",") if opts.sizes else (list(QUICK) if opts.quick else list(MESHES))
    import polyccd
    fcl = None
    if not opts.no_fcl:
        try:
            import fcl
        except ImportError as e:
            print(f"fcl: not available ({e})")
    print("polyccd hierarchy benchmark: polyccd.check (auto = bvh) vs python-fcl, real CGAL meshes and molecules")
    print(f"date      {datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')}")
    print(f"machine   {BR.cpu_model()}, {os.cpu_count()} logical CPUs, {platform.platform()}")
    print(f"polyccd   {polyccd.__version__}; fcl {BR.pkg_version('python-fcl') if fcl else 'skipped'}; "
          f"min over {opts.repeat} round(s), ms per query")
    print()
    scaling = {}
    for label in sizes:
        if label in MESHES:
            rows, _, drows = mesh_rows(polyccd, fcl, label, opts, scaling)
            show_rows(rows, True)
            print()
            if drows:
                show_delta_rows(drows, opts.delta)
                print()
        if label in MOLS and not opts.no_molecules:
            show_rows(mol_rows(polyccd, fcl, label, opts, scaling), True)
            print()
    print("fitted exponents (least squares of log ms on log total primitives)")
    srows = []
    for (what, m), pts in sorted(scaling.items()):
        e = BR.fit_exponent(pts)
        if e is not None:
            srows.append([what, m, f"{e:.2f}", " / ".join(f"{t:.3g}" for _, t in pts)])
    if srows:
        BR.print_table(["family / case", "method", "exponent", "ms by size"], srows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
