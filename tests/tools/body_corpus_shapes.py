"""The vocabulary of the body corpus cases (make_body_corpus.py): exact number texts,
shapes (meshes, ball sets, boxes, tetrahedra, plates), motions (linear, still, rotations
about an axis, polynomial products) and the case registry that the case modules fill.
Plain data: nothing here calls polyccd or the oracle."""
import os
from fractions import Fraction as F

from oracle import decimal_str, fraction_str   # noqa: E402  (tests/oracle on sys.path)

TESTS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
E30 = F(1, 10 ** 30)


# ---------------------------------------------------------------- exact texts

class Raw(str):
    """A JSON number written as it is (e.g. 0.5 or 1e-30), an exact decimal."""


def num(x):
    if isinstance(x, Raw):
        return x
    x = F(x)
    if x.denominator == 1:
        return int(x)
    for k in range(1, 61):
        if x == F(1, 10 ** k):
            return "1e-%d" % k
        if x == F(-1, 10 ** k):
            return "-1e-%d" % k
    s = decimal_str(x)
    return s if len(s) <= 24 else fraction_str(x)


def nums(v):
    return [nums(x) for x in v] if isinstance(v, (list, tuple)) else num(v)


# ---------------------------------------------------------------- shapes and motions

def mesh(vertices, triangles):
    return {"mesh": {"vertices": nums(vertices), "triangles": [list(t) for t in triangles]}}


def balls(centers, radii):
    return {"spheres": {"centers": nums(centers), "radii": nums(radii)}}


def body(name, shape, translation=None, rotation=None):
    b = {"name": name}
    b.update(shape)
    mo = {}
    if translation is not None:
        mo["translation"] = nums(translation)
    if rotation is not None:
        mo["rotation"] = nums(rotation)
    if mo:
        b["motion"] = mo
    return b


CUBE_TRIS = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
             [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
# top face z = hi: triangles 2 = [4, 5, 6] (x + y <= 1 in local coordinates) and 3


def cube(lo=(0, 0, 0), s=1):
    lo = [F(x) for x in lo]
    s = F(s)
    v = [[lo[0] + s * (i & 1), lo[1] + s * ((i >> 1) & 1), lo[2] + s * (i >> 2)]
         for i in range(8)]
    return mesh(v, CUBE_TRIS)


def box(lo, hi):
    v = [[(hi if i & 1 else lo)[0], (hi if i & 2 else lo)[1], (hi if i & 4 else lo)[2]]
         for i in range(8)]
    return mesh(v, CUBE_TRIS)


def octahedron(c=(0, 0, 0), r=1):
    c = [F(x) for x in c]
    v = [[c[0] + r, c[1], c[2]], [c[0] - r, c[1], c[2]], [c[0], c[1] + r, c[2]],
         [c[0], c[1] - r, c[2]], [c[0], c[1], c[2] + r], [c[0], c[1], c[2] - r]]
    t = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    return mesh(v, t)


def tet(apex, base):
    """Vertex 0 = apex, 1-3 = base; outward-ish orientation does not matter."""
    return mesh([apex] + list(base), [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])


def plate(z=0, x0=0, x1=1, y0=0, y1=1):
    """Square [x0, x1] x [y0, y1] at height z: triangle 0 = (x0,y0) (x1,y0) (x0,y1)."""
    v = [[x0, y0, z], [x1, y0, z], [x0, y1, z], [x1, y1, z]]
    return mesh(v, [[0, 1, 2], [1, 3, 2]])


def linear(p0, p1):
    return [[F(a), F(b) - F(a)] for a, b in zip(p0, p1)]


def still(p):
    return [[F(a)] for a in p]


def about(axis, tau0, tau1, scale=1):
    """Quaternion scale * (1, tau(t) axis), tau linear from tau0 to tau1."""
    tau = [F(tau0), F(tau1) - F(tau0)]
    return [[F(scale)]] + [[scale * a * c for c in tau] for a in axis]


def pmul(p, q):
    out = [F(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            out[i + j] += F(a) * F(b)
    return out


def padd(p, q):
    n = max(len(p), len(q))
    return [(F(p[i]) if i < len(p) else 0) + (F(q[i]) if i < len(q) else 0) for i in range(n)]


# apex-down tetrahedron (apex at the body origin), everything else 1 above
TET_DOWN = ([0, 0, 0], [[F(-1, 4), F(-1, 4), 1], [F(1, 2), F(-1, 4), 1], [F(-1, 4), F(1, 2), 1]])
# apex at (0, 0, -1), other vertices within |p| < 1/2 of the origin (for rotations about
# the x or y axis through the origin only the apex comes within 1/2 of the plane z = h - 1)
TET_PIN = ([0, 0, -1], [[F(-1, 4), F(-1, 4), 0], [F(1, 4), F(-1, 4), 0], [F(-1, 4), F(1, 4), 0]])
PAR = padd(pmul([-1, 2], [-1, 2]), [1])      # 1 + (2t - 1)^2: a parabola's height
BIG_TRI = mesh([[-3, -3, 0], [3, -3, 0], [0, 3, 0]], [[0, 1, 2]])
ROOT3 = (F(42, 100), F(43, 100))     # 1 - sqrt(3)/3 = 0.42264...


def moved(b, off):
    return [[x + o for x, o in zip(p, off)] for p in b]


# ---------------------------------------------------------------- the cases
#
# case(category, name, bodies, want, feat=None, options=None, pairs=None, note="")
#   want: None (no contact) | rational time | ("irr", [c0, c1, ...], lo, hi) | "any"

CASES = []


def case(category, name, bodies, want, feat=None, options=None, pairs=None, note=""):
    CASES.append(dict(category=category, name=name, bodies=bodies, want=want, feat=feat,
                      options=options, pairs=pairs, note=note))


def vt(a, b, fa, fb):
    return [{"bodies": [a, b], "a": list(fa), "b": list(fb)}]
