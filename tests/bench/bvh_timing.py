"""The moves and the clocks of bench_bvh.py: the CGAL meshes it loads, the poses of the
moving copy (far, hit, near, rot) as polyccd motions and FCL transforms, and the timed
runs of polyccd and FCL with their answers (first contact time, or none)."""
import math
import time
from fractions import Fraction

import numpy as np

import bench_report as BR      # tests/bench on sys.path (bench_bvh.py puts it there)
import bodies_methods as BM

TAU1 = Fraction(1, 2)  # rotation: tan(angle(1) / 2) = 1/2

def load_mesh(name):
    import trimesh
    from polyccd.apps._data import cgal_data_file
    m = trimesh.load(str(cgal_data_file(name, install=True)), process=False, validate=False)
    V = np.array(m.vertices, dtype=np.float64)
    F = np.array(m.faces, dtype=np.int64)
    V -= (V.min(axis=0) + V.max(axis=0)) / 2
    ext = float((V.max(axis=0) - V.min(axis=0)).max())
    V *= 2.0 ** -math.ceil(math.log2(ext))
    return V, F


def quat_z(angle):
    return np.array([math.cos(angle / 2), 0.0, 0.0, math.sin(angle / 2)])


def rotz(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


THETA1 = -2 * math.atan(float(TAU1))  # about +z (axis -z in polyccd)


def fcl_time_of(t):
    """FCL's (angle-linear) time of polyccd's time t on the rot path."""
    return 2 * math.atan(float(t) * float(TAU1)) / (2 * math.atan(float(TAU1)))


def poses(E, kind, P=None):
    """(polyccd motion, FCL start Transform args, FCL end Transform args, motion type)."""
    import polyccd
    if kind == "rot":
        off = [1.1 * E, 0.0, 0.0]
        P = [1.1 * E, E, 0.0] if P is None else P
        m = polyccd.Motion.axis_rotation([0, 0, -1], P, 0, TAU1).compose([1, 0, 0, 0], off, side="body")
        Pn = np.array(P)
        end = (quat_z(THETA1), rotz(THETA1) @ (np.array(off) - Pn) + Pn)
        return m, (np.array(off),), end, "CCDM_SCREW"
    x0, x1 = {"far": (3 * E, 2.5 * E), "hit": (1.5 * E, 0.5 * E)}[kind]
    return (polyccd.Motion.linear([x0, 0, 0], [x1, 0, 0]), (np.array([x0, 0.0, 0.0]),),
            (np.array([x1, 0.0, 0.0]),), "CCDM_TRANS")


def poly_answer(r):
    fc = r.first_contact
    key = (r.collides, None if fc is None else (fc.lo, fc.hi, fc.exact))
    return key, (None if fc is None else float(fc.approx))


FAST_NS = 50_000


def stop_short(polyccd, E, lo):
    """The hit translation x0 = 1.5 E -> (x0 - E) stopped 2^-20 E before the x it has at
    time lo (the hit's first contact, or its first time within delta): a near miss.
    (motion, FCL start, FCL end, FCL motion type, the end x)."""
    x0 = 1.5 * E
    xc = Fraction(x0) - Fraction(lo) * Fraction(E)  # >= x at time lo
    x1 = float(xc + Fraction(E) * Fraction(1, 2 ** 20))
    while Fraction(x1) <= xc:
        x1 = math.nextafter(x1, math.inf)
    motion = polyccd.Motion.linear([x0, 0, 0], [x1, 0, 0])
    return motion, (np.array([x0, 0.0, 0.0]),), (np.array([x1, 0.0, 0.0]),), "CCDM_TRANS", x1


def time_fcl(fcl, bvh, start, end, reqs, repeat, row):
    """FCL's continuous collision of the mesh (at rest) against its copy moving from the
    pose start to end, with each request of reqs ("FCL-CA", "FCL-naive"): row[name] is the
    time in ns, row[name + " ans"] the answer (collides, time of contact)."""
    oA = fcl.CollisionObject(bvh, fcl.Transform())
    oB = fcl.CollisionObject(bvh, fcl.Transform(*start))
    for name in ("FCL-CA", "FCL-naive"):
        req = reqs[name]

        def run():
            res = fcl.ContinuousCollisionResult()
            fcl.continuousCollide(oA, fcl.Transform(), oB, fcl.Transform(*end), req, res)
            return res.is_collide, res.time_of_contact
        row[name], row[name + " ans"] = timed(run, repeat)


def timed(fn, repeat):
    """(min ns per call, first call's output): BM.timed, then for a call under FAST_NS
    also the per-call mean of `repeat` batches of about 1 ms (see Timing above)."""
    best, out = BM.timed(fn, repeat)
    if isinstance(out, Exception) or best >= FAST_NS:
        return best, out
    k = max(1, int(1_000_000 // max(best, 1)))
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter_ns()
        for _ in range(k):
            fn()
        best = min(best, (time.perf_counter_ns() - t0) / k)
    return best, out


def time_poly(polyccd, bodies, threads, repeat, broad_phase="auto", min_distance=None):
    ns, out = timed(lambda: polyccd.check(bodies, threads=threads, broad_phase=broad_phase,
                                          min_distance=min_distance), repeat)
    if isinstance(out, Exception):
        raise out
    return ns, out


def fmt(ns):
    if ns is not None and ns < 100_000:  # under 0.1 ms: to 0.1 us
        return f"{ns / 1e6:.4f}"
    return BR.fmt_ms(ns)
