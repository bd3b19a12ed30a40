"""Deliberately degenerate query constructions (see tests/oracle/oracle_gen.py for helpers).

degenerate_query(rng, kind) picks one construction of that kind at random. Most build
the configuration in simple coordinates (a plane z = 0, a line, a fixed direction) and
then apply one random invertible integer affine map plus a polynomial translation to
every point (oracle_gen.affine), which keeps the degeneracy exact but hides it.
"""
from fractions import Fraction as F

from oracle_gen import (PYTH, affine, combo, irrational_factor, perturb, planted, pmul,
                        ratio, rdeg, rescale, rnum, rpoly, rtime, rtraj, rweights, tadd,
                        tat, tconst, tscale, tsub)


def flat(rng, deg=None):
    """A random trajectory in the plane z = 0."""
    p = rtraj(rng, deg)
    return [p[0], p[1], [F(0)]]


def on_line(rng, o, d, deg=None):
    """o(t) + s(t) d(t) for a random polynomial s."""
    return tadd(o, tscale(d, rpoly(rng, rng.randint(0, deg or rdeg(rng)))))


def bump(t0, eps=F(0)):
    """(t - t0)^2 + eps: touches zero only at t0 (a double root), or never (eps > 0)."""
    return [t0 * t0 + eps, -2 * t0, F(1)]


def squared_irrational(rng):
    """g(t)^2 for a quadratic g with a root in (0, 1), usually irrational: a double
    root at an irrational time."""
    g = irrational_factor(rng)
    return pmul(g, g)


def tiny_ints(rng, kind, n):
    """Degree-1 trajectories with coefficients in {-1, 0, 1}: exact degeneracies galore."""
    pts = [[[F(rng.randint(-1, 1)), F(rng.randint(-1, 1))] for _ in range(3)]
           for _ in range(n)]
    radii = [F(1, 2), F(rng.randint(1, 2), 2)] if kind == "sphere-sphere" else None
    return kind, pts, radii, "degree 1, coefficients in {-1, 0, 1}"


def maybe_plant(rng, others, t0=None):
    """A random trajectory, which most of the time passes at t0 (default: random)
    through a random convex combination of the `others` trajectories."""
    v = rtraj(rng)
    if rng.random() < 0.4:
        return v
    t0 = rtime(rng) if t0 is None else t0
    return tadd(tsub(v, tconst(tat(v, t0))),
                tconst(tat(combo(others, rweights(rng, len(others))), t0)))


def at_end(rng, kind):
    t0 = rng.choice((F(0), F(1)))
    return planted(rng, kind, t0=t0)


# ---------------------------------------------------------------- vertex-face

def vf(rng):
    k = "vertex-face"
    c = rng.randrange(14)
    if c == 0:
        pts = [flat(rng) for _ in range(4)]
        return k, affine(rng, pts), None, "coplanar for all t: vertex moving in the face plane"
    if c == 1:
        t0 = rtime(rng)
        f = [flat(rng) for _ in range(3)]
        v = flat(rng)
        v = tadd(tsub(v, tconst(tat(v, t0))), tconst(tat(combo(f, rweights(rng, 3)), t0)))
        return (k, affine(rng, [v] + f), None,
                "coplanar for all t, vertex enters the face at t=%s" % t0)
    if c == 2:
        f0, f1 = rtraj(rng), rtraj(rng)
        lam = ratio(rng) if rng.random() < 0.7 else rpoly(rng, 1)
        f = [f0, f1, tadd(f0, tscale(tsub(f1, f0), lam))]
        return k, [maybe_plant(rng, f)] + f, None, "collinear triangle (f2 on line f0 f1)"
    if c == 3:
        f0 = rtraj(rng)
        f = [f0, f0, f0] if rng.random() < 0.3 else [f0, f0, rtraj(rng)]
        rng.shuffle(f)
        return k, [maybe_plant(rng, f)] + f, None, "coincident face vertices"
    if c == 4:
        f = [rtraj(rng) for _ in range(3)]
        i = rng.randrange(3)
        return k, [f[i]] + f, None, "vertex equal to face vertex %d for all t" % i
    if c in (5, 6):
        t0, w = rtime(rng), rweights(rng, 3)
        f = [flat(rng, rng.randint(0, 2)) for _ in range(3)]
        eps = perturb(rng) if c == 6 else F(0)
        v = tadd(combo(f, w), tscale(tconst((0, 0, rng.choice((1, -1, F(1, 3))))),
                                     bump(t0, eps)))
        what = "near miss by %s" % eps if eps else "grazing (double root) at t=%s" % t0
        return k, affine(rng, [v] + f), None, what + ", face plane z=0 before an affine map"
    if c == 7:
        return at_end(rng, k)
    if c == 9:
        t0 = rtime(rng)
        f0, f1 = rtraj(rng), rtraj(rng)
        f2 = tadd(tadd(f0, tscale(tsub(f1, f0), ratio(rng))),
                  tscale(rtraj(rng, 1), [-t0, F(1)]))
        f = [f0, f1, f2]
        rng.shuffle(f)
        return (k, [maybe_plant(rng, f, t0)] + f, None,
                "triangle collinear only at t=%s" % t0)
    if c == 10:
        f = [flat(rng, rng.randint(0, 2)) for _ in range(3)]
        v = tadd(combo(f, rweights(rng, 3)), tscale(tconst((0, 0, 1)), squared_irrational(rng)))
        return k, affine(rng, [v] + f), None, "grazing at an irrational double root"
    if c == 11:
        return rescale(rng, *planted(rng, k, irrational=rng.random() < 0.5))
    if c == 12:
        o, d = rtraj(rng, rng.randint(0, 2)), rtraj(rng, rng.randint(0, 1))
        return (k, [on_line(rng, o, d, 2) for _ in range(4)], None,
                "vertex and (collinear) face on one line for all t")
    if c == 13:
        f = [flat(rng) for _ in range(2)]
        f.append(tadd(f[0], tscale(tsub(f[1], f[0]), rpoly(rng, 1))))
        return (k, affine(rng, [flat(rng)] + f), None,
                "coplanar for all t, collinear face (f2 on line f0 f1)")
    return tiny_ints(rng, k, 4)


# ---------------------------------------------------------------- edge-edge

def ee(rng):
    k = "edge-edge"
    c = rng.randrange(14)
    if c == 0:
        a0, a1, b0 = rtraj(rng), rtraj(rng), rtraj(rng)
        b1 = tadd(b0, tscale(tsub(a1, a0), rnum(rng) or F(1)))
        return k, [a0, a1, b0, b1], None, "parallel edges for all t"
    if c == 1:
        o, d = rtraj(rng, rng.randint(0, 2)), rtraj(rng, rng.randint(0, 1))
        pts = [on_line(rng, o, d, 2) for _ in range(4)]
        return k, pts, None, "collinear for all t: edges sliding along one line"
    if c == 2:
        pts = [flat(rng) for _ in range(4)]
        return k, affine(rng, pts), None, "coplanar for all t"
    if c == 3:
        kind, pts, _, label = planted(rng, k)
        x = rng.random()
        if x < 0.7:
            pts[1] = pts[0]
        if x > 0.4:
            pts[3] = pts[2]
        return k, pts, None, "zero-length edge(s), " + label
    if c == 4:
        pts = [rtraj(rng) for _ in range(4)]
        i, j = rng.choice((0, 1)), rng.choice((2, 3))
        pts[j] = pts[i]
        return k, pts, None, "edges sharing an endpoint for all t"
    if c in (5, 6):
        t0 = rtime(rng)
        eps = perturb(rng) if c == 6 else F(0)
        x0 = rng.choice((F(-1), F(1), F(0), F(1, 2), F(-1, 3)))
        h = tscale(tconst((0, 0, 1)), bump(t0, eps))
        pts = [tconst((-1, 0, 0)), tconst((1, 0, 0)),
               tadd(tconst((x0, -1, 0)), h), tadd(tconst((x0, rng.choice((1, 0)), 0)), h)]
        if rng.random() < 0.3:             # A stretches along its own line too
            pts[:2] = [tadd(p, tscale(tconst((1, 0, 0)), [F(0), rnum(rng)])) for p in pts[:2]]
        what = "near miss by %s" % eps if eps else "grazing crossing (double root) at t=%s" % t0
        return k, affine(rng, pts), None, what
    if c == 7:
        t0 = rtime(rng)
        a0, a1, n = rtraj(rng), rtraj(rng), rtraj(rng, 1)
        s = rng.choice((F(0), F(1, 2), F(1), F(-1), F(3, 2), F(2)))
        off = tadd(tscale(tsub(a1, a0), s), tscale(n, [-t0, F(1)]))
        return (k, [a0, a1, tadd(a0, off), tadd(a1, off)], None,
                "parallel, collinear at t=%s with shift %s" % (t0, s))
    if c == 8:
        return at_end(rng, k)
    if c == 10:
        t0 = rtime(rng)
        a0, a1 = rtraj(rng), rtraj(rng)
        s = rng.choice((F(0), F(1, 2), F(1), F(3, 2), F(-1, 2)))
        # b0(t0) on line A at parameter s; db = da + (t - t0) X: parallel only at t0
        b0 = tadd(tadd(a0, tscale(tsub(a1, a0), s)), tscale(rtraj(rng, 1), [-t0, F(1)]))
        b1 = tadd(b0, tadd(tsub(a1, a0), tscale(rtraj(rng, 1), [-t0, F(1)])))
        return k, [a0, a1, b0, b1], None, "parallel only at t=%s, shift %s" % (t0, s)
    if c == 11:
        h = tscale(tconst((0, 0, 1)), squared_irrational(rng))
        x0 = rng.choice((F(-1), F(1), F(0), F(1, 3)))
        pts = [tconst((-1, 0, 0)), tconst((1, 0, 0)),
               tadd(tconst((x0, -1, 0)), h), tadd(tconst((x0, 1, 0)), h)]
        return k, affine(rng, pts), None, "grazing crossing at an irrational double root"
    if c == 12:
        return rescale(rng, *planted(rng, k, irrational=rng.random() < 0.5))
    if c == 13:
        pts = [flat(rng) for _ in range(3)]
        return (k, affine(rng, pts[:2] + [pts[2], pts[2]]), None,
                "coplanar for all t, edge B of zero length")
    return tiny_ints(rng, k, 4)


# ---------------------------------------------------------------- vertex-edge

def ve(rng):
    k = "vertex-edge"
    c = rng.randrange(10)
    if c == 0:
        o, d = rtraj(rng, rng.randint(0, 2)), rtraj(rng, rng.randint(0, 1))
        return k, [on_line(rng, o, d, 2) for _ in range(3)], None, "collinear for all t"
    if c == 1:
        e0 = rtraj(rng)
        return k, [maybe_plant(rng, [e0]), e0, e0], None, "zero-length edge"
    if c == 2:
        e0, e1 = rtraj(rng), rtraj(rng)
        return k, [rng.choice((e0, e1)), e0, e1], None, "vertex equal to an endpoint"
    if c in (3, 4):
        t0, w = rtime(rng), rweights(rng, 2)
        e = [rtraj(rng), rtraj(rng)]
        eps = perturb(rng) if c == 4 else F(0)
        v = tadd(combo(e, w), tscale(rtraj(rng, 1), bump(t0, eps)))
        what = "near miss by ~%s" % eps if eps else "grazing (double root) at t=%s" % t0
        return k, [v] + e, None, what
    if c == 5:
        return at_end(rng, k)
    if c == 6:
        kind, pts, radii, label = planted(rng, k)
        pts[0] = tadd(pts[0], tconst((0, 0, perturb(rng))))
        return k, pts, None, label + ", vertex lifted by a tiny z offset"
    if c == 8:
        e = [rtraj(rng), rtraj(rng)]
        v = tadd(combo(e, rweights(rng, 2)), tscale(rtraj(rng, 1), squared_irrational(rng)))
        return k, [v] + e, None, "grazing at an irrational double root"
    if c == 9:
        return rescale(rng, *planted(rng, k, irrational=rng.random() < 0.5))
    return tiny_ints(rng, k, 3)


# ---------------------------------------------------------------- vertex-vertex

def vv(rng):
    k = "vertex-vertex"
    c = rng.randrange(8)
    a, t0, d = rtraj(rng), rtime(rng), rtraj(rng, rng.randint(0, 2))
    if c == 0:
        return k, [a, a], None, "coincident for all t"
    if c == 1:
        return k, [a, tadd(a, tscale(d, bump(t0)))], None, "meet at t=%s, double root" % t0
    if c == 2:
        return k, [a, tadd(a, tscale(d, [-t0, F(1)]))], None, "cross at t=%s" % t0
    if c == 3:
        e = perturb(rng)
        b = tadd(tadd(a, tscale(tconst((1, 0, 0)), [-t0, F(1)])), tconst((0, e, 0)))
        return k, [a, b], None, "near miss by %s" % e
    if c == 4:
        return at_end(rng, k)
    if c == 5:
        return k, [a, tadd(a, tconst((0, 0, rnum(rng) or 1)))], None, "constant offset"
    if c == 7:
        return rescale(rng, *planted(rng, k, irrational=rng.random() < 0.5))
    return tiny_ints(rng, k, 2)


# ---------------------------------------------------------------- sphere-sphere

def ss(rng):
    k = "sphere-sphere"
    c = rng.randrange(10)
    ca, t0 = rtraj(rng), rtime(rng)
    ra, rb = F(rng.randint(1, 5), rng.choice((1, 2, 3))), F(rng.randint(1, 5), 2)
    (u, L), R = rng.choice(PYTH), ra + rb
    w = tconst((u[1], -u[0], 0) if u[:2] != (0, 0) else (1, 0, 0))   # w . u == 0
    if c in (0, 1):
        eps = perturb(rng) if c == 1 else F(0)
        cb = tadd(tadd(ca, tconst([(R + eps) / L * x for x in u])), tscale(w, bump(t0)))
        what = "near miss by %s" % eps if eps else "touching at t=%s only (grazing)" % t0
        return k, [ca, cb], [ra, rb], what
    if c == 2:
        return k, [ca, tadd(ca, tconst([R / L * x for x in u]))], [ra, rb], "touching for all t"
    if c == 3:
        return k, [ca, ca], [ra, rb], "same centre for all t"
    if c == 4:
        sgn = rng.choice((1, -1))
        cb = tadd(ca, tscale(tconst([R / L * x for x in u]), [1 + sgn * t0, F(-sgn)]))
        return k, [ca, cb], [ra, rb], "crossing |d| = ra + rb at t=%s" % t0
    if c == 5:
        tiny = F(1, 10 ** rng.choice((10, 30)))
        cb = tadd(ca, tscale(tconst(u), [-t0 * L, F(L)]))
        return k, [ca, cb], [tiny, tiny], "tiny radii %s, centres meet at t=%s" % (tiny, t0)
    if c == 6:
        return at_end(rng, k)
    if c == 8:
        cb = tadd(tadd(ca, tconst([R / L * x for x in u])), tscale(w, squared_irrational(rng)))
        return k, [ca, cb], [ra, rb], "touching only at an irrational time (grazing)"
    if c == 9:
        return rescale(rng, *planted(rng, k, irrational=rng.random() < 0.5))
    return tiny_ints(rng, k, 2)


DEGENERATE = {"vertex-face": vf, "edge-edge": ee, "vertex-edge": ve, "vertex-vertex": vv,
              "sphere-sphere": ss}


def degenerate_query(rng, kind):
    return DEGENERATE[kind](rng)
