#!/usr/bin/env python3
"""Benchmark: polyccd scenes (polyccd.check on two Body objects) against FCL's continuous
collision, on mesh pairs and molecule pairs whose exact answer is known by construction.

A benchmark, not a test: it never asserts on speed. Every answer is compared with a truth
that is derived from the geometry alone (exact Fraction arithmetic, independent of polyccd
and FCL) and printed OK / WRONG. tests/test_bench_bodies.py runs --quick and asserts that
every polyccd answer is OK.

Exact common input. Every coordinate, radius and motion parameter handed to either library
is a multiple of 2^-30 of magnitude < 2^22, so it is a float64 exactly, and every sum or
difference used to place the bodies is again exact. polyccd gets these doubles as exact
binary values (numpy float arrays / Fraction), FCL gets the same doubles: both libraries
are asked the same geometric question, and the truth below is exact for that question.

(1) Meshes. A unit icosphere (icosahedron subdivided s = 3..6 times, midpoints pushed onto
    the sphere: 1280, 5120, 20480, 81920 triangles; turned by a fixed generic rotation so
    its lowest vertex is off the spin axis; vertices rounded to the 2^-30 grid, so it is a
    rational polyhedron) above a plate: a closed flat box, top face z = h a k x k
    grid, bottom face a k x k grid, sides k quads each (4k^2 + 8k triangles, k chosen to
    match the sphere's count). The sphere moves by a screw about the vertical line through
    its centre: polyccd Motion.screw(axis=(0,0,-1), center=0, tau0=0, tau1=1/2, advance=A)
    (spin by 2 atan(t/2) about -z, translation -A t z); FCL CCDM_SCREW between the same
    start pose (identity) and end pose (rotation 2 atan(1/2) about -z, translation -A z),
    which it interpolates at constant angular speed (another time parametrization of the
    rotation, same linear translation). A rotation about the z axis keeps every z
    coordinate exactly, so on BOTH paths the sphere's lowest point at time t is
    zmin - A t (zmin = the least vertex z, exact), every plate point has z <= h, and the
    top face covers the sphere's xy disk. Hence the first contact is exactly
    t* = (zmin - h) / A when that is in [0, 1], and there is no contact otherwise:
      hit:   h = zmin - A/2            -> contact, t* = 1/2 (penetration A/2 at t = 1)
      near:  h = zmin - A - G          -> no contact, gap G at t = 1 (closest approach)
      touch: h = zmin - A              -> contact, t* = 1 exactly (touching at the end)
    G = 1074 * 2^-30 = 1.00024e-6 (the double-exact number nearest 1e-6 on the grid).
(2) Molecules. Atoms of a real PDB structure (Debian's libcgal-demo examples: 1t7i,
    1mvm, 1IYE; 1IYE replicated 2 x 2 for 30k; a synthetic jittered ball lattice when the
    files are missing), Bondi van der Waals radii. Molecule A stays; molecule B is the same
    atom set moved so that its leftmost ball b* (least x - r) has the y, z of A's
    rightmost ball a* (greatest x + r), separated in x by D0 = 3 (angstrom), and B translates by
    -L along x (Motion.linear). A's balls lie in x <= X_A, B's in x >= X_B(t), so nothing
    touches before X_B(t) = X_A, and then a*, b* touch (centres r_a* + r_b* apart on a
    line parallel to x):
      hit:   L = 2 D0   -> t* = 1/2;   near: L = D0 - G -> gap G;   touch: L = D0 -> t* = 1.
    Every claim above is re-checked with Fractions before any library runs.

FCL (python-fcl) continuousCollide, ContinuousCollisionRequest(num_max_iterations=10,
toc_err=1e-4, GST_LIBCCD), ccd_motion_type CCDM_SCREW for the meshes and CCDM_TRANS for the
molecules (their path is a pure translation; FCL's screw motion without rotation moves a
body by |d| d instead of d, measured with python-fcl 0.7.0.11: a 2-sphere query with
translation 3 reports its contact at t = 1/6 instead of 1/2):
  FCL-CA     ccd_solver_type=CCDC_CONSERVATIVE_ADVANCEMENT
  FCL-naive  ccd_solver_type=CCDC_NAIVE (10 discrete samples t = i/9)
Meshes are fcl.BVHModel (OBBRSS). python-fcl has no compound shape that continuousCollide
accepts, so a molecule is one fcl.Sphere CollisionObject per atom: the FCL time of a
molecule query is a numpy swept-box prefilter over all atom pairs (counted in the time)
plus one continuousCollide call per surviving pair (all of them, for the first time).

Timing: one process; time.perf_counter_ns around each query; garbage collector off;
minimum over --repeat rounds (a query whose first run exceeds 5 s is not repeated). Body
construction (polyccd Mesh / Spheres, FCL BVHModel / objects) is timed separately.

Usage: python tests/bench/bench_bodies.py [--quick] [--sizes mesh-1k,mol-1k,...]
                                          [--repeat N] [--no-fcl] [--json FILE]
"""

import argparse
import datetime
import gc
import json
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

# Siblings in tests/bench (the script's own folder is on sys.path).
from bench_report import (cpu_model, fit_exponent, fmt_ms, fmt_time, fstr, loaded_libraries,
                          pkg_version, print_table)
from bodies_cases import (ALL_SIZES, GAP, MESH_SIZES, METHODS, QUICK_SIZES, SCREW_ADVANCE,
                          SLOW_NS, VARIANTS, mesh_case, mol_case)
from bodies_methods import (Answer, fcl_build_mesh, fcl_build_mol, fcl_mesh_query,
                            fcl_mol_query, fcl_requests, judge, polyccd_answer,
                            polyccd_build_mesh, polyccd_build_mol, polyccd_mesh_query,
                            polyccd_mol_query, polyccd_scene_api, timed)


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help=f"only {', '.join(QUICK_SIZES)} (CI smoke)")
    ap.add_argument("--sizes", help=f"comma-separated from {', '.join(ALL_SIZES)}; a bare 1k / 5k / ... "
                    "selects both families' entries of that size")
    ap.add_argument("--repeat", type=int, default=int(os.environ.get("POLYCCD_BENCH_REPEAT", "3")))
    ap.add_argument("--no-fcl", action="store_true", help="skip FCL")
    ap.add_argument("--no-polyccd", action="store_true", help="skip polyccd (FCL and truth only)")
    ap.add_argument("--json", metavar="FILE", help="also write every record as JSON")
    opts = ap.parse_args()

    if opts.sizes:
        sizes = []
        for s in opts.sizes.split(","):
            s = s.strip()
            hits = [a for a in ALL_SIZES if a == s or a.split("-", 1)[1] == s]
            if not hits:
                sys.exit(f"--sizes: unknown size {s!r} (choose from {', '.join(ALL_SIZES)})")
            sizes += [h for h in hits if h not in sizes]
    elif opts.quick:
        sizes = list(QUICK_SIZES)
    else:
        sizes = list(ALL_SIZES)
    sizes.sort(key=ALL_SIZES.index)

    polyccd, pnote = None, "skipped (--no-polyccd)"
    if not opts.no_polyccd:
        try:
            import polyccd
            pnote = polyccd_scene_api(polyccd)
            if pnote is not None:
                pnote += ": polyccd columns n/a"
                polyccd = None
        except ImportError as e:
            pnote = f"cannot import polyccd ({e}); run `make venv`"
    fcl, fnote = None, "skipped (--no-fcl)"
    if not opts.no_fcl:
        try:
            import fcl
        except ImportError as e:
            fnote = f"not available ({e}); pip install -r tests/bench/requirements.txt"

    print("polyccd body benchmark: polyccd.check vs FCL continuousCollide, exact truth, one process")
    print(f"date      {datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')}")
    print(f"machine   {cpu_model()}, {os.cpu_count()} logical CPUs, {platform.platform()}")
    print(f"python    {platform.python_version()} ({platform.python_implementation()}), numpy {np.__version__}")
    if polyccd is not None:
        print(f"polyccd   {polyccd.__version__} ({Path(polyccd.__file__).parent})")
        for path, mtime in loaded_libraries(("_pccd", "libpolyccd")):
            print(f"          loaded {path} (modified {mtime})")
    else:
        print(f"polyccd   {pnote}")
    print(f"fcl       python-fcl {pkg_version('python-fcl')}" if fcl else f"fcl       {fnote}")
    print(f"sizes     {', '.join(sizes)}")
    print(f"timing    perf_counter_ns per query, min over {opts.repeat} round(s) (not repeated "
          f"when a run takes > {SLOW_NS / 1e9:.0f} s), gc disabled; body construction timed apart")
    print("FCL       ContinuousCollisionRequest(num_max_iterations=10, toc_err=1e-4, GST_LIBCCD, "
          "CCDM_SCREW for meshes, CCDM_TRANS for molecules); CA = CCDC_CONSERVATIVE_ADVANCEMENT, "
          "naive = CCDC_NAIVE (10 samples)")
    print(f"truth     exact (Fractions), from the geometry only; near-miss gap G = {GAP} = {float(GAP):.6g}")
    print()

    requests = ({"mesh": fcl_requests(fcl, "CCDM_SCREW"), "molecule": fcl_requests(fcl, "CCDM_TRANS")}
                if fcl else {})
    records = []
    scaling = {"mesh": {}, "molecule": {}}
    any_wrong = False
    gc_was = gc.isenabled()
    for label in sizes:
        tb = time.perf_counter_ns()
        case = mesh_case(label, MESH_SIZES[label]) if label in MESH_SIZES else mol_case(label)
        truth_ms = (time.perf_counter_ns() - tb) / 1e6
        fam = case["family"]
        if fam == "mesh":
            SV, SF = case["sphere"]
            print(f"== {label}: icosphere {len(SF)} triangles ({len(SV)} vertices, zmin = "
                  f"{float(case['zmin']):.17g}) vs plate {case['n_b']} triangles (k = {case['k']}); "
                  f"screw: spin 2 atan(t/2) [FCL: t * 2 atan(1/2)] about -z, descent {SCREW_ADVANCE} t")
        else:
            ia, ib = case["pair"]
            print(f"== {label}: 2 x {case['n_a']} atoms ({case['source']}); B translates along -x; "
                  f"first contact decided by A atom {ia} and B atom {ib}")
        print(f"   geometry + exact truth {truth_ms:.0f} ms")
        gc.collect()

        pbuilt = fbuilt = None
        build = {}
        if polyccd is not None:
            pbuilt = (polyccd_build_mesh if fam == "mesh" else polyccd_build_mol)(polyccd, case)
            build["polyccd"] = pbuilt["build_ms"]
        if fcl is not None:
            fbuilt = (fcl_build_mesh if fam == "mesh" else fcl_build_mol)(fcl, case)
            build["fcl"] = fbuilt["build_ms"]
        print("   build (per body pair): " + (", ".join(f"{k} {v:.1f} ms" for k, v in build.items()) or "n/a")
              + ("   [polyccd: Mesh/Spheres; FCL: BVHModel (OBBRSS) / Sphere objects]"))

        rows = []
        for v in VARIANTS:
            var = case["variants"][v]
            truth, tstar = var["truth"], var["t_star"]
            queries = {}
            if polyccd is not None:
                for m, th in (("polyccd-t1", 1), ("polyccd-t2", 2)):
                    queries[m] = (polyccd_mesh_query(polyccd, pbuilt, v, th) if fam == "mesh"
                                  else polyccd_mol_query(polyccd, pbuilt, case, v, th))
            if fcl is not None:
                for m in ("FCL-CA", "FCL-naive"):
                    queries[m] = (fcl_mesh_query(fcl, fbuilt, v, requests[fam][m]) if fam == "mesh"
                                  else fcl_mol_query(fcl, fbuilt, case, v, requests[fam][m]))
            res = {}
            gc.disable()
            try:
                for m, q in queries.items():
                    ns, out = timed(q, opts.repeat)
                    if isinstance(out, Exception):
                        ans = Answer(error=f"{type(out).__name__}: {out}")
                    elif m.startswith("polyccd"):
                        ans = polyccd_answer(out)
                    else:
                        ans = out
                    verdict = judge(ans, truth, tstar, m.startswith("polyccd"))
                    if m.startswith("polyccd") and verdict != "OK":
                        any_wrong = True
                    res[m] = (ns, ans, verdict)
            finally:
                if gc_was:
                    gc.enable()
            rec = {"size": label, "family": fam, "variant": v, "primitives_a": case["n_a"],
                   "primitives_b": case["n_b"], "truth": truth, "t_star": fstr(tstar),
                   "gap": fstr(var["gap"]), "build_ms": build, "methods": {}}
            for m in METHODS:
                if m not in res:
                    rec["methods"][m] = None
                    continue
                ns, ans, verdict = res[m]
                rec["methods"][m] = {
                    "ms": ns / 1e6, "verdict": verdict, "collides": ans.collides, "error": ans.error,
                    "time": ans.time, "exact": fstr(ans.exact), "lo": fstr(ans.lo), "hi": fstr(ans.hi),
                    **{k: val for k, val in ans.extra.items()}}
            records.append(rec)
            n_tot = case["n_a"] + case["n_b"]
            for m in METHODS:
                if m in res and res[m][1].error is None:
                    scaling[fam].setdefault((m, v), []).append((n_tot, res[m][0] / 1e6))

            def cell(m):
                return (fmt_ms(res[m][0]), res[m][2]) if m in res else ("n/a", "-")

            truth_txt = (f"hit t*={tstar}" if truth else f"miss gap={float(var['gap']):.3g}")
            row = [v, truth_txt]
            for m in METHODS:
                row += list(cell(m))
            ca = res.get("FCL-CA")
            p1 = res.get("polyccd-t1")
            row.append(f"{p1[0] / ca[0]:.3g}" if ca and p1 else "n/a")
            row.append(" / ".join(fmt_time(res[m][1]) if m in res else "n/a"
                                  for m in ("polyccd-t1", "FCL-CA", "FCL-naive")))
            if fam == "molecule" and "FCL-CA" in res:
                row.append(res["FCL-CA"][1].extra.get("pairs_tested", "?"))
            rows.append(row)
        hdr = ["variant", "truth", "polyccd t=1 ms", "ans", "polyccd t=2 ms", "ans", "FCL-CA ms", "ans",
               "FCL-naive ms", "ans", "poly/CA", "first time poly / CA / naive"]
        if fam == "molecule" and fcl is not None:
            hdr.append("FCL pairs")
        print_table(hdr, rows)
        for rec in records[-len(VARIANTS):]:
            p = rec["methods"].get("polyccd-t1")
            if p and p.get("stats"):
                print(f"   polyccd stats ({rec['variant']}): {p['stats']}")
            for m in METHODS:
                e = rec["methods"].get(m)
                if e and e["error"]:
                    print(f"   {m} ({rec['variant']}) raised {e['error']}")
        print()

    print("scaling: fitted exponent of time vs total primitive count (least squares on log-log)")
    srows = []
    for fam in ("mesh", "molecule"):
        for m in METHODS:
            exps = []
            for v in VARIANTS:
                pts = scaling[fam].get((m, v), [])
                exps.append(fit_exponent(pts))
            if all(e is None for e in exps):
                continue
            good = [e for e in exps if e is not None]
            srows.append([fam, m] + [f"{e:.2f}" if e is not None else "n/a" for e in exps]
                         + [f"{sum(good) / len(good):.2f}"])
    if srows:
        print_table(["family", "method"] + [f"exp ({v})" for v in VARIANTS] + ["mean"], srows)
    else:
        print("   n/a (needs two sizes of a family)")
    print()
    bad = [(r["size"], r["variant"], m, e["verdict"]) for r in records for m, e in r["methods"].items()
           if e and e["verdict"] != "OK"]
    print(f"answers: {sum(1 for r in records for e in r['methods'].values() if e)} computed, "
          f"{len(bad)} not OK" + (": " + "; ".join(f"{s}/{v} {m} {x}" for s, v, m, x in bad) if bad else ""))
    if polyccd is None:
        print(f"polyccd: {pnote}")

    if opts.json:
        exps = {fam: {f"{m}/{v}": fit_exponent(p) for (m, v), p in d.items()} for fam, d in scaling.items()}
        out = {"date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
               "cpu": cpu_model(), "python": platform.python_version(),
               "polyccd": getattr(polyccd, "__version__", None), "polyccd_note": pnote if polyccd is None else None,
               "fcl": pkg_version("python-fcl") if fcl else None, "repeat": opts.repeat, "sizes": sizes,
               "gap": str(GAP), "records": records, "exponents": exps}
        Path(opts.json).write_text(json.dumps(out, indent=2, default=str) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
