"""Query generators shared by tests/test_property.py and tests/tools/make_corpus.py.

Every generator takes a random.Random and returns (kind, points, radii, label): points
in the polyccd-query/1 layout with Fraction coefficients, radii None except for spheres,
label a short text saying how the query was built (printed on failure).

Coordinates are small integers and simple fractions on purpose, so that the
degeneracies the constructions aim at (coplanar or collinear for all t, parallel edges,
coincident points, contact exactly at t = 0 or 1, double roots) happen EXACTLY.
"""
from fractions import Fraction as F

NPTS = {"vertex-face": 4, "edge-edge": 4, "vertex-edge": 3, "vertex-vertex": 2,
        "sphere-sphere": 2}
# Integer vectors of rational length (Pythagorean quadruples): exact touching balls.
PYTH = [((3, 4, 0), 5), ((2, 3, 6), 7), ((1, 4, 8), 9), ((2, 6, 9), 11), ((0, 0, 1), 1),
        ((4, 4, 7), 9), ((1, 2, 2), 3), ((6, 6, 7), 11)]


# ---------------------------------------------------------------- polynomial helpers

def trim(c):
    c = list(c)
    while len(c) > 1 and c[-1] == 0:
        c.pop()
    return c


def padd(a, b):
    n = max(len(a), len(b))
    return trim([(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)])


def pscale(a, k):
    return trim([k * x for x in a])


def pmul(a, b):
    out = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return trim(out)


def pstr(a):
    """Readable text of a polynomial of t: 'c0 + c1 t + c2 t^2'."""
    terms = ["%s%s" % (c, "" if i == 0 else " t" if i == 1 else " t^%d" % i)
             for i, c in enumerate(a) if c != 0]
    return " + ".join(terms) or "0"


def peval(a, t):
    v = F(0)
    for c in reversed(a):
        v = v * t + c
    return v


def tadd(p, q):
    return [padd(a, b) for a, b in zip(p, q)]


def tsub(p, q):
    return [padd(a, pscale(b, -1)) for a, b in zip(p, q)]


def tscale(p, k):
    """Trajectory times a number or a polynomial of t (given as a list)."""
    if isinstance(k, list):
        return [pmul(a, k) for a in p]
    return [pscale(a, k) for a in p]


def tconst(v):
    return [[F(x)] for x in v]


def tat(p, t):
    return [peval(a, t) for a in p]


def combo(trajs, weights):
    out = tconst((0, 0, 0))
    for p, w in zip(trajs, weights):
        out = tadd(out, tscale(p, w))
    return out


# ---------------------------------------------------------------- random pieces

def rnum(rng, big=4, wild=False):
    """A small exact number: mostly integers, sometimes halves, thirds, quarters; or
    (wild) a fraction of two random 18-digit integers."""
    if wild:
        return F(rng.randint(-10 ** 18, 10 ** 18), rng.randint(1, 10 ** 18))
    n = rng.randint(-big, big)
    return F(n, rng.choice((1, 1, 1, 2, 3, 4)))


def rdeg(rng):
    """Trajectory degree: 1..3 mostly, sometimes 4..6."""
    return rng.choice((1, 1, 2, 2, 3)) if rng.random() < 0.9 else rng.randint(4, 6)


def rpoly(rng, deg, big=4, wild=False):
    return trim([rnum(rng, big, wild) for _ in range(deg + 1)])


def rtraj(rng, deg=None, big=4, wild=False):
    deg = rdeg(rng) if deg is None else deg
    return [rpoly(rng, rng.randint(0, deg) if rng.random() < 0.3 else deg, big, wild)
            for _ in range(3)]


def rtime(rng):
    """A planted contact time: often 0 or 1, else a simple fraction in (0, 1)."""
    x = rng.random()
    if x < 0.12:
        return F(0)
    if x < 0.24:
        return F(1)
    d = rng.choice((2, 3, 4, 5, 7, 8, 10))
    return F(rng.randint(1, d - 1), d)


def rweights(rng, n):
    """Convex weights (sum 1, >= 0), often with zeros (edge / vertex contacts)."""
    while True:
        w = [F(rng.randint(0, 3)) for _ in range(n)]
        if rng.random() < 0.4:
            w[rng.randrange(n)] = F(0)
        if sum(w):
            s = sum(w)
            return [x / s for x in w]


def ratio(rng):
    """A collinearity factor: inside [0, 1] or outside it."""
    return rng.choice((F(0), F(1), F(1, 2), F(1, 3), F(2), F(-1), F(3, 2), F(-1, 2)))


def affine(rng, points, linear=True):
    """Same invertible integer affine map (+ polynomial translation) on every point:
    preserves every incidence, collinearity and coplanarity exactly."""
    if linear:
        while True:
            m = [[rng.randint(-2, 2) for _ in range(3)] for _ in range(3)]
            det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                   - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                   + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
            if det:
                break
        points = [[trim(padd(padd(pscale(p[0], m[r][0]), pscale(p[1], m[r][1])),
                             pscale(p[2], m[r][2]))) for r in range(3)] for p in points]
    b = rtraj(rng, rng.randint(0, 2), 2)
    return [tadd(p, b) for p in points]


def perturb(rng):
    """A tiny exact offset: 10^-k."""
    return F(1, 10 ** rng.choice((6, 12, 20, 30)))


# ---------------------------------------------------------------- planted contacts

def irrational_factor(rng):
    """A quadratic g(t) with a root in (0, 1), usually irrational: t^2 + b t - c."""
    while True:
        b = rng.choice((F(0), F(0), F(1), F(-1, 2), F(1, 2)))
        c = F(rng.randint(1, 9), rng.choice((2, 3, 5, 7, 10)))
        g = [-c, b, F(1)]
        if peval(g, 0) * peval(g, 1) < 0:
            return g


def planted(rng, kind, t0=None, irrational=False, deg=None, wild=False):
    """Random trajectories (degree `deg`, default random; `wild` numbers, see rnum)
    with a contact planted at t0 (or at a root of a quadratic). The first contact may
    still come earlier: the oracle decides."""
    n = NPTS[kind]
    pts = [rtraj(rng, deg, wild=wild) for _ in range(n)]
    t0 = rtime(rng) if t0 is None else t0
    if irrational:
        g = irrational_factor(rng)
        # moving part = target(t) + g(t) D(t): on target exactly where g(t) == 0
        off = tscale(rtraj(rng, rng.randint(0, 2)), g)
        label = "planted contact at a root of %s" % pstr(g)
    else:
        label = "planted contact at t=%s" % (t0,)
    if kind == "sphere-sphere":
        ra, rb = F(rng.randint(1, 6), rng.choice((1, 2, 4))), F(rng.randint(1, 6), 2)
        (u, L) = rng.choice(PYTH)
        k = (ra + rb) / L * rng.choice((F(1), F(1), F(1, 2), F(0)))
        base = tconst([k * x for x in u])
        if irrational:
            pts[1] = tadd(tadd(pts[0], base), off)
        else:   # cb(t0) - ca(t0) = base, |base| <= ra + rb
            pts[1] = tadd(tsub(pts[1], tconst(tat(pts[1], t0))),
                          tadd(tconst(tat(pts[0], t0)), base))
        return kind, pts, [ra, rb], label
    if kind == "edge-edge":
        s, u = rweights(rng, 2), rweights(rng, 2)
        gap = tsub(combo(pts[0:2], s), combo(pts[2:4], u))
        if not irrational:
            gap = tconst(tat(gap, t0))
        else:
            gap = tadd(gap, off)
        pts[2], pts[3] = tadd(pts[2], gap), tadd(pts[3], gap)
        return kind, pts, None, label
    # vertex-face, vertex-edge, vertex-vertex: point 0 against the rest
    target = combo(pts[1:], rweights(rng, n - 1))
    if irrational:
        pts[0] = tadd(target, off)
    else:
        pts[0] = tadd(tsub(pts[0], tconst(tat(pts[0], t0))), tconst(tat(target, t0)))
    return kind, pts, None, label


def free(rng, kind):
    pts = [rtraj(rng) for _ in range(NPTS[kind])]
    radii = None
    if kind == "sphere-sphere":
        radii = [F(rng.randint(1, 8), rng.choice((1, 2, 3))) for _ in range(2)]
    return kind, pts, radii, "free random trajectories"


def random_query(rng, kind):
    """The 'random' mix of the property test: free, planted rational, planted
    irrational (some rescaled), and planted then moved off by a tiny exact offset."""
    x = rng.random()
    if x < 0.07:
        return rescale(rng, *planted(rng, kind, irrational=x < 0.03))
    if x < 0.35:
        return free(rng, kind)
    if x < 0.7:
        return planted(rng, kind)
    if x < 0.9:
        return planted(rng, kind, irrational=True)
    k, pts, radii, label = planted(rng, kind)
    eps = perturb(rng)
    i = rng.randrange(len(pts))
    pts[i] = tadd(pts[i], tconst([eps * rng.randint(-1, 1) for _ in range(3)]))
    return k, pts, radii, label + ", point %d moved by multiples of %s" % (i, eps)


def rescale(rng, kind, pts, radii, label):
    """Same contacts at other magnitudes: every coordinate (and radius) times 10^k,
    plus sometimes a huge common translation (vertices, edges, faces only)."""
    k = rng.choice((-30, -12, 12, 30))
    s = F(10) ** k
    pts = [tscale(p, s) for p in pts]
    radii = [r * s for r in radii] if radii else radii
    label += ", scaled by 1e%d" % k
    if kind != "sphere-sphere" and rng.random() < 0.5:
        shift = tconst([F(rng.randint(-9, 9)) * 10 ** rng.choice((15, 40)) for _ in range(3)])
        pts = [tadd(p, shift) for p in pts]
        label += ", translated by %s" % ([str(x[0]) for x in shift],)
    return kind, pts, radii, label


def heavy_query(rng, kind):
    """Planted contacts with trajectories of degree 7..12 or 18-digit fractions: slow
    for the engine (seconds to minutes per query), so only run on request."""
    irrational = rng.random() < 0.5
    if rng.random() < 0.5:
        deg = rng.randint(7, 12)
        k, pts, radii, label = planted(rng, kind, irrational=irrational, deg=deg)
        return k, pts, radii, label + ", degree %d" % deg
    k, pts, radii, label = planted(rng, kind, irrational=irrational, wild=True)
    return k, pts, radii, label + ", 18-digit fractions"
