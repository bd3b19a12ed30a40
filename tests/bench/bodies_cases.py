"""The bodies of bench_bodies.py and their exact truth: icosphere meshes over a plate
and molecules (PDB atom sets, or synthetic ones) over a plate, every number a multiple
of 2^-30 so that each is an exact double; for every variant (hit, near miss, touch) the
first contact time is known exactly from the construction (mesh_truth, mol_case)."""
import math
import tarfile
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
