"""On-line adversarial families (issue 31): one stored body of about n triangles in a
polyccd.Index, queried by q one-triangle bodies on short motions, where bounding boxes
overlap widely and the stored elements differ by one or two parameters (their lifted
points, range/LINEARIZATION.md, lie on a curve or a sheet). Used by
tests/bench/bench_adversarial.py (per-query times against n) and tests/test_online_families.py
(every broad phase gives brute force's answer at small sizes).

make(polyccd, family, n, q, hit=False, seed=31) returns (stored Body, [q query Bodies]).
With hit=False no query touches the stored body on [0, 1] (why: per family below); with
hit=True each query's motion is changed so that many of them cross a stored element
(which ones touch is brute force's answer). Every coordinate is an integer or on the 2^-16
grid (exact doubles), so the inputs are what is described.

Families:
  tneedles  n translated copies of one long thin triangle: needle j has the corners
            j s, j s + h d, j s + e / 8 with d = (1, 1, 1), e = (1, -1, 0) (across),
            s = (1, 0, -1) (side by side), h = n + 8: every box meets every other. The
            needles lie on the parallel planes m . x = 3 j (m = d x e = (1, 1, -2), m . s = 3).
            Queries: triangles of radius <= 1/8 centred on the mid planes m . x = 3 j + 3/2,
            translated along e or d (m . x stays constant): each vertex stays at
            |m . x - (3 j + 3/2)| <= |m| / 8 < 3/2 from its mid plane, off every needle's
            plane. hit: the translation runs along d and also by 2 s (m . x grows by 6: it
            crosses two needles' planes over their strip).
  shells    k nested closed octahedra |x| + |y| + |z| = r_i, r_i = k (2 k + i), i < k, each
            face cut into a k x k grid (8 k^2 triangles per shell, n ~ 8 k^3, integer
            corners): scaled copies of a convex body around the origin, so disjoint, the
            shells k / sqrt(3) apart in distance while a triangle's box is about 2 k wide
            (boxes meet across several shells). Queries: triangles of radius <= k / 16
            centred on the mid surface r_i + k / 2 inside one face (barycentric weights
            >= 1/5), translated by at most k sqrt(2) / 16 within the face's plane: each
            vertex stays within 3 k / 20 of the mid surface's plane, less than the
            k / (2 sqrt 3) to either neighbouring shell's. hit: the translation also moves
            k along the face normal (through shell i + 1).
  turned    a x b blades: blade (j, l) is the thin triangle with (rho, z) corners
            (1, z_l), (8, z_l + H), (1, z_l + 1/4), z_l = l / 2, H = b / 2 + 4, in the
            vertical half-plane at angle 2 pi j / a (rotations of one blade about the z axis,
            stacked along it: lifted points on a sheet). Blades at one angle are
            translates 1/2 apart in z; at different angles they meet only on the axis,
            which they avoid (rho >= 1). Queries: triangles at angles between two blades,
            rho in [2, 7], rotating about the z axis (Motion.axis_rotation: range's exact
            rotation conditions) by at most a quarter of the angle step: each vertex keeps
            an angle at least a sixteenth of a step away from both neighbouring blades'
            half-planes. hit: the rotation turns by 3/2 of a step (it crosses a half-plane).
"""

import math

import numpy as np

FAMILIES = ("tneedles", "shells", "turned")


def _grid(x):
    """x rounded to the 2^-16 grid (exact doubles)."""
    return np.round(np.asarray(x, dtype=float) * 65536.0) / 65536.0


def _tri(polyccd, corners, motion, name):
    return polyccd.Body(polyccd.Mesh(_grid(corners), [[0, 1, 2]]), motion, name=name)


def _small_triangle(rng, radius):
    """Three corners within radius of the origin (a random orientation)."""
    d = rng.normal(size=(3, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    return d * rng.uniform(0.5, 1.0, (3, 1)) * radius


def tneedles(polyccd, n, q, hit, rng):
    d, e, s = np.array([1, 1, 1]), np.array([1, -1, 0]), np.array([1, 0, -1])
    h = n + 8
    V, F = [], []
    for j in range(n):
        V += [j * s, j * s + h * d, j * s + e / 8]
        F.append([3 * j, 3 * j + 1, 3 * j + 2])
    stored = polyccd.Body(polyccd.Mesh(np.array(V, dtype=float), F), name="needles")
    out = []
    for k in range(q):
        j = int(rng.integers(0, max(1, n - 1)))
        # centre on the mid plane m . x = 3 j + 3/2, over the needles' strip (e in [0, 1/8]):
        # grid multiples of the integer vectors d, e keep m . x exact
        c = (j + 0.5) * s + _grid(rng.uniform(0.25, 0.75) * h) * d + _grid(rng.uniform(0, 1 / 8)) * e
        along = d if (k % 2 or hit) else e
        move = along * float(_grid(rng.uniform(-2, 2)))
        if hit:
            move = move + 2 * s
        tri = c + _small_triangle(rng, 1 / 8)
        out.append(_tri(polyccd, tri, polyccd.Motion(translation=[[0.0, float(x)] for x in move]), f"q{k}"))
    return stored, out


def _octahedron(r, k):
    """The surface |x| + |y| + |z| = r, each face cut into k x k cells (2 triangles each):
    (vertices, triangles), faces outward by the right-hand rule."""
    V, F, index = [], [], {}

    def vid(p):
        key = tuple(p)
        if key not in index:
            index[key] = len(V)
            V.append(p)
        return index[key]

    step = r // k
    for sx in (1, -1):
        for sy in (1, -1):
            for sz in (1, -1):
                def P(a, b):
                    return (sx * a * step, sy * b * step, sz * (k - a - b) * step)
                flip = sx * sy * sz < 0
                for a in range(k):
                    for b in range(k - a):
                        tris = [(P(a, b), P(a + 1, b), P(a, b + 1))]
                        if a + b + 1 < k:
                            tris.append((P(a + 1, b), P(a + 1, b + 1), P(a, b + 1)))
                        for t in tris:
                            ids = [vid(p) for p in t]
                            F.append(ids[::-1] if flip else ids)
    return V, F


def shells(polyccd, n, q, hit, rng):
    k = max(2, round((n / 8) ** (1 / 3)))
    V, F = [], []
    for i in range(k):
        v, f = _octahedron(k * (2 * k + i), k)
        F += [[len(V) + x for x in t] for t in f]
        V += v
    stored = polyccd.Body(polyccd.Mesh(np.array(V, dtype=float), F), name="shells")
    out = []
    for j in range(q):
        i = int(rng.integers(0, k - 1))
        r = k * (2 * k + i) + k / 2                       # the mid surface
        sign = rng.choice([-1.0, 1.0], 3)
        w = rng.uniform(1.0, 2.0, 3)                       # barycentric weights >= 1/5
        w = w / w.sum()
        c = sign * _grid(w * r)
        c[2] = sign[2] * (r - abs(c[0]) - abs(c[1]))       # exactly on the mid surface
        # within the face's plane: sign . u = 0 exactly for u1, u2 (integer vectors)
        u1, u2 = sign * np.array([1, -1, 0]), sign * np.array([0, 1, -1])
        move = _grid(rng.uniform(-1, 1) * k / 32) * u1 + _grid(rng.uniform(-1, 1) * k / 32) * u2
        if hit:
            move = move + k * sign
        tri = c + _small_triangle(rng, k / 16)
        out.append(_tri(polyccd, tri, polyccd.Motion(translation=[[0.0, float(x)] for x in move]), f"q{j}"))
    return stored, out


def turned(polyccd, n, q, hit, rng):
    a = max(2, round(math.sqrt(2 * n)))
    b = max(1, n // a)
    H = b / 2 + 4
    V, F = [], []
    for j in range(a):
        c, s = math.cos(2 * math.pi * j / a), math.sin(2 * math.pi * j / a)
        p1, p8 = _grid([c, s]), _grid([8 * c, 8 * s])
        for l in range(b):
            z = l / 2
            V += [[p1[0], p1[1], z], [p8[0], p8[1], z + H], [p1[0], p1[1], z + 0.25]]
            F.append([len(V) - 3, len(V) - 2, len(V) - 1])
    stored = polyccd.Body(polyccd.Mesh(np.array(V, dtype=float), F), name="blades")
    step = 2 * math.pi / a
    out = []
    for k in range(q):
        ang = (int(rng.integers(0, a)) + 0.5) * step
        rho = rng.uniform(2, 7)
        z = rng.uniform(0, H + b / 2)
        c = np.array([rho * math.cos(ang), rho * math.sin(ang), z])
        # radius 1/8 of the arc to a blade at rho >= 2 (a sixteenth of the step in angle)
        tri = c + _small_triangle(rng, 2 * math.sin(step / 16))
        turn = (1.5 if hit else 0.25) * step * (1 if k % 2 else -1)
        m = polyccd.Motion.axis_rotation([0, 0, 1], [0, 0, 0], 0, float(_grid(math.tan(turn / 2))))
        out.append(_tri(polyccd, tri, m, f"q{k}"))
    return stored, out


def make(polyccd, family, n, q, hit=False, seed=31):
    """(stored Body of about n triangles, q query Bodies) of family (module docstring)."""
    rng = np.random.default_rng([seed, FAMILIES.index(family), n, q, int(hit)])
    return globals()[family](polyccd, n, q, hit, rng)
