"""The scenes of bench_online.py: the stored body (a terrain mesh or a slab of balls,
every number on a 2^-16 grid), the query bodies, their motions (linear, rotation,
polynomial, axis swings) and their placement so that a known fraction hits (see
bench_online.py's docstring for the parameters' meaning)."""
import math

import numpy as np

GRID = 2.0 ** 16                     # every coordinate and coefficient is a multiple of 2^-16
CLASSES = ("mesh", "mol")
MOTIONS = ("linear", "rotation", "poly", "axis")   # append only: rng_for seeds by the index
HIT_FRACTION = 0.10
MESH_SAMPLES_T = 41                  # time samples for placing a triangle query
MOL_SAMPLES_T = 25                   # time samples for placing a ball query
CHUNK = 1024                         # queries per numpy chunk while placing

# terrain and slab parameters (see the docstring)
BUMP_AMP, BUMP_P1, BUMP_P2, NOISE = 1.0, 20.0, 13.0, 0.05
MOL_SPACING, MOL_LAYERS, MOL_DROP, MOL_JITTER, MOL_BUMP, MOL_BUMP_P = 3.6, 3, 0.10, 0.3, 2.0, 40.0
RADII = (1.2, 2.0)
SCALE = {"mesh": {"run": (1.5, 3.0), "drop": (0.0, 1.0), "bend": 0.6,
                  "miss": (0.02, 0.2), "hit": (-0.4, -0.1), "start": 0.02},
         "mol": {"run": (4.0, 8.0), "drop": (0.0, 3.0), "bend": 2.0,
                 "miss": (0.05, 0.5), "hit": (-0.8, -0.2), "start": 0.05}}


def on_grid(x):
    x = np.asarray(x, dtype=np.float64)
    assert np.all(np.abs(x) < 2.0 ** 30)
    return np.round(x * GRID) / GRID


def rng_for(seed, cls, motion, n, what):
    return np.random.default_rng([seed, CLASSES.index(cls), MOTIONS.index(motion), n, what])


# ---------------------------------------------------------------------------------------
# Stored bodies


def terrain(n, rng):
    """(V (float64, exact), F, H heights (k+1, k+1), k): a height field over [0, k]^2 with
    unit cells, each cell split along its (i, j)-(i+1, j+1) diagonal."""
    k = max(2, round(math.sqrt(n / 2)))
    xs = np.arange(k + 1, dtype=float)
    gx, gy = np.meshgrid(xs, xs, indexing="ij")
    ph = rng.uniform(0, 2 * math.pi, 3)
    H = (BUMP_AMP * np.sin(2 * math.pi * gx / BUMP_P1 + ph[0]) * np.sin(2 * math.pi * gy / BUMP_P1 + ph[1])
         + 0.5 * BUMP_AMP * np.sin(2 * math.pi * (gx + gy) / BUMP_P2 + ph[2])
         + rng.uniform(-NOISE, NOISE, gx.shape))
    H = on_grid(H)
    V = np.column_stack([gx.ravel(), gy.ravel(), H.ravel()])
    vid = np.arange((k + 1) ** 2).reshape(k + 1, k + 1)
    a, b = vid[:-1, :-1].ravel(), vid[1:, :-1].ravel()          # (i, j), (i+1, j)
    c, d = vid[1:, 1:].ravel(), vid[:-1, 1:].ravel()            # (i+1, j+1), (i, j+1)
    F = np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    return V, F.astype(np.int64), H, k


def terrain_height(H, k, x, y):
    """The terrain's (piecewise linear) height at x, y (clamped into the grid)."""
    x = np.clip(x, 0.0, k - 1e-9)
    y = np.clip(y, 0.0, k - 1e-9)
    i, j = np.floor(x).astype(np.int64), np.floor(y).astype(np.int64)
    u, v = x - i, y - j
    h00, h10, h11, h01 = H[i, j], H[i + 1, j], H[i + 1, j + 1], H[i, j + 1]
    low = h00 + u * (h10 - h00) + v * (h11 - h10)               # triangle (a, b, c): u >= v
    up = h00 + v * (h01 - h00) + u * (h11 - h01)                # triangle (a, c, d): u < v
    return np.where(u >= v, low, up)


def slab(n, rng):
    """(centers, radii, grid): a 3-layer jittered lattice of balls with 10 % of the sites
    empty. grid = (C (k, k, L, 3), R (k, k, L), present (k, k, L)) for placing queries."""
    k = max(2, round(math.sqrt(n / (MOL_LAYERS * (1 - MOL_DROP)))))
    a = MOL_SPACING
    ii, jj, ll = np.meshgrid(np.arange(k), np.arange(k), np.arange(MOL_LAYERS), indexing="ij")
    ph = rng.uniform(0, 2 * math.pi, 2)
    lift = (MOL_BUMP * np.sin(2 * math.pi * ii * a / MOL_BUMP_P + ph[0])
            * np.sin(2 * math.pi * jj * a / MOL_BUMP_P + ph[1]))
    C = np.stack([ii * a, jj * a, ll * a + lift], axis=-1)
    C = on_grid(C + rng.uniform(-MOL_JITTER, MOL_JITTER, ii.shape + (3,)))
    R = on_grid(rng.uniform(*RADII, ii.shape))
    present = rng.random(ii.shape) >= MOL_DROP
    return C[present], R[present], (C, R, present, k)


# ---------------------------------------------------------------------------------------
# Query motions and placement


def rotation_matrices(q):
    """R(r) of formats.md for quaternions q (..., 4) = (w, x, y, z), any nonzero length."""
    w, v = q[..., 0], q[..., 1:]
    n2 = w * w + np.sum(v * v, axis=-1)
    vv = np.sum(v * v, axis=-1)
    R = (w * w - vv)[..., None, None] * np.eye(3) + 2 * v[..., :, None] * v[..., None, :]
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    cross = np.stack([np.stack([0 * x, -z, y], -1), np.stack([z, 0 * x, -x], -1),
                      np.stack([-y, x, 0 * x], -1)], -2)
    R = R + 2 * w[..., None, None] * cross
    return R / n2[..., None, None]


def polyval(coef, ts):
    """coef (N, c, d+1) ascending powers; ts (T,) -> (N, T, c)."""
    powers = ts[None, :] ** np.arange(coef.shape[-1])[:, None]      # (d+1, T)
    return np.einsum("ncd,dt->ntc", coef, powers)


def random_tau(N, rng):
    """tau(t) = tau0 + dtau t: tau0 in [-0.5, 0.5], dtau +-[0.5, 1]."""
    return rng.uniform(-0.5, 0.5, N), rng.uniform(0.5, 1.0, N) * rng.choice([-1.0, 1.0], N)


def axis_rotations(axis, tau0, dtau):
    """rot (N, 4, 2) of r(t) = (1, tau(t) axis)."""
    N = len(axis)
    return np.concatenate([np.column_stack([np.ones(N), np.zeros(N)])[:, None, :],
                           np.stack([axis * tau0[:, None], axis * dtau[:, None]], axis=-1)], axis=1)


def lever_arms(N, rng, scale):
    """The "axis" class's lever arms (N, 3) on the grid: length in scale["run"], within
    10 deg of horizontal, random azimuth."""
    length = rng.uniform(*scale["run"], N)
    az = rng.uniform(0, 2 * math.pi, N)
    el = np.radians(rng.uniform(-10.0, 10.0, N))
    return on_grid(length[:, None] * np.column_stack([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az),
                                                      np.sin(el)]))


def random_motions(motion, N, span, rng, scale):
    """trans (N, 3, dt+1), rot (N, 4, dr+1): coefficient arrays on the grid, z constant 0
    (it is set by the placement). span = ((xlo, xhi), (ylo, yhi)) for the start point."""
    (xlo, xhi), (ylo, yhi) = span
    p0 = np.column_stack([rng.uniform(xlo, xhi, N), rng.uniform(ylo, yhi, N), np.zeros(N)])
    if motion == "axis":
        # a swing about a fixed axis through the pivot p0: no run; the axis within 30 deg
        # of the vertical (uniform on the cap), either sense
        cz = rng.uniform(math.cos(math.radians(30.0)), 1.0, N)
        az = rng.uniform(0, 2 * math.pi, N)
        sz = np.sqrt(1.0 - cz * cz)
        axis = np.column_stack([sz * np.cos(az), sz * np.sin(az), cz]) * rng.choice([-1.0, 1.0], (N, 1))
        return on_grid(p0[:, :, None]), on_grid(axis_rotations(axis, *random_tau(N, rng)))
    ang = rng.uniform(0, 2 * math.pi, N)
    run = rng.uniform(*scale["run"], N)
    d = np.column_stack([run * np.cos(ang), run * np.sin(ang), -rng.uniform(*scale["drop"], N)])
    if motion == "poly":
        bend = rng.normal(0, scale["bend"] / math.sqrt(3), (N, 3))
        trans = np.stack([p0, d + bend, -bend], axis=-1)
        w = np.column_stack([np.ones(N), rng.uniform(-0.3, 0.3, (N, 2))])
        v = np.stack([rng.uniform(-0.5, 0.5, (N, 3)), rng.uniform(-0.8, 0.8, (N, 3)),
                      rng.uniform(-0.8, 0.8, (N, 3))], axis=-1)
        rot = np.concatenate([w[:, None, :], v], axis=1)
    else:
        trans = np.stack([p0, d], axis=-1)
        if motion == "rotation":
            axis = rng.normal(size=(N, 3))
            axis /= np.linalg.norm(axis, axis=1)[:, None]
            rot = axis_rotations(axis, *random_tau(N, rng))
        else:
            rot = np.concatenate([np.ones((N, 1, 1)), np.zeros((N, 3, 1))], axis=1)
    return on_grid(trans), on_grid(rot)


def positions(trans, rot, pts, ts):
    """Body points pts (N, P, 3) on the motions at times ts: (N, T, P, 3)."""
    R = rotation_matrices(polyval(rot, ts))                         # (N, T, 3, 3)
    return np.einsum("ntij,npj->ntpi", R, pts) + polyval(trans, ts)[:, :, None, :]


def mesh_clearances(trans, rot, tri, H, k):
    """Per query: (conservative clearance, the same at t = 0, sampled-point clearance) of a
    triangle above the terrain, min over time samples. Conservative: lowest vertex z minus
    the highest terrain vertex of the cells under the triangle's xy box (> 0 at every
    sample: no contact there).
    Sampled: least z - terrain(x, y) over 15 points of the triangle (< 0: a point of the
    triangle below the terrain)."""
    ts = np.linspace(0.0, 1.0, MESH_SAMPLES_T)
    bary = np.array([(i, j, 4 - i - j) for i in range(5) for j in range(5 - i)], dtype=float) / 4
    pts = np.einsum("pv,nvc->npc", bary, tri)                       # (N, 15, 3), vertices included
    X = positions(trans, rot, pts, ts)                              # (N, T, 15, 3)
    h = terrain_height(H, k, X[..., 0], X[..., 1])
    sampled = np.min(X[..., 2] - h, axis=(1, 2))
    isv = np.max(bary, axis=1) == 1.0
    V = X[:, :, isv, :]                                             # (N, T, 3, 3)
    zmin = V[..., 2].min(axis=2)
    i0 = np.clip(np.floor(V[..., 0].min(axis=2)), 0, k).astype(np.int64)
    i1 = np.clip(np.ceil(V[..., 0].max(axis=2)), 0, k).astype(np.int64)
    j0 = np.clip(np.floor(V[..., 1].min(axis=2)), 0, k).astype(np.int64)
    j1 = np.clip(np.ceil(V[..., 1].max(axis=2)), 0, k).astype(np.int64)
    hmax = np.full(zmin.shape, -np.inf)
    for a in range(int((i1 - i0).max()) + 1):
        for b in range(int((j1 - j0).max()) + 1):
            ok = (i0 + a <= i1) & (j0 + b <= j1)
            hv = H[np.minimum(i0 + a, k), np.minimum(j0 + b, k)]
            hmax = np.where(ok, np.maximum(hmax, hv), hmax)
    return np.min(zmin - hmax, axis=1), zmin[:, 0] - hmax[:, 0], sampled


def mol_clearance(trans, rot, offs, rho, grid):
    """Per query: (least over time samples, at t = 0) vertical clearance of the ball centre
    above the upper envelope of the stored balls grown by the query's radius (top two layers,
    5 x 5 columns around it). > 0: apart at every sample; < 0: overlapping at some sample
    (when below an envelope point by less than that ball's height)."""
    C, R, present, k = grid
    ts = np.linspace(0.0, 1.0, MOL_SAMPLES_T)
    X = positions(trans, rot, offs[:, None, :], ts)[:, :, 0, :]    # (N, T, 3)
    ci = np.rint(X[..., 0] / MOL_SPACING).astype(np.int64)
    cj = np.rint(X[..., 1] / MOL_SPACING).astype(np.int64)
    best = np.full(X.shape[:2], np.inf)
    for a in range(-2, 3):
        for b in range(-2, 3):
            ii, jj = ci + a, cj + b
            inside = (ii >= 0) & (ii < k) & (jj >= 0) & (jj < k)
            ii, jj = np.clip(ii, 0, k - 1), np.clip(jj, 0, k - 1)
            for layer in range(MOL_LAYERS - 2, MOL_LAYERS):
                c = C[ii, jj, layer]                                 # (N, T, 3)
                rr = R[ii, jj, layer] + rho[:, None]
                hor2 = (X[..., 0] - c[..., 0]) ** 2 + (X[..., 1] - c[..., 1]) ** 2
                ok = inside & present[ii, jj, layer] & (hor2 < rr * rr)
                top = c[..., 2] + np.sqrt(np.maximum(rr * rr - hor2, 0.0))
                best = np.where(ok, np.minimum(best, X[..., 2] - top), best)
    return best.min(axis=1), best[:, 0]


def make_queries(polyccd, cls, motion, n, seed, stored):
    """n query Body objects and a description of each (for the dump of a failing case)."""
    rng = rng_for(seed, cls, motion, n, 1)
    scale = SCALE[cls]
    width = stored["width"]
    margin = min(scale["run"][1] + 2 * scale["bend"] + 1.0, width / 3)
    span = ((margin, width - margin), (margin, width - margin))
    hit = rng.random(n) < HIT_FRACTION
    target = np.where(hit, rng.uniform(*scale["hit"], n), rng.uniform(*scale["miss"], n))
    bodies, raw = [], []
    for s in range(0, n, CHUNK):
        N = min(CHUNK, n - s)
        trans, rot = random_motions(motion, N, span, rng, scale)
        if cls == "mesh":
            dirs = rng.normal(size=(N, 3, 3))
            dirs /= np.linalg.norm(dirs, axis=2)[..., None]
            tri = dirs * rng.uniform(0.4, 0.8, (N, 3, 1))
            tri = on_grid(tri - tri.mean(axis=1)[:, None, :])
            if motion == "axis":
                tri = tri + lever_arms(N, rng, scale)[:, None, :]      # exact: both on the grid
            cons, cons0, sampled = mesh_clearances(trans, rot, tri, stored["H"], stored["k"])
            gap, gap0 = np.where(hit[s:s + N], sampled, cons), cons0
        else:
            if motion == "axis":
                offs = lever_arms(N, rng, scale)
            else:
                dirs = rng.normal(size=(N, 3))
                dirs /= np.linalg.norm(dirs, axis=1)[:, None]
                offs = on_grid(dirs * rng.uniform(0.0, 1.5, (N, 1)))
            rho = on_grid(rng.uniform(*RADII, N))
            gap, gap0 = mol_clearance(trans, rot, offs, rho, stored["grid"])
            gap = np.where(np.isfinite(gap), gap, 0.0)               # no ball under the path at all
        # misses: the least clearance becomes the target; hits: the deepest sampled point
        # goes the target below the surface, but the query starts clear of it (>= "start")
        # when that is possible (else it is a near miss or a hit found by the library)
        shift = target[s:s + N] - gap
        shift = np.where(hit[s:s + N] & np.isfinite(gap0), np.maximum(shift, scale["start"] - gap0), shift)
        trans[:, 2, 0] = on_grid(trans[:, 2, 0] + shift)
        for q in range(N):
            tr = [[float(c) for c in row] for row in trans[q]]
            ro = [[float(c) for c in row] for row in rot[q]]
            m = polyccd.Motion(translation=tr, rotation=ro)
            if cls == "mesh":
                shape = polyccd.Mesh(tri[q], [[0, 1, 2]])
                raw.append({"mesh": {"vertices": tri[q].tolist(), "triangles": [[0, 1, 2]]},
                            "motion": {"translation": tr, "rotation": ro}})
            else:
                shape = polyccd.Spheres(offs[q][None, :], rho[q:q + 1])
                raw.append({"spheres": {"centers": [offs[q].tolist()], "radii": [float(rho[q])]},
                            "motion": {"translation": tr, "rotation": ro}})
            bodies.append(polyccd.Body(shape, m, name=f"q{s + q}"))
    return bodies, raw


def make_stored(polyccd, cls, n, seed):
    rng = rng_for(seed, cls, MOTIONS[0], n, 0)          # the stored body does not depend on the motion class
    if cls == "mesh":
        V, F, H, k = terrain(n, rng)
        return {"V": V, "F": F, "H": H, "k": k, "width": float(k), "n": len(F),
                "make": lambda: polyccd.Mesh(V, F),
                "raw": lambda: {"mesh": {"vertices": V.tolist(), "triangles": F.tolist()}},
                "text": f"terrain {k} x {k} cells, {len(F)} triangles, heights in "
                        f"[{H.min():.2f}, {H.max():.2f}]"}
    C, R, grid = slab(n, rng)
    k = grid[3]
    return {"C": C, "R": R, "grid": grid, "width": (k - 1) * MOL_SPACING, "n": len(C),
            "make": lambda: polyccd.Spheres(C, R),
            "raw": lambda: {"spheres": {"centers": C.tolist(), "radii": R.tolist()}},
            "text": f"slab {k} x {k} x {MOL_LAYERS} sites (spacing {MOL_SPACING} A), {len(C)} balls"}
