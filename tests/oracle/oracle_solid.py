"""Solids for the tests, independent of polyccd: an exact point-in-solid test by ray
parity in Fractions, and the answer of a polyccd/1 scene with solid meshes ("solid":
true on a mesh body) built from the surface oracle (oracle_body.py).

Point in solid (winding number): the signed count of the triangles a ray from p
crosses, each +1 or -1 by the side the ray enters from. The ray's direction is taken
from a fixed list of rational directions; a ray that meets a triangle's edge or vertex,
or runs in a triangle's plane, is degenerate (decided exactly, in Fractions) and the
next direction is tried, so no perturbation enters (polyccd decides degenerate rays by
a symbolic perturbation instead: a different method). p on a triangle raises
OnSurface.

Scenes: a pair (i, j) with j solid is contained at t = 0 when some point of body i
(every vertex a triangle uses, or every ball centre) is strictly inside solid j at
t = 0 (world coordinates, oracle_body.world_at). Its first contact is then 0;
otherwise it is the surface oracle's (oracle_body.solve_scene).
"""
from fractions import Fraction
from itertools import product

import oracle_body


class OnSurface(Exception):
    pass


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


# Directions with unlike small primes: few meshes in tests are degenerate for several.
DIRECTIONS = [(Fraction(1), Fraction(1, 3), Fraction(1, 7))] + [
    (Fraction(a), Fraction(b, 11), Fraction(c, 13))
    for a, b, c in product((1, -1, 2), (5, -3, 7), (2, -9, 4))]


def _count(vertices, triangles, p, d):
    """The signed crossing count along direction d, or None when the ray is degenerate."""
    total = 0
    for t in triangles:
        a, b, c = (vertices[k] for k in t)
        e1, e2 = _sub(b, a), _sub(c, a)
        n = _cross(e1, e2)
        if n == (0, 0, 0):
            continue                 # a degenerate triangle: crossed only with its neighbours
        s = _sub(p, a)
        dn = _dot(d, n)
        if dn == 0:
            if _dot(s, n) == 0:
                return None          # the ray runs in the triangle's plane
            continue
        tt = -Fraction(_dot(s, n)) / dn              # p + tt d is in the plane
        x = tuple(p[k] + tt * d[k] for k in range(3))
        # barycentric signs by the areas of the sub-triangles against n
        w0 = _dot(_cross(_sub(b, x), _sub(c, x)), n)
        w1 = _dot(_cross(_sub(c, x), _sub(a, x)), n)
        w2 = _dot(_cross(_sub(a, x), _sub(b, x)), n)
        if w0 < 0 or w1 < 0 or w2 < 0:
            continue                 # the plane point is outside the closed triangle
        if tt == 0:
            raise OnSurface(p)
        if tt < 0:
            continue
        if w0 == 0 or w1 == 0 or w2 == 0:
            return None              # through an edge or a vertex
        total += 1 if dn > 0 else -1
    return total


def winding(vertices, triangles, p):
    """The winding number of the closed mesh about p (exact); OnSurface when p is on it."""
    for d in DIRECTIONS:
        w = _count(vertices, triangles, p, d)
        if w is not None:
            return w
    raise AssertionError("every test direction is degenerate for %r" % (p,))


def _points_at_zero(body):
    if body.kind == "mesh":
        return [oracle_body.world_at(body, body.vertices[k], 0) for k in body.used]
    return [oracle_body.world_at(body, c, 0) for c in body.centers]


def contained(solid, other):
    """Whether some point of `other` is strictly inside the solid mesh at t = 0."""
    verts = [oracle_body.world_at(solid, v, 0) for v in solid.vertices]
    for p in _points_at_zero(other):
        try:
            if winding(verts, solid.triangles, p) != 0:
                return True
        except OnSurface:
            pass                     # a surface contact at t = 0: the surface oracle's
    return False


class SolidAnswer:
    __slots__ = ("collides", "first", "pairs", "contained", "surface")


def solve(doc):
    """The answer of a polyccd/1 scene with solids: pairs {(i, j): first time},
    contained {(i, j)}: the pairs touching at t = 0 by containment, and the surface
    oracle's answer (surface)."""
    surface = oracle_body.solve_scene(doc)
    bodies = surface.bodies
    solid = [bool(b.get("solid", False)) and "mesh" in b for b in doc["bodies"]]
    ans = SolidAnswer()
    ans.surface, ans.contained, ans.pairs = surface, set(), {}
    for i in range(len(bodies)):
        for j in range(i + 1, len(bodies)):
            if ((solid[j] and contained(bodies[j], bodies[i]))
                    or (solid[i] and contained(bodies[i], bodies[j]))):
                ans.contained.add((i, j))
                ans.pairs[(i, j)] = Fraction(0)
            elif (i, j) in surface.pairs:
                ans.pairs[(i, j)] = surface.pairs[(i, j)].first
    ans.collides = bool(ans.pairs)
    ans.first = None
    if ans.contained:
        ans.first = Fraction(0)
    elif surface.collides:
        ans.first = surface.first
    return ans
