"""A second, pointwise contact test used only to check the oracle (and its generators):
at a RATIONAL time t, decide contact with plain Fractions by a formulation unrelated to
tests/oracle/oracle_pred.py.

Every kind except spheres is "does the origin lie in the convex hull of finitely many
points?": vertex-face 0 in conv{f_i - v}, vertex-edge 0 in conv{e_i - v}, vertex-vertex
0 in conv{b - a}, edge-edge 0 in conv{a_i - b_j} (the Minkowski difference of two
segments). By Caratheodory, x lies in conv(P) iff x is a convex combination of an
affinely independent subset S of P; for such an S the affine coordinates are unique and
come from a Gram system, so trying every subset decides membership exactly, whatever the
degeneracy of P (repeated points, collinear points, ...).
"""
from fractions import Fraction
from itertools import combinations


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _solve(G, rhs):
    """Exact Gauss-Jordan; None when G is singular."""
    n = len(G)
    M = [list(row) + [r] for row, r in zip(G, rhs)]
    for c in range(n):
        p = next((r for r in range(c, n) if M[r][c] != 0), None)
        if p is None:
            return None
        M[c], M[p] = M[p], M[c]
        for r in range(n):
            if r != c and M[r][c] != 0:
                f = M[r][c] / M[c][c]
                M[r] = [x - f * y for x, y in zip(M[r], M[c])]
    return [M[i][n] / M[i][i] for i in range(n)]


def in_hull(points, x):
    """Exactly: x in the convex hull of `points` (3-vectors of Fractions)."""
    pts = list(dict.fromkeys(tuple(p) for p in points))     # duplicates add nothing
    x = tuple(x)
    for k in range(1, min(4, len(pts)) + 1):
        for S in combinations(pts, k):
            p0 = S[0]
            D = [tuple(a - b for a, b in zip(p, p0)) for p in S[1:]]
            y = tuple(a - b for a, b in zip(x, p0))
            if not D:
                if y == (0, 0, 0):
                    return True
                continue
            mu = _solve([[_dot(a, b) for b in D] for a in D], [_dot(a, y) for a in D])
            if mu is None:
                continue                    # affinely dependent subset: skip
            if min(mu) < 0 or sum(mu) > 1:
                continue
            z = tuple(sum(m * d[i] for m, d in zip(mu, D)) for i in range(3))
            if z == y:
                return True
    return False


def _at(traj, t):
    out = []
    for coeffs in traj:
        v = Fraction(0)
        for c in reversed(coeffs):
            v = v * t + Fraction(c)
        out.append(v)
    return out


def contact_at_rational(kind, points, radii, t):
    P = [_at(p, Fraction(t)) for p in points]
    sub = lambda a, b: [x - y for x, y in zip(a, b)]        # noqa: E731
    origin = (0, 0, 0)
    if kind == "vertex-face":
        return in_hull([sub(f, P[0]) for f in P[1:]], origin)
    if kind == "vertex-edge":
        return in_hull([sub(e, P[0]) for e in P[1:]], origin)
    if kind == "vertex-vertex":
        return in_hull([sub(P[1], P[0])], origin)
    if kind == "edge-edge":
        return in_hull([sub(a, b) for a in P[0:2] for b in P[2:4]], origin)
    if kind == "sphere-sphere":
        d = sub(P[1], P[0])
        r = Fraction(radii[0]) + Fraction(radii[1])
        return _dot(d, d) <= r * r
    raise ValueError(kind)
