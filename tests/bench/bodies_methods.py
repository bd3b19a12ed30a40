"""The methods bench_bodies.py compares and how they are timed: polyccd (the scene API,
1 and 2 threads) and FCL (conservative advancement, and the naive per-pair query), each
answer judged against the exact truth of bodies_cases."""
import time

import numpy as np

# Siblings in tests/bench (the script's own folder is on sys.path).
from bodies_cases import SCREW_ADVANCE, SCREW_TAU, SLOW_NS, VARIANTS, grid_fraction, quat_z

# ---------------------------------------------------------------------------------------
# Timing


def timed(fn, repeat):
    """(min ns over rounds, first round's output or exception)."""
    best, out = None, None
    for i in range(max(1, repeat)):
        try:
            t0 = time.perf_counter_ns()
            r = fn()
            t1 = time.perf_counter_ns()
        except Exception as e:  # recorded as an error of that method, never hidden
            t1 = time.perf_counter_ns()
            r = e
        dt = t1 - t0
        if i == 0:
            out = r
        best = dt if best is None else min(best, dt)
        if dt > SLOW_NS or isinstance(r, Exception):
            break
    return best, out


class Answer:
    def __init__(self, collides=None, time=None, exact=None, lo=None, hi=None, error=None, extra=None):
        self.collides, self.time, self.exact, self.lo, self.hi = collides, time, exact, lo, hi
        self.error, self.extra = error, extra or {}


def judge(ans, truth, tstar, exact_method):
    """'OK' / 'WRONG' / 'ERROR' for the decision; for an exact method a contact time that
    does not enclose t* is WRONG too."""
    if ans.error is not None:
        return "ERROR"
    if bool(ans.collides) != truth:
        return "WRONG"
    if exact_method and truth:
        if ans.exact is not None and ans.exact != tstar:
            return "WRONG"
        if ans.lo is not None and not (ans.lo <= tstar <= ans.hi):
            return "WRONG"
    return "OK"


# polyccd ---------------------------------------------------------------------------------


def polyccd_scene_api(polyccd):
    missing = [n for n in ("check", "Body") if not hasattr(polyccd, n)]
    return f"polyccd.{', polyccd.'.join(missing)} missing" if missing else None


def polyccd_answer(r):
    fc = r.first_contact
    if fc is None:
        return Answer(collides=bool(r.collides), extra={"stats": dict(r.stats)})
    return Answer(collides=bool(r.collides), time=float(fc.approx), exact=fc.exact, lo=fc.lo, hi=fc.hi,
                  extra={"stats": dict(r.stats)})


def polyccd_build_mesh(polyccd, case):
    SV, SF = case["sphere"]
    t0 = time.perf_counter_ns()
    sphere = polyccd.Mesh(SV, SF)
    t1 = time.perf_counter_ns()
    plates = {v: polyccd.Mesh(*case["variants"][v]["plate"]) for v in VARIANTS}
    t2 = time.perf_counter_ns()
    motion = polyccd.Motion.screw([0, 0, -1], [0, 0, 0], 0, SCREW_TAU, SCREW_ADVANCE).validate()
    return {"sphere": sphere, "plates": plates, "motion": motion,
            "build_ms": (t1 - t0) / 1e6 + (t2 - t1) / 1e6 / len(VARIANTS)}


def polyccd_mesh_query(polyccd, built, variant, threads):
    bodies = [polyccd.Body(built["sphere"], built["motion"], name="sphere"),
              polyccd.Body(built["plates"][variant], None, name="plate")]
    return lambda: polyccd.check(bodies, threads=threads)


def polyccd_build_mol(polyccd, case):
    t0 = time.perf_counter_ns()
    shape = polyccd.Spheres(case["centers"], case["radii"])
    t1 = time.perf_counter_ns()
    return {"shape": shape, "build_ms": (t1 - t0) / 1e6}


def polyccd_mol_query(polyccd, built, case, variant, threads):
    off = case["offset_exact"]
    L = case["variants"][variant]["L"]
    mB = polyccd.Motion.linear(list(off), [off[0] - L, off[1], off[2]]).validate()
    bodies = [polyccd.Body(built["shape"], None, name="A"), polyccd.Body(built["shape"], mB, name="B")]
    return lambda: polyccd.check(bodies, threads=threads)


# FCL -------------------------------------------------------------------------------------


def fcl_requests(fcl, motion_type):
    common = dict(num_max_iterations=10, toc_err=1e-4, ccd_motion_type=getattr(fcl.CCDMotionType, motion_type),
                  gjk_solver_type=fcl.GJKSolverType.GST_LIBCCD)
    return {"FCL-CA": fcl.ContinuousCollisionRequest(
                ccd_solver_type=fcl.CCDSolverType.CCDC_CONSERVATIVE_ADVANCEMENT, **common),
            "FCL-naive": fcl.ContinuousCollisionRequest(
                ccd_solver_type=fcl.CCDSolverType.CCDC_NAIVE, **common)}


def fcl_bvh(fcl, V, F):
    m = fcl.BVHModel()
    m.beginModel(len(F), len(V))
    m.addSubModel(V, F)
    m.endModel()
    return m


def fcl_build_mesh(fcl, case):
    SV, SF = case["sphere"]
    t0 = time.perf_counter_ns()
    sphere = fcl.CollisionObject(fcl_bvh(fcl, SV, SF), fcl.Transform())
    t1 = time.perf_counter_ns()
    plates = {v: fcl.CollisionObject(fcl_bvh(fcl, *case["variants"][v]["plate"]), fcl.Transform())
              for v in VARIANTS}
    t2 = time.perf_counter_ns()
    end = fcl.Transform(quat_z(SCREW_TAU), np.array([0.0, 0.0, -float(SCREW_ADVANCE)]))
    return {"sphere": sphere, "plates": plates, "sphere_end": end, "identity": fcl.Transform(),
            "build_ms": (t1 - t0) / 1e6 + (t2 - t1) / 1e6 / len(VARIANTS)}


def fcl_mesh_query(fcl, built, variant, request):
    o1, o2 = built["sphere"], built["plates"][variant]
    e1, e2 = built["sphere_end"], built["identity"]

    def run():
        res = fcl.ContinuousCollisionResult()
        toc = fcl.continuousCollide(o1, e1, o2, e2, request, res)
        return Answer(collides=bool(res.is_collide), time=float(res.time_of_contact),
                      extra={"returned": float(toc)})
    return run


def fcl_build_mol(fcl, case):
    C, R, off = case["centers"], case["radii"], case["offset"]
    t0 = time.perf_counter_ns()
    geoms = [fcl.Sphere(float(r)) for r in R]
    objA = [fcl.CollisionObject(g, fcl.Transform(c)) for g, c in zip(geoms, C)]
    objB = [fcl.CollisionObject(g, fcl.Transform(c + off)) for g, c in zip(geoms, C)]
    endA = [fcl.Transform(c) for c in C]
    t1 = time.perf_counter_ns()
    endB = {}
    for v in VARIANTS:                 # B's end poses depend on the variant's path length
        shift = off - np.array([grid_fraction(case["variants"][v]["L"]), 0.0, 0.0])
        endB[v] = [fcl.Transform(c + shift) for c in C]
    t2 = time.perf_counter_ns()
    return {"objA": objA, "objB": objB, "endA": endA, "endB": endB,
            "build_ms": (t1 - t0) / 1e6 + (t2 - t1) / 1e6 / len(VARIANTS)}


def swept_pairs(C, R, off, L):
    """Atom pairs (i in A, j in B) whose axis-aligned boxes swept over [0, 1] overlap; B's
    centres move from C + off to C + off - (L, 0, 0). Exact enough: the boxes are widened
    by 1e-9, so no touching pair is lost to rounding."""
    eps = 1e-9
    Bc = C + off
    # B's swept box: x in [x - r - L, x + r]; A's box: [x - r, x + r]
    a_lo, a_hi = C - R[:, None] - eps, C + R[:, None] + eps
    b_lo = Bc - R[:, None]
    b_hi = Bc + R[:, None]
    b_lo[:, 0] -= L
    # prune to the atoms that can reach the other molecule's box at all
    ia = np.nonzero(a_hi[:, 0] >= b_lo[:, 0].min())[0]
    ib = np.nonzero(b_lo[:, 0] <= a_hi[:, 0].max())[0]
    pairs_i, pairs_j = [], []
    order = ia[np.argsort(a_lo[ia, 1])]
    ylo_sorted = a_lo[order, 1]
    for j in ib:
        k = np.searchsorted(ylo_sorted, b_hi[j, 1], side="right")
        cand = order[:k]
        ok = ((a_hi[cand, 1] >= b_lo[j, 1]) & (a_lo[cand, 0] <= b_hi[j, 0]) & (a_hi[cand, 0] >= b_lo[j, 0])
              & (a_lo[cand, 2] <= b_hi[j, 2]) & (a_hi[cand, 2] >= b_lo[j, 2]))
        sel = cand[ok]
        pairs_i.append(sel)
        pairs_j.append(np.full(len(sel), j))
    if not pairs_i:
        return np.empty(0, dtype=np.int64), np.empty(0, dtype=np.int64)
    return np.concatenate(pairs_i), np.concatenate(pairs_j)


def fcl_mol_query(fcl, built, case, variant, request):
    C, R, off = case["centers"], case["radii"], case["offset"]
    L = float(case["variants"][variant]["L"])
    objA, objB, endA, endB = built["objA"], built["objB"], built["endA"], built["endB"][variant]

    def run():
        pi, pj = swept_pairs(C, R, off, L)
        hit, toc = False, 1.0
        for i, j in zip(pi.tolist(), pj.tolist()):
            res = fcl.ContinuousCollisionResult()
            fcl.continuousCollide(objA[i], endA[i], objB[j], endB[j], request, res)
            if res.is_collide:
                hit = True
                toc = min(toc, float(res.time_of_contact))
        return Answer(collides=hit, time=toc if hit else None, extra={"pairs_tested": len(pi)})
    return run
