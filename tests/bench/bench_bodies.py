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
import math
import os
import platform
import sys
import tarfile
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

GRID = 2 ** 30                       # every number is a multiple of 1/GRID
GAP = Fraction(1074, GRID)           # the near-miss gap, 1.00024e-6
MESH_SIZES = {"mesh-1k": 3, "mesh-5k": 4, "mesh-20k": 5, "mesh-80k": 6}  # icosphere subdivisions
MOL_SIZES = ("mol-1k", "mol-5k", "mol-30k")
ALL_SIZES = tuple(MESH_SIZES) + MOL_SIZES
QUICK_SIZES = ("mesh-1k", "mol-1k")
VARIANTS = ("hit", "near", "touch")
METHODS = ("polyccd-t1", "polyccd-t2", "FCL-CA", "FCL-naive")
SCREW_TAU = Fraction(1, 2)           # tan(theta(1)/2): the spin at t = 1 is 2 atan(1/2) = 53.13 deg
SCREW_ADVANCE = Fraction(1, 4)       # A: the sphere's descent over [0, 1]
TILT = (1.0, 0.3, 0.2, 0.1)          # quaternion turning the icosphere before rounding
PLATE_HALF = Fraction(5, 4)          # plate top face [-5/4, 5/4]^2 (sphere radius 1)
PLATE_THICK = Fraction(1, 4)
MOL_D0 = Fraction(3)                 # initial x separation of the molecules' extreme balls
BONDI = {"H": Fraction("1.20"), "C": Fraction("1.70"), "N": Fraction("1.55"), "O": Fraction("1.52"),
         "S": Fraction("1.80"), "P": Fraction("1.80")}
CGAL_EXAMPLES = Path("/usr/share/doc/libcgal-demo/examples.tar.gz")
PDB_DIR = "examples/Skin_surface_3/data/"
SLOW_NS = 5_000_000_000


def on_grid(x):
    """float64 array -> nearest multiples of 2^-30 (exact doubles for |x| < 2^22)."""
    x = np.asarray(x, dtype=np.float64)
    assert np.all(np.abs(x) < 2.0 ** 22)
    return np.round(x * GRID) / GRID


def grid_fraction(q):
    """A Fraction that must be a multiple of 2^-30 -> that exact double."""
    assert (q * GRID).denominator == 1 and abs(q) < 2 ** 22, q
    x = float(q)
    assert Fraction(x) == q
    return x


def fr(x):
    return Fraction(float(x))


# ---------------------------------------------------------------------------------------
# Meshes: icosphere and plate


def icosphere(subdivisions):
    """Unit icosphere: the icosahedron, each triangle split in 4 per level, new vertices
    (edge midpoints) pushed onto the unit sphere, then turned by TILT and rounded to the
    2^-30 grid. 20 * 4^s triangles, 10 * 4^s + 2 vertices."""
    p = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p),
             (0, -1, -p), (0, 1, -p), (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    verts = [tuple(c / math.sqrt(1.0 + p * p) for c in v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        cache = {}

        def mid(a, b):
            key = (a, b) if a < b else (b, a)
            if key not in cache:
                m = [(verts[a][i] + verts[b][i]) / 2.0 for i in range(3)]
                n = math.sqrt(sum(c * c for c in m))
                verts.append(tuple(c / n for c in m))
                cache[key] = len(verts) - 1
            return cache[key]

        new = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    # a fixed generic tilt, so that the lowest vertex is off the spin axis and unique
    q = np.array(TILT, dtype=float) / np.linalg.norm(TILT)
    w, x, y, z = q
    rot = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return on_grid(np.array(verts) @ rot.T), np.array(faces, dtype=np.int64)


def plate(k, h):
    """Closed flat box [-W, W]^2 x [h - T, h]: top and bottom k x k grids (2 triangles per
    cell), each side k quads; 4k^2 + 8k triangles. Every coordinate is on the 2^-30 grid."""
    W = float(PLATE_HALF)
    xs = on_grid(np.linspace(-W, W, k + 1))
    xs[0], xs[-1] = -W, W
    hz, bz = grid_fraction(h), grid_fraction(h - PLATE_THICK)
    gx, gy = np.meshgrid(xs, xs, indexing="ij")
    n = (k + 1) ** 2
    top = np.column_stack([gx.ravel(), gy.ravel(), np.full(n, hz)])
    bot = np.column_stack([gx.ravel(), gy.ravel(), np.full(n, bz)])
    V = np.vstack([top, bot])

    def vid(i, j, level):
        return level * n + i * (k + 1) + j

    F = []
    for i in range(k):
        for j in range(k):
            a, b, c, d = vid(i, j, 0), vid(i + 1, j, 0), vid(i + 1, j + 1, 0), vid(i, j + 1, 0)
            F += [(a, b, c), (a, c, d)]                          # top, facing +z
            a, b, c, d = (vid(i, j, 1), vid(i + 1, j, 1), vid(i + 1, j + 1, 1), vid(i, j + 1, 1))
            F += [(a, c, b), (a, d, c)]                          # bottom, facing -z
    ring = ([(i, 0) for i in range(k)] + [(k, j) for j in range(k)] +
            [(i, k) for i in range(k, 0, -1)] + [(0, j) for j in range(k, 0, -1)])
    ring.append(ring[0])
    for (i0, j0), (i1, j1) in zip(ring[:-1], ring[1:]):
        a, b = vid(i0, j0, 0), vid(i1, j1, 0)
        c, d = vid(i1, j1, 1), vid(i0, j0, 1)
        F += [(a, d, c), (a, c, b)]
    return V, np.array(F, dtype=np.int64), top_count(k)


def top_count(k):
    return (k + 1) ** 2


def plate_k(ntri):
    """k whose plate triangle count 4k^2 + 8k is nearest ntri."""
    return min(range(1, 400), key=lambda k: abs(4 * k * k + 8 * k - ntri))


def quat_z(tau):
    """polyccd's rotation quaternion r = (1, 0, 0, -tau) (axis (0,0,-1)) as a unit
    quaternion [w, x, y, z] for fcl.Transform."""
    n = math.sqrt(1.0 + float(tau) ** 2)
    return np.array([1.0 / n, 0.0, 0.0, -float(tau) / n])


def rotz_exact(tau):
    """R(r) of formats.md for r = (1, 0, 0, -tau), exact."""
    w, v = Fraction(1), (Fraction(0), Fraction(0), -Fraction(tau))
    n2 = w * w + sum(c * c for c in v)
    vv = sum(c * c for c in v)
    cross = [[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]
    return [[((w * w - vv) * (i == j) + 2 * v[i] * v[j] + 2 * w * cross[i][j]) / n2 for j in range(3)]
            for i in range(3)]


def mesh_truth(SV, PV, ntop, h, variant):
    """Exact truth of the sphere/plate screw query, from the geometry alone."""
    A = SCREW_ADVANCE
    zs = [fr(z) for z in SV[:, 2]]
    zmin = min(zs)
    # a rotation about the z axis keeps z: the z row of R is (0, 0, 1) for every tau
    for tau in (Fraction(0), SCREW_TAU / 3, SCREW_TAU, Fraction(7, 3)):
        assert rotz_exact(tau)[2] == [0, 0, 1]
    # the sphere's xy disk (invariant under the spin) is inside the plate's top face
    r2 = max(fr(x) ** 2 + fr(y) ** 2 for x, y in SV[:, :2])
    assert r2 < PLATE_HALF ** 2
    top, rest = PV[:ntop], PV[ntop:]
    assert all(fr(z) == h for z in top[:, 2]) and all(fr(z) <= h for z in rest[:, 2])
    assert fr(top[:, 0].min()) == -PLATE_HALF and fr(top[:, 0].max()) == PLATE_HALF
    assert fr(top[:, 1].min()) == -PLATE_HALF and fr(top[:, 1].max()) == PLATE_HALF
    assert zmin > h, "the bodies must be apart at t = 0"
    tstar = (zmin - h) / A
    expect = {"hit": Fraction(1, 2), "near": 1 + GAP / A, "touch": Fraction(1)}[variant]
    assert tstar == expect
    if tstar <= 1:
        return True, tstar, None
    return False, None, zmin - A - h       # the gap at t = 1


def mesh_case(label, subdivisions):
    SV, SF = icosphere(subdivisions)
    zmin = min(fr(z) for z in SV[:, 2])
    k = plate_k(len(SF))
    A = SCREW_ADVANCE
    heights = {"hit": zmin - A / 2, "near": zmin - A - GAP, "touch": zmin - A}
    variants = {}
    for v in VARIANTS:
        PV, PF, ntop = plate(k, heights[v])
        collides, tstar, gap = mesh_truth(SV, PV, ntop, heights[v], v)
        variants[v] = {"plate": (PV, PF), "truth": collides, "t_star": tstar, "gap": gap}
    return {"label": label, "family": "mesh", "sphere": (SV, SF), "k": k,
            "n_a": len(SF), "n_b": len(variants["hit"]["plate"][1]), "variants": variants,
            "zmin": zmin}


# ---------------------------------------------------------------------------------------
# Molecules


def read_pdb_atoms(name):
    """[(x, y, z, element)] of the ATOM/HETATM records of a PDB file from the CGAL examples."""
    with tarfile.open(CGAL_EXAMPLES) as tar:
        text = tar.extractfile(PDB_DIR + name).read().decode("ascii", "replace")
    atoms = []
    for line in text.splitlines():
        if line.startswith(("ATOM  ", "HETATM")):
            el = line[76:78].strip().upper() or line[12:14].strip().lstrip("0123456789")[:1]
            atoms.append((float(line[30:38]), float(line[38:46]), float(line[46:54]), el))
    return atoms


def synthetic_atoms(n, seed):
    """A jittered cubic lattice of carbon balls (spacing 3.6 > 2 * 1.70): no two overlap."""
    rng = np.random.default_rng(seed)
    m = math.ceil(n ** (1 / 3))
    idx = np.array([(i, j, l) for i in range(m) for j in range(m) for l in range(m)][:n], dtype=float)
    pts = idx * 3.6 + rng.uniform(-0.05, 0.05, idx.shape)
    return [(x, y, z, "C") for x, y, z in pts]


def molecule(label):
    """(centers float64 (n, 3) on the grid, radii float64 (n,) on the grid, source text)."""
    try:
        if label == "mol-1k":
            atoms, src = read_pdb_atoms("1t7i.pdb")[:1000], "1t7i.pdb, first 1000 atoms"
        elif label == "mol-5k":
            atoms, src = read_pdb_atoms("1mvm.pdb"), "1mvm.pdb, all atoms"
        else:
            base = read_pdb_atoms("1IYE.pdb")
            xyz = np.array([a[:3] for a in base])
            ext = xyz.max(axis=0) - xyz.min(axis=0) + 8.0
            atoms = [(x, y + dy * ext[1], z + dz * ext[2], e) for dy in (0, 1) for dz in (0, 1)
                     for x, y, z, e in base]
            src = "1IYE.pdb replicated 2 x 2 in y, z"
    except (OSError, KeyError, tarfile.TarError) as e:
        n = {"mol-1k": 1000, "mol-5k": 5000, "mol-30k": 30000}[label]
        atoms = synthetic_atoms(n, seed=len(label))
        src = f"synthetic jittered lattice ({CGAL_EXAMPLES} unavailable: {type(e).__name__})"
    C = on_grid([a[:3] for a in atoms])
    R = on_grid([float(BONDI.get(a[3], Fraction("1.80"))) for a in atoms])
    return C, R, src


def mol_case(label):
    C, R, src = molecule(label)
    # extreme balls, exact
    right = [fr(x) + fr(r) for x, r in zip(C[:, 0], R)]
    left = [fr(x) - fr(r) for x, r in zip(C[:, 0], R)]
    ia = max(range(len(C)), key=right.__getitem__)
    ib = min(range(len(C)), key=left.__getitem__)
    XA, XB0 = right[ia], left[ib]
    # B = A + offset: b*'s centre gets a*'s y, z and X_B(0) = X_A + D0
    off = (XA + MOL_D0 - XB0, fr(C[ia, 1]) - fr(C[ib, 1]), fr(C[ia, 2]) - fr(C[ib, 2]))
    offset = np.array([grid_fraction(o) for o in off])
    variants = {}
    for v in VARIANTS:
        L = {"hit": 2 * MOL_D0, "near": MOL_D0 - GAP, "touch": MOL_D0}[v]
        # exact checks: slab separation, the touching pair, the truth
        xb_left = min(fr(x) - fr(r) for x, r in zip(C[:, 0], R)) + off[0]
        assert xb_left == XA + MOL_D0 > XA
        ca = [fr(c) for c in C[ia]]
        cb = [fr(c) + o for c, o in zip(C[ib], off)]
        tstar = MOL_D0 / L
        if tstar <= 1:
            cb_t = [cb[0] - L * tstar, cb[1], cb[2]]
            d2 = sum((p - q) ** 2 for p, q in zip(ca, cb_t))
            assert d2 == (fr(R[ia]) + fr(R[ib])) ** 2, "a*, b* must touch at t*"
            variants[v] = {"L": L, "truth": True, "t_star": tstar, "gap": None}
        else:
            gap = xb_left - L - XA
            assert gap == GAP
            variants[v] = {"L": L, "truth": False, "t_star": None, "gap": gap}
    return {"label": label, "family": "molecule", "centers": C, "radii": R, "offset": offset,
            "offset_exact": off, "source": src, "n_a": len(C), "n_b": len(C),
            "variants": variants, "pair": (ia, ib)}


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


# ---------------------------------------------------------------------------------------
# Reporting


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def loaded_libraries(names):
    """[(path, mtime)] of the shared objects this process mapped whose name contains one of
    names (from /proc/self/maps: the files actually in use, even if rebuilt since)."""
    seen = []
    try:
        with open("/proc/self/maps") as f:
            for line in f:
                path = line.split(None, 5)[-1].strip() if len(line.split(None, 5)) == 6 else ""
                if any(n in Path(path).name for n in names) and path not in [p for p, _ in seen]:
                    deleted = path.endswith(" (deleted)")
                    try:
                        mtime = ("file replaced since" if deleted else datetime.datetime.fromtimestamp(
                            os.stat(path).st_mtime, datetime.timezone.utc).isoformat(timespec="seconds"))
                    except OSError:
                        mtime = "?"
                    seen.append((path, mtime))
    except OSError:
        pass
    return seen


def pkg_version(name):
    try:
        from importlib.metadata import version

        return version(name)
    except Exception:
        return "not installed"


def print_table(headers, rows):
    widths = [max(len(str(h)), *(len(str(r[i])) for r in rows)) for i, h in enumerate(headers)]
    line = "  ".join(f"{h:>{w}}" for h, w in zip(headers, widths))
    print(line)
    print("-" * len(line))
    for r in rows:
        print("  ".join(f"{str(c):>{w}}" for c, w in zip(r, widths)))


def fmt_ms(ns):
    if ns is None:
        return "n/a"
    ms = ns / 1e6
    return f"{ms:.3f}" if ms < 10 else f"{ms:.1f}"


def fmt_time(ans):
    if ans is None or ans.error is not None or not ans.collides:
        return "-"
    if ans.exact is not None:
        return str(ans.exact)
    return f"{ans.time:.6g}" if ans.time is not None else "?"


def fit_exponent(points):
    """Least-squares slope of log(time) against log(primitives)."""
    pts = [(n, t) for n, t in points if t and t > 0]
    if len(pts) < 2 or len({n for n, _ in pts}) < 2:
        return None
    x = np.log([n for n, _ in pts])
    y = np.log([t for _, t in pts])
    return float(np.polyfit(x, y, 1)[0])


def fstr(q):
    return None if q is None else str(q)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
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
