"""Exact distances between closed primitives, in Fractions (the oracle of minimum
separation queries, tests/test_min_distance.py). Written from the textbook closest-point
constructions (convex minimization over each primitive's parameter domain), not from
polyccd's feature systems: the squared distance of two closed convex polytopes with
rational vertices is rational, and each function below computes it exactly.
"""
from fractions import Fraction as F


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def clamp01(x):
    return F(0) if x < 0 else F(1) if x > 1 else x


def point_point(p, q):
    d = sub(p, q)
    return dot(d, d)


def point_segment(p, a, b):
    """min over s in [0, 1] of |p - (a + s (b - a))|^2: the unconstrained minimizer
    clamped (a convex quadratic in one variable)."""
    e = sub(b, a)
    ee = dot(e, e)
    if ee == 0:
        return point_point(p, a)
    s = clamp01(F(dot(sub(p, a), e)) / ee)
    return point_point(p, [x + s * y for x, y in zip(a, e)])


def point_triangle(p, a, b, c):
    """The plane distance when the projection is in the closed triangle, else the
    nearest of the three sides (a degenerate triangle is its sides)."""
    n = cross(sub(b, a), sub(c, a))
    nn = dot(n, n)
    sides = min(point_segment(p, a, b), point_segment(p, b, c), point_segment(p, c, a))
    if nn == 0:
        return sides
    inside = all(dot(n, cross(sub(v1, v0), sub(p, v0))) >= 0
                 for v0, v1 in ((a, b), (b, c), (c, a)))
    if not inside:
        return sides
    h = dot(n, sub(p, a))
    return F(h * h) / nn


def segment_segment(p, q, a, b):
    """min over (s, u) in [0, 1]^2 of |p + s (q - p) - a - u (b - a)|^2: the critical
    point of the convex quadratic when it lies in the square, else the minimum over the
    square's sides, which are point-segment distances."""
    sides = min(point_segment(p, a, b), point_segment(q, a, b),
                point_segment(a, p, q), point_segment(b, p, q))
    d1, d2, r = sub(q, p), sub(b, a), sub(p, a)
    A, E, B = dot(d1, d1), dot(d2, d2), dot(d1, d2)
    C, Fv = dot(d1, r), dot(d2, r)
    den = A * E - B * B
    if den == 0:
        return sides
    s = F(B * Fv - C * E, den)
    u = F(A * Fv - B * C, den)
    if 0 <= s <= 1 and 0 <= u <= 1:
        x = [pi + s * di for pi, di in zip(p, d1)]
        y = [ai + u * di for ai, di in zip(a, d2)]
        return min(sides, point_point(x, y))
    return sides


def at(traj, t):
    """The position of a point trajectory [xs, ys, zs] (ascending coefficients) at t."""
    return [sum(F(c) * t ** i for i, c in enumerate(axis)) for axis in traj]


def distance2(kind, points, t):
    """The squared distance of the closed primitives of a query at time t."""
    x = [at(p, t) for p in points]
    if kind == "vertex-vertex":
        return point_point(x[0], x[1])
    if kind == "vertex-edge":
        return point_segment(x[0], x[1], x[2])
    if kind == "vertex-face":
        return point_triangle(x[0], x[1], x[2], x[3])
    if kind == "edge-edge":
        return segment_segment(x[0], x[1], x[2], x[3])
    raise ValueError(kind)
