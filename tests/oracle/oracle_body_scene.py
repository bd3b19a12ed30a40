"""The scenes of the body oracle (oracle_body.py): rational functions of t (RF), exact
vector operations, and a polyccd/1 document read into bodies whose world positions
are exact rational functions of t (parse_scene, world_at). Independent of polyccd."""
from fractions import Fraction

from flint import fmpq_poly

from oracle import parse_number
from oracle_alg import irreducible_factors, roots_in_unit_interval, to_fmpq

F0, F1 = Fraction(0), Fraction(1)


# ---------------------------------------------------------------- rational functions

def _poly(coeffs):
    return fmpq_poly([to_fmpq(c) for c in coeffs])


ONE = _poly([1])


class RF:
    """num(t) / den(t) with fmpq_poly parts; den is a product of the W's (> 0)."""
    __slots__ = ("num", "den")

    def __init__(self, num, den=ONE):
        self.num, self.den = num, den

    def __add__(self, o):
        if self.den is o.den or self.den == o.den:
            return RF(self.num + o.num, self.den)
        return RF(self.num * o.den + o.num * self.den, self.den * o.den)

    def __sub__(self, o):
        if self.den is o.den or self.den == o.den:
            return RF(self.num - o.num, self.den)
        return RF(self.num * o.den - o.num * self.den, self.den * o.den)

    def __mul__(self, o):
        if isinstance(o, RF):
            return RF(self.num * o.num, self.den * o.den)
        return RF(self.num * to_fmpq(o), self.den)

    __rmul__ = __mul__

    def __neg__(self):
        return RF(-self.num, self.den)

    def is_zero(self):
        return self.num.degree() < 0


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


# ---------------------------------------------------------------- scenes

class Body:
    __slots__ = ("name", "kind", "vertices", "triangles", "edges", "used", "centers", "radii",
                 "translation", "rotation")


def _motion(obj, where):
    mo = obj.get("motion") or {}
    tr = mo.get("translation", [[0], [0], [0]])
    rot = mo.get("rotation", [[1], [0], [0], [0]])
    if len(tr) != 3 or len(rot) != 4:
        raise ValueError("%s.motion: 3 translation and 4 rotation polynomials" % where)
    tr = [_poly([parse_number(c) for c in comp]) for comp in tr]
    rot = [_poly([parse_number(c) for c in comp]) for comp in rot]
    g = rot[0]
    for p in rot[1:]:
        g = g.gcd(p) if g.degree() >= 0 else p
    if g.degree() < 0:
        raise ValueError("%s.motion.rotation: identically zero" % where)
    for key, f in irreducible_factors(g).items():
        if roots_in_unit_interval(key, f):
            raise ValueError("%s.motion.rotation: vanishes on [0, 1]" % where)
    return tr, rot


def mesh_edges(triangles):
    """Mesh.edges of docs/python.md: each side {a, b}, a != b, once as (a, b), a < b, sorted."""
    out = set()
    for tri in triangles:
        for u, w in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            if u != w:
                out.add((min(u, w), max(u, w)))
    return sorted(out)


def parse_scene(doc):
    if doc.get("format") != "polyccd/1":
        raise ValueError("not a polyccd/1 scene")
    bodies = []
    for i, b in enumerate(doc["bodies"]):
        body = Body()
        body.name = b.get("name", "body%d" % i)
        if "mesh" in b:
            body.kind = "mesh"
            body.vertices = [tuple(parse_number(c) for c in v) for v in b["mesh"]["vertices"]]
            body.triangles = [tuple(int(k) for k in t) for t in b["mesh"]["triangles"]]
            for t in body.triangles:
                if len(t) != 3 or not all(0 <= k < len(body.vertices) for k in t):
                    raise ValueError("bodies[%d]: bad triangle %r" % (i, t))
            body.edges = mesh_edges(body.triangles)
            body.used = sorted({k for t in body.triangles for k in t})
        else:
            body.kind = "spheres"
            body.centers = [tuple(parse_number(c) for c in v) for v in b["spheres"]["centers"]]
            body.radii = [parse_number(r) for r in b["spheres"]["radii"]]
            if len(body.radii) != len(body.centers) or min(body.radii) <= 0:
                raise ValueError("bodies[%d]: bad spheres" % i)
        body.translation, body.rotation = _motion(b, "bodies[%d]" % i)
        bodies.append(body)
    names = [b.name for b in bodies]
    if len(set(names)) != len(names) or len(bodies) < 2:
        raise ValueError("a scene needs >= 2 bodies with distinct names")
    return bodies


def rot_matrix(rot):
    """(M, W): R(r) = M / W, polynomial entries, from formats.md's formula."""
    w, x, y, z = rot
    v = (x, y, z)
    vv = x * x + y * y + z * z
    W = w * w + vv
    skew = ((None, -z, y), (z, None, -x), (-y, x, None))     # [v]x
    M = []
    for i in range(3):
        row = []
        for j in range(3):
            e = 2 * v[i] * v[j]
            if i == j:
                e = e + (w * w - vv)
            else:
                e = e + 2 * w * skew[i][j]
            row.append(e)
        M.append(row)
    return M, W


def world_at(body, p, t):
    """Exact world position of body point p at the rational time t (Fractions)."""
    t = to_fmpq(t)
    M, W = rot_matrix(body.rotation)
    Wt = W(t)
    out = []
    for i in range(3):
        s = sum((M[i][j](t) * to_fmpq(p[j]) for j in range(3)), to_fmpq(0))
        val = s / Wt + body.translation[i](t)
        out.append(Fraction(int(val.p), int(val.q)))
    return tuple(out)
