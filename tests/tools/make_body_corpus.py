"""Builds corpus/bodies/<category>/<name>.json (polyccd/1 scene cases) whose expectations
come from the independent body oracle (tests/oracle/oracle_body.py), never from polyccd.

    python tests/tools/make_body_corpus.py [--out corpus/bodies] [--check]

Every case carries the answer reasoned out by hand (`want`, derivation in the comment
next to it) and the script stops if the oracle disagrees; a few cases say "any" (the
oracle's answer is written as it is). `features` (optional in EXPECT) is written when
the oracle finds the touching feature set at t* > 0 unambiguous (one vertex-triangle,
edge-edge or ball-ball pair, or one ball touching a triangle inside its open face);
where the case lists `feat`, the oracle must find exactly that. The output is
deterministic; --check only verifies that the files on disk are what this script writes.
"""
import argparse
import json
import os
import sys
import time
from fractions import Fraction as F

TESTS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The oracles live in tests/oracle/ and import each other by plain name.
sys.path.insert(0, os.path.join(TESTS, "oracle"))
import oracle_body as OB          # noqa: E402
from oracle import decimal_str, fraction_str, time_strictly_in   # noqa: E402

SOURCE = "tests/tools/make_body_corpus.py (oracle: tests/oracle/oracle_body.py)"
ENCLOSURE = F(1, 10 ** 20)
OUT = os.path.join(TESTS, "..", "corpus", "bodies")
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


# ----- mesh vs mesh
MM = "mesh-mesh"

# B's bottom face z = 2 - 2t reaches A's top z = 1 at t = 1/2 (coplanar faces meet).
case(MM, "cube-face-onto-face-translation",
     [body("A", cube()), body("B", cube(["1/2", "1/4", 2]), translation=[[0], [0], [0, -2]])],
     F(1, 2), note="two unit cubes; B falls onto A, overlapping faces at t = 1/2")

# apex (1/3, 1/2, 3 - 3t) reaches the top face z = 1 at t = 2/3, strictly inside
# triangle 2 = [4, 5, 6] (x + y = 5/6 < 1); the base is then at z >= 2.
case(MM, "vertex-into-face-interior-translation",
     [body("A", cube()),
      body("B", tet([F(1, 3), F(1, 2), 3], [[0, 0, 4], [1, 0, 4], [0, 1, 4]]),
           translation=[[0], [0], [0, -3]])],
     F(2, 3), feat=vt("A", "B", ("triangle", 2), ("vertex", 0)))

# r = (1, t - 1/2, 0, 0) turns B about the x axis; the apex (0, 0, -1) is at
# (0, sin th, 1 - cos th) >= 0 (translation (0, 0, 1)), zero only at th = 0, t = 1/2:
# a double root, the apex grazes the interior of A's triangle at the origin. All other
# points of B are within 1/2 of the origin, so they stay above z = 1/2.
case(MM, "vertex-face-grazing-rotation",
     [body("A", BIG_TRI), body("B", tet(*TET_PIN), translation=still([0, 0, 1]),
                               rotation=about([1, 0, 0], F(-1, 2), F(1, 2)))],
     F(1, 2), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))

# the same lifted by 1e-30: the apex stays 1e-30 above the plane.
case(MM, "vertex-face-grazing-rotation-miss-1e-30",
     [body("A", BIG_TRI), body("B", tet(*TET_PIN), translation=still([0, 0, 1 + E30]),
                               rotation=about([1, 0, 0], F(-1, 2), F(1, 2)))],
     None)

# B's bottom edge (0, s, -1), s in [-1, 1], turned about the y axis by th (tau = t - 1/3)
# and lifted by 1 is at z = 1 - cos th >= 0, zero only at t = 1/3 where it lies along the
# y axis and crosses A's top edge (the x axis) at the origin: grazing edge-edge.
EE_A = mesh([[-1, 0, 0], [1, 0, 0], [0, 0, -1]], [[0, 1, 2]])
EE_B = mesh([[0, -1, -1], [0, 1, -1], [0, 0, 0]], [[0, 1, 2]])
case(MM, "edge-edge-grazing-rotation",
     [body("A", EE_A), body("B", EE_B, translation=still([0, 0, 1]),
                            rotation=about([0, 1, 0], F(-1, 3), F(2, 3)))],
     F(1, 3), feat=vt("A", "B", ("edge", 0), ("edge", 0)))

case(MM, "edge-edge-grazing-rotation-miss-1e-30",
     [body("A", EE_A), body("B", EE_B, translation=still([0, 0, 1 + E30]),
                            rotation=about([0, 1, 0], F(-1, 3), F(2, 3)))],
     None)

# lifted by 1/2 and tau = t - 1: z = 1/2 - cos th = 0 at tau^2 = 1/3, t = 1 - sqrt(3)/3,
# a root of 3t^2 - 6t + 2; the edge then crosses the x axis at x = sqrt(3)/2 < 1.
case(MM, "edge-edge-irrational-rotation",
     [body("A", EE_A), body("B", EE_B, translation=still([0, 0, F(1, 2)]),
                            rotation=about([0, 1, 0], -1, 0))],
     ("irr", [2, -6, 3]) + ROOT3, feat=vt("A", "B", ("edge", 0), ("edge", 0)))

# apex (0, 0, -1) turned about x, tau = t - 1, lifted by 1/2: z = 1/2 - cos th = 0 at
# t = 1 - sqrt(3)/3 (3t^2 - 6t + 2 = 0), at y = sin th = -sqrt(3)/2, inside A's triangle.
case(MM, "vertex-face-irrational-rotation",
     [body("A", BIG_TRI), body("B", tet(*TET_PIN), translation=still([0, 0, F(1, 2)]),
                               rotation=about([1, 0, 0], -1, 0))],
     ("irr", [2, -6, 3]) + ROOT3, feat=vt("A", "B", ("triangle", 0), ("vertex", 0)),
     options={"time_tolerance": "1e-30"})

# apex at z = 3 - (2 - 1e-30) t reaches 1 + 1e-30 at t = 1 only: a miss by 1e-30.
case(MM, "vertex-face-translation-miss-1e-30",
     [body("A", cube()),
      body("B", tet([F(1, 3), F(1, 2), 3], [[0, 0, 4], [1, 0, 4], [0, 1, 4]]),
           translation=[[0], [0], [0, -2 + E30]])],
     None)

# apex height above the top face: (2t - 1)^2 (+ 1e-30): grazing at t = 1/2 / a miss.
PAR = padd(pmul([-1, 2], [-1, 2]), [1])      # 1 + (2t - 1)^2
case(MM, "vertex-face-grazing-parabola",
     [body("A", cube()), body("B", tet([F(1, 3), F(1, 4), 0], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]),
                              translation=[[0], [0], PAR])],
     F(1, 2), feat=vt("A", "B", ("triangle", 2), ("vertex", 0)))
case(MM, "vertex-face-grazing-parabola-miss-1e-30",
     [body("A", cube()), body("B", tet([F(1, 3), F(1, 4), 0], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]),
                              translation=[[0], [0], padd(PAR, [E30])])],
     None)

# B's edge (0, y, 0), y in [-1, 1], at height (2t - 1)^2 over A's edge (the x axis):
# grazing edge-edge at t = 1/2 (a translation of degree 2).
case(MM, "edge-edge-grazing-parabola",
     [body("A", EE_A),
      body("B", mesh([[0, -1, 0], [0, 1, 0], [0, 0, 1]], [[0, 1, 2]]),
           translation=[[0], [0], pmul([-1, 2], [-1, 2])])],
     F(1, 2), feat=vt("A", "B", ("edge", 0), ("edge", 0)))

# coplanar unit squares in z = 0; B spans x in [3 - 5t/2, 4 - 5t/2]: touches x = 1 at 4/5.
case(MM, "coplanar-sliding-squares",
     [body("A", plate()), body("B", plate(0, 3, 4, F(1, 4), F(3, 4)),
                               translation=[[0, F(-5, 2)], [0], [0]])],
     F(4, 5))

# the same, 1e-30 above the plane: never touches.
case(MM, "coplanar-sliding-squares-miss-1e-30",
     [body("A", plate()), body("B", plate(E30, 3, 4, F(1, 4), F(3, 4)),
                               translation=[[0, F(-5, 2)], [0], [0]])],
     None)

# B: unit square centred on its origin, turning in the plane z = 0 (tau = t about z)
# while its centre goes from x = 3 to x = 1: its extent to the left is (cos th + sin th)/2,
# so the first contact is near the root of 2 - 2t = (cos th + sin th)/2 (about 0.68); the
# corner's height decides which edges meet, the oracle the exact time.
case(MM, "coplanar-square-turning-in-plane",
     [body("A", plate()),
      body("B", plate(0, F(-1, 2), F(1, 2), F(-1, 2), F(1, 2)),
           translation=[[3, -2], [F(1, 2)], [0]], rotation=about([0, 0, 1], 0, 1))],
     "any")

# parallel edges: B's bottom edge (x in [1, 3], y = 0, z = 1 - 2t) comes down onto A's
# top edge (x in [0, 2]) at t = 1/2, overlapping in [1, 2].
case(MM, "parallel-edges-overlap",
     [body("A", mesh([[0, 0, 0], [2, 0, 0], [1, 0, -1]], [[0, 1, 2]])),
      body("B", mesh([[1, 0, 0], [3, 0, 0], [2, 1, 0]], [[0, 1, 2]]),
           translation=[[0], [0], [1, -2]])],
     F(1, 2))

# the same with B shifted by 1e-30 in y: B's triangle keeps y >= 1e-30 > 0 = A's plane.
case(MM, "parallel-edges-pass-1e-30-apart",
     [body("A", mesh([[0, 0, 0], [2, 0, 0], [1, 0, -1]], [[0, 1, 2]])),
      body("B", mesh([[1, E30, 0], [3, E30, 0], [2, 1, 0]], [[0, 1, 2]]),
           translation=[[0], [0], [1, -2]])],
     None)

# face to face at t = 0, then B leaves along +x.
case(MM, "touching-at-t0-moving-apart",
     [body("A", cube()), body("B", cube([1, 0, 0]), translation=[[0, 1], [0], [0]])],
     F(0))

# A in the plane y = 0, B in x = 0, crossing like two chain links at t = 0: the common
# points are the segment x = y = 0, -1 <= z <= 1, with no vertex of one in the other and
# no two edges meeting (only an edge through the other's interior). B then moves 3 to +x.
X_A = mesh([[-2, 0, -1], [2, 0, -1], [0, 0, 2]], [[0, 1, 2]])
X_B = mesh([[0, -2, 1], [0, 2, 1], [0, 0, -2]], [[0, 1, 2]])
case(MM, "transversal-crossing-at-t0",
     [body("A", X_A), body("B", X_B, translation=[[0, 3], [0], [0]])], F(0))

# the same crossing at t = 0 with B turning about z and rising.
case(MM, "transversal-crossing-at-t0-rotating",
     [body("A", X_A), body("B", X_B, translation=[[0], [0], [0, 4]],
                            rotation=about([0, 0, 1], 0, 2))], F(0))

# B at x in [3 - 2t, 4 - 2t] meets A exactly at t = 1; with 2 - 1e-30 it stops 1e-30 short.
case(MM, "face-contact-exactly-at-t1",
     [body("A", cube()), body("B", cube([3, 0, 0]), translation=[[0, -2], [0], [0]])], F(1))
case(MM, "face-gap-1e-30-at-t1",
     [body("A", cube()), body("B", cube([3, 0, 0]), translation=[[0, -2 + E30], [0], [0]])],
     None)

# a needle (collinear triangle 0, 1, 2 on a vertical line) falls onto a plate: its bottom
# vertex (1/3, 1/4, 1 - 2t) touches triangle 0 of the plate at t = 1/2.
case(MM, "degenerate-collinear-needle-onto-plate",
     [body("A", plate()),
      body("B", mesh([[F(1, 3), F(1, 4), 1], [F(1, 3), F(1, 4), 2], [F(1, 3), F(1, 4), 3]],
                     [[0, 1, 2]]), translation=[[0], [0], [0, -2]])],
     F(1, 2), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))

# segment triangles: A = [0, 1, 1] on the x axis, B = [0, 0, 1] along y at z = 1 - 2t
# (plus a point triangle [2, 2, 2] far away): the segments cross at t = 1/2.
case(MM, "degenerate-segment-triangles-cross",
     [body("A", mesh([[-1, 0, 0], [1, 0, 0]], [[0, 1, 1]])),
      body("B", mesh([[0, -1, 1], [0, 1, 1], [5, 5, 5]], [[0, 0, 1], [2, 2, 2]]),
           translation=[[0], [0], [0, -2]])],
     F(1, 2), feat=vt("A", "B", ("edge", 0), ("edge", 0)))

# a point triangle [2, 2, 2] at (1/3, 1/4, 1/2 - t) hits the plate at t = 1/2; the
# segment triangle [0, 0, 1] stays at z >= 3/2 - t.
case(MM, "degenerate-point-triangle-onto-plate",
     [body("A", plate()),
      body("B", mesh([[0, 0, 2], [1, 1, 2], [F(1, 3), F(1, 4), F(1, 2)]], [[0, 0, 1], [2, 2, 2]]),
           translation=[[0], [0], [0, -1]])],
     F(1, 2), feat=vt("A", "B", ("triangle", 0), ("vertex", 2)))

# vertex 4 of B is used by no triangle (no part of B's surface): it crosses the plate at
# t = 1/3 (z = 1/2 - 3t/2), which is no contact; the apex (z = 1 - 3t/2) touches at 2/3.
case(MM, "unused-vertex-passes-through",
     [body("A", plate()),
      body("B", mesh([[F(1, 3), F(1, 4), 1], [0, 0, 2], [1, 0, 2], [0, 1, 2], [F(1, 2), F(1, 2), F(1, 2)]],
                     [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]),
           translation=[[0], [0], [0, F(-3, 2)]])],
     F(2, 3), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))

# two octahedra head on: B's vertex (3 - 2t - 1, 0, 0) meets A's vertex (1, 0, 0) at 1/2.
case(MM, "octahedra-vertex-meets-vertex",
     [body("A", octahedron()), body("B", octahedron([3, 0, 0]), translation=[[0, -2], [0], [0]])],
     F(1, 2))

# two tetrahedra sharing only a point of an edge at t = 0 (edge-edge), then apart.
case(MM, "edge-edge-touching-at-t0",
     [body("A", EE_A), body("B", mesh([[0, -1, 0], [0, 1, 0], [0, 0, 1]], [[0, 1, 2]]),
                            translation=[[0], [0], [0, 1]])],
     F(0))

# an octahedron turning about a tilted axis and sliding towards a cube: oracle's answer.
case(MM, "octahedron-tumbling-into-cube",
     [body("A", cube()), body("B", octahedron([0, 0, 0], F(3, 4)),
                              translation=linear([F(5, 2), F(1, 2), F(1, 2)], [F(3, 2), F(1, 2), F(1, 2)]),
                              rotation=about([1, 2, 2], 0, 1))],
     "any")


# both bodies turning: an octahedron turning about x (tau = t) and a cube turning about z
# (tau = -t) while closing in along x; the oracle decides.
case(MM, "both-bodies-turning",
     [body("A", octahedron([0, 0, 0], 1), rotation=about([1, 0, 0], 0, 1)),
      body("B", cube([F(-1, 2), F(-1, 2), F(-1, 2)]), translation=linear([3, F(1, 4), 0], [1, F(1, 4), 0]),
           rotation=about([0, 0, 1], 0, -1))],
     "any")

# the grazing rotation of vertex-face-grazing-rotation with tau = t - 1: the apex touches
# the plane (double root) exactly at the end, t = 1; with tau = t at the start, t = 0.
case(MM, "vertex-face-grazing-rotation-at-t1",
     [body("A", BIG_TRI), body("B", tet(*TET_PIN), translation=still([0, 0, 1]),
                               rotation=about([1, 0, 0], -1, 0))],
     F(1), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))
case(MM, "vertex-face-grazing-rotation-at-t0",
     [body("A", BIG_TRI), body("B", tet(*TET_PIN), translation=still([0, 0, 1]),
                               rotation=about([1, 0, 0], 0, 1))],
     F(0))

# cubes of side 10^6: B slides along y past A with a gap of 1e-20 in x (B's face at
# x = 10^6 + 1e-20): no contact.
case(MM, "large-scale-gap-1e-20",
     [body("A", cube([0, 0, 0], 10 ** 6)),
      body("B", cube([10 ** 6 + F(1, 10 ** 20), 0, 0], 10 ** 6),
           translation=linear([0, -3 * 10 ** 6, 0], [0, 3 * 10 ** 6, 0]))],
     None)
# the x gap 1e-20 (1 - 3t) closes at t = 1/3, when B's y range [-3e6 + 6e6 t, -2e6 + 6e6 t]
# also reaches y = 0: before 1/3 they are apart in x and in y, at 1/3 they meet along
# the edge x = 10^6, y = 0 (and then interpenetrate).
case(MM, "large-scale-gap-closes",
     [body("A", cube([0, 0, 0], 10 ** 6)),
      body("B", cube([10 ** 6, 0, 0], 10 ** 6),
           translation=[[F(1, 10 ** 20), F(-3, 10 ** 20)], [-3 * 10 ** 6, 6 * 10 ** 6], [0]])],
     F(1, 3))

# Swings about a fixed axis against a body at rest: the range phase's exact rotation
# linearization (lib/range/LINEARIZATION.md), contacts decided at a root of its quadratic.
# A pivot c is written as body points shifted by -c and the constant translation c.
#
# tests/c/test_index.c's swing: B = (1/3, 2, 1/2), (1, 2, 1/2), (1, 2, 3/4) turns about the
# vertical axis through (2, 2, 0), tau 0 -> 1. Vertex 0 (distance 5/3 from the axis) is at
# (2 - 5/3 cos th, 2 - 5/3 sin th, 1/2) and reaches the face y = 1 at sin th = 3/5
# (x = 2/3, inside triangle 7 = [3, 6, 7]: x + z >= 1), tan(th / 2) = 1/3 = tau: t = 1/3.
case(MM, "rotation-swing-vertex-onto-face",
     [body("A", cube()),
      body("B", mesh([[F(-5, 3), 0, F(1, 2)], [-1, 0, F(1, 2)], [-1, 0, F(3, 4)]], [[0, 1, 2]]),
           translation=still([2, 2, 0]), rotation=about([0, 0, 1], 0, 1))],
     F(1, 3), feat=vt("A", "B", ("triangle", 7), ("vertex", 0)))

# B (x in [1/2, 1]) turns about the y axis from -90 to 90 degrees: its points
# (x cos th, y, -x sin th) reach x >= 1 only at th = 0 (t = 1/2), coplanar with A in z = 0,
# B's edge x = 1 through A's vertex (1, 0, 0), the end of A's edges (1,0,0)-(2,0,0) and
# (1,0,0)-(2,0,-1): a touch at an edge's endpoint, in a common plane.
case(MM, "rotation-edge-turns-coplanar-onto-edge-end",
     [body("A", mesh([[1, 0, 0], [2, 0, 0], [2, 0, -1]], [[0, 1, 2]])),
      body("B", mesh([[1, -1, 0], [1, 1, 0], [F(1, 2), 0, 0]], [[0, 1, 2]]),
           rotation=about([0, 1, 0], -1, 1))],
     F(1, 2))

# B's vertex 0 on the unit circle about the z axis, tau = 4t: y = sin th = 3/5 at
# tan(th / 2) = 1/3 and 3, i.e. t = 1/12 and 3/4 (two roots of the contact quadratic in
# the piece); A's triangle in y = 3/5 holds both points; B's other vertices stay within
# radius 3/5 - and below it. First contact at 1/12.
case(MM, "rotation-arc-crosses-triangle-twice",
     [body("A", mesh([[-2, F(3, 5), -1], [2, F(3, 5), -1], [0, F(3, 5), 2]], [[0, 1, 2]])),
      body("B", mesh([[1, 0, 0], [F(1, 2), 0, 0], [F(1, 2), F(-1, 4), 0]], [[0, 1, 2]]),
           rotation=about([0, 0, 1], 0, 4))],
     F(1, 12), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))

# ----- sphere sets vs sphere sets
SS = "spheres-spheres"

# centres 5 - 4t apart, radii 1 + 1: touch at 5 - 4t = 2, t = 3/4.
case(SS, "head-on-touch",
     [body("A", balls([[0, 0, 0]], [Raw("1.0")])),
      body("B", balls([[0, 0, 0]], [1]), translation=linear([5, 0, 0], [1, 0, 0]))],
     F(3, 4), feat=vt("A", "B", ("sphere", 0), ("sphere", 0)))

# B's centre (-3 + 6t, 2, 0): |d|^2 = (6t - 3)^2 + 4 >= 4 = (1 + 1)^2, equal at t = 1/2.
case(SS, "pass-by-grazing",
     [body("A", balls([[0, 0, 0]], [1])),
      body("B", balls([[0, 0, 0]], [1]), translation=linear([-3, 2, 0], [3, 2, 0]))],
     F(1, 2), feat=vt("A", "B", ("sphere", 0), ("sphere", 0)))
case(SS, "pass-by-miss-1e-30",
     [body("A", balls([[0, 0, 0]], [1])),
      body("B", balls([[0, 0, 0]], [1]), translation=linear([-3, 2 + E30, 0], [3, 2 + E30, 0]))],
     None)

# dumbbell (+-2, 0, 0), radii 1/2, turning about z with tau = t; ball (0, 5/2, 0) radius
# 1/2: |d|^2 = 4 + 25/4 - 10 sin th = 1 at sin th = 2t/(1+t^2) = 37/40: 37t^2 - 80t + 37 = 0.
case(SS, "rotating-dumbbell-irrational",
     [body("A", balls([[2, 0, 0], [-2, 0, 0]], [F(1, 2), F(1, 2)]),
           rotation=about([0, 0, 1], 0, 1)),
      body("B", balls([[0, F(5, 2), 0]], [F(1, 2)]))],
     ("irr", [37, -80, 37], F(67, 100), F(68, 100)),
     feat=vt("A", "B", ("sphere", 0), ("sphere", 0)))

case(SS, "overlapping-at-t0",
     [body("A", balls([[0, 0, 0], [3, 0, 0]], [1, 1])),
      body("B", balls([[F(3, 2), 0, 0]], [1]), translation=linear([0, 0, 0], [0, 5, 0]))],
     F(0))

# centres 4 - 2t apart, radii 1 + 1: touch at t = 1 exactly.
case(SS, "touching-exactly-at-t1",
     [body("A", balls([[0, 0, 0]], [1])),
      body("B", balls([[4, 0, 0]], [1]), translation=[[0, -2], [0], [0]])],
     F(1), feat=vt("A", "B", ("sphere", 0), ("sphere", 0)))

# radii 1e-30: B's centre (-1 + 2t, 2e-30, 0) passes A's at distance exactly 2e-30 at 1/2.
case(SS, "tiny-radii-1e-30-touch",
     [body("A", balls([[0, 0, 0]], [Raw("1e-30")])),
      body("B", balls([[0, 0, 0]], ["1e-30"]), translation=linear([-1, 2 * E30, 0], [1, 2 * E30, 0]))],
     F(1, 2), feat=vt("A", "B", ("sphere", 0), ("sphere", 0)))
case(SS, "tiny-radii-1e-30-miss",
     [body("A", balls([[0, 0, 0]], ["1e-30"])),
      body("B", balls([[0, 0, 0]], ["1e-30"]),
           translation=linear([-1, 2 * E30 + F(1, 10 ** 60), 0], [1, 2 * E30 + F(1, 10 ** 60), 0]))],
     None)

# a 6-atom molecule and a 4-atom one; B's atom 2 (body (1, 0, 0), radius 1/2) reaches A's
# atom 1 ((3, 0, 0), radius 1/2) when B's origin is at x = 1, i.e. 5 - 4t = 1 at t = 1.
# Before that, B's atoms are all at x >= 5 - 4t + 1 - 1/2 ... the first contact is atom 2
# with atom 1? B's atom 0 (body (2, 1/2, 0)) is farther. The oracle decides the rest.
case(SS, "molecules-six-and-four-atoms",
     [body("A", balls([[0, 0, 0], [3, 0, 0], [0, 3, 0], [0, 0, 3], [F(3, 2), F(3, 2), 0], [-1, -1, -1]],
                      [F(1, 2), F(1, 2), F(3, 4), 1, F(1, 4), F(1, 3)])),
      body("B", balls([[2, F(1, 2), 0], [3, 0, 1], [1, 0, 0], [2, -1, 0]],
                      [F(1, 4), F(1, 2), F(1, 2), F(1, 3)]),
           translation=linear([5, 0, 0], [0, 0, 0]), rotation=about([0, 0, 1], 0, F(1, 4)))],
     "any")


# atom 0 of the dumbbell turns with tau = 2t to (0, 2, 0) at t = 1/2 (th = 90 degrees);
# the ball at (0, 3, 0) is then exactly 1/2 + 1/2 away: |d|^2 = 13 - 12 sin th >= 1, a
# grazing contact at t = 1/2 only; with the ball 1e-30 farther out, none.
case(SS, "rotating-dumbbell-grazing",
     [body("A", balls([[2, 0, 0], [-2, 0, 0]], [F(1, 2), F(1, 2)]), rotation=about([0, 0, 1], 0, 2)),
      body("B", balls([[0, 3, 0]], [F(1, 2)]))],
     F(1, 2), feat=vt("A", "B", ("sphere", 0), ("sphere", 0)))
case(SS, "rotating-dumbbell-miss-1e-30",
     [body("A", balls([[2, 0, 0], [-2, 0, 0]], [F(1, 2), F(1, 2)]), rotation=about([0, 0, 1], 0, 2)),
      body("B", balls([[0, 3 + E30, 0]], [F(1, 2)]))],
     None)
# B's ball turns about the vertical axis through (1, 0, 0), tau -1 -> 0 (90 degrees, back
# to rest): its centre 1 + v moves from (9/5, 2/5, 0) to (3/5, 4/5, 0) on the circle |v| =
# 2 / sqrt(5) about the pivot, its angle from 26.6 to 116.6 degrees, so its squared
# distance 9/5 + 2 v_x to A's ball at the origin falls all the way to 1 = (1/2 + 1/2)^2:
# tangent at t = 1 only (the exact ball clause: the quadratic's minimum at the piece's end).
case(SS, "rotation-balls-tangent-at-t1",
     [body("A", balls([[0, 0, 0]], [F(1, 2)])),
      body("B", balls([[F(-2, 5), F(4, 5), 0]], [F(1, 2)]), translation=still([1, 0, 0]),
           rotation=about([0, 0, 1], -1, 0))],
     1, feat=vt("A", "B", ("sphere", 0), ("sphere", 0)))

# ----- sphere sets vs meshes
SM = "spheres-mesh"

# centre (1/2, 1/3, 4 - 4t), radius 1: reaches the top face z = 1 at z = 2, t = 1/2,
# projecting strictly inside triangle 2 (x + y = 5/6 < 1).
case(SM, "ball-hits-face-interior",
     [body("A", cube()), body("B", balls([[F(1, 2), F(1, 3), 0]], [1]), translation=[[0], [0], [4, -4]])],
     F(1, 2), feat=vt("A", "B", ("triangle", 2), ("sphere", 0)))

# in the triangle's own plane: centre (0, -3 + 4t, 0), radius 1, touches the edge y = 0 at
# (0, 0, 0) when y = -1, t = 1/2.
case(SM, "ball-hits-edge-in-plane",
     [body("A", balls([[0, 0, 0]], [1]), translation=linear([0, -3, 0], [0, 1, 0])),
      body("B", mesh([[-2, 0, 0], [2, 0, 0], [0, 2, 0]], [[0, 1, 2]]))],
     F(1, 2))

# centre (0, -3 + 3t, 3 - 3t): distance to the edge (the x axis) sqrt(2) (3 - 3t) = 1 at
# t = 1 - sqrt(2)/6, a root of 18t^2 - 36t + 17 (the nearest point is then on the edge).
case(SM, "ball-hits-edge-irrational",
     [body("A", mesh([[-2, 0, 0], [2, 0, 0], [0, 2, 0]], [[0, 1, 2]])),
      body("B", balls([[0, 0, 0]], [1]), translation=linear([0, -3, 3], [0, 0, 0]))],
     ("irr", [17, -36, 18], F(76, 100), F(77, 100)), options={"time_tolerance": "1e-25"})

# Regression (issue 15, a scene check that ran 60 s): a ball of radius 1/5 + 2^-8000
# (8,000-bit numbers) turning about the z axis through (0, 1/3, 0) (tau 0 -> 1/2) while a
# tetrahedron slides into it. Its first time's rational-root test narrowed an isolating
# interval below 1/lc(F), lc of about 32,000 bits, one halving per step, with fraction
# arithmetic and a Euclid over Q (poly/rational_root.cpp, poly/gcd.cpp: now quadratic
# interval refinement and the primitive remainder sequence). Answer: the oracle's.
case(SM, "slow-rational-root-long-radius",
     [body("A", balls([[0, F(-1, 3), 0]], [F(1, 5) + F(1, 2 ** 8000)]), translation=still([0, F(1, 3), 0]),
           rotation=about([0, 0, 1], 0, F(1, 2))),
      body("B", mesh([[1, -1, -1], [1, 1, -1], [1, 0, 1], [2, 0, 0]], [[0, 1, 2], [0, 1, 3], [1, 2, 3], [0, 2, 3]]),
           translation=linear([0, 0, 0], [F(-3, 4), F(1, 9), F(1, 7)]))],
     "any")

# centre (1, 1, 1) + (1 - t)(2, 1, 2), radius 1: the corner (1, 1, 1) is the nearest point,
# at distance 3 (1 - t) = 1 when t = 2/3.
case(SM, "ball-hits-cube-corner",
     [body("A", cube()),
      body("B", balls([[1, 1, 1]], [1]), translation=[[2, -2], [1, -1], [2, -2]])],
     F(2, 3))

# centre (1/2, 1/3, 2 + (2t - 1)^2), radius 1, over the top face z = 1: grazes at t = 1/2.
case(SM, "ball-grazing-face-parabola",
     [body("A", cube()), body("B", balls([[F(1, 2), F(1, 3), 1]], [1]), translation=[[0], [0], PAR])],
     F(1, 2), feat=vt("A", "B", ("triangle", 2), ("sphere", 0)))
case(SM, "ball-grazing-face-miss-1e-30",
     [body("A", cube()), body("B", balls([[F(1, 2), F(1, 3), 1]], [1]),
                              translation=[[0], [0], padd(PAR, [E30])])],
     None)

# centre (0, 0, 1/2 + 2t), radius 1, over a big triangle's interior: the ball already cuts
# the face at t = 0 though every vertex is far outside it.
case(SM, "ball-cuts-face-at-t0-vertices-outside",
     [body("A", mesh([[-4, -4, 0], [4, -4, 0], [0, 4, 0]], [[0, 1, 2]])),
      body("B", balls([[0, 0, F(1, 2)]], [1]), translation=[[0], [0], [0, 2]])],
     F(0))

# centre (-2 + 4t, 1/3, 2), radius 1, moving parallel to the top face z = 1 (distance 1):
# for x < 0 the nearest point is on the edge x = 0, z = 1 at distance sqrt(x^2 + 1); the
# ball first touches that edge at x = 0, t = 1/2 (and then rolls on the face).
case(SM, "ball-rolling-onto-face-over-edge",
     [body("A", cube()), body("B", balls([[0, F(1, 3), 2]], [1]), translation=[[-2, 4], [0], [0]])],
     F(1, 2))

# apex (0, 0, -1) turned about x (tau = t - 1), lifted by 1/2, runs on the circle of
# radius 1 about (0, 0, 1/2) in the plane x = 0, at (0, sin th, 1/2 - cos th). The ball
# (centre (0, -1, -1/4), radius 1/4) is 5/4 from the circle's centre, so the circle only
# grazes it, at the point towards the centre: sin th = -4/5, cos th = 3/5, i.e.
# tau = sin th / (1 + cos th) = -1/2, t = 1/2 (a double root). The rest of B stays within
# 0.36 of (0, 0, 1/2).
case(SM, "rotating-tet-apex-grazes-ball",
     [body("A", balls([[0, -1, F(-1, 4)]], [F(1, 4)])),
      body("B", tet(*TET_PIN), translation=still([0, 0, F(1, 2)]), rotation=about([1, 0, 0], -1, 0))],
     F(1, 2))

# a segment triangle [0, 0, 1] on the x axis; centre (1/2, 0, 3 - 4t), radius 1: t = 1/2.
case(SM, "ball-onto-degenerate-segment-triangle",
     [body("A", mesh([[0, 0, 0], [1, 0, 0]], [[0, 0, 1]])),
      body("B", balls([[F(1, 2), 0, 0]], [1]), translation=[[0], [0], [3, -4]])],
     F(1, 2))

# a three-atom molecule turning (non-unit quaternion (2, 0, 0, 2t)) and falling onto a cube.
case(SM, "molecule-turning-onto-cube",
     [body("A", cube()),
      body("B", balls([[F(1, 2), 0, 0], [F(-1, 2), 0, 0], [0, F(1, 2), F(-1, 4)]],
                      [F(1, 4), F(1, 4), F(1, 3)]),
           translation=[[F(1, 2)], [F(1, 2)], [3, -2]], rotation=[[2], [0], [0], [0, 2]])],
     "any")


# ----- scenes of 3-4 bodies
MB = "multi-body"

# B (x in [2 + 2t, 3 + 2t]) reaches C (x in [4, 5]) at t = 1/2 and leaves A (x <= 1) alone.
case(MB, "three-cubes-middle-moves-right",
     [body("A", cube()), body("B", cube([2, 0, 0]), translation=[[0, 2], [0], [0]]),
      body("C", cube([4, 0, 0]))],
     F(1, 2), pairs=[["B", "C"]])

# B (x in [3 - 4t, 4 - 4t]) meets A (x <= 1) at t = 1/2; the ball C of radius 1 at
# (13/2, 1/2, 1/2) is never reached (B's right face is at x <= 4).
case(MB, "cube-between-cube-and-ball",
     [body("A", cube()), body("B", cube([3, 0, 0]), translation=[[0, -4], [0], [0]]),
      body("C", balls([[F(13, 2), F(1, 2), F(1, 2)]], [1]))],
     F(1, 2), pairs=[["A", "B"]])

# balls in a row (radius 1/2 each, touching at distance 1): L at x = 0, M at 2 - 4t,
# R at 4 - 6t. L-M: 2 - 4t = 1 at t = 1/4 (first); M-R: 2 - 2t = 1 at t = 1/2; L-R:
# 4 - 6t = 1 at t = 1/2.
case(MB, "three-balls-chain",
     [body("L", balls([[0, 0, 0]], [F(1, 2)])),
      body("M", balls([[2, 0, 0]], [F(1, 2)]), translation=[[0, -4], [0], [0]]),
      body("R", balls([[4, 0, 0]], [F(1, 2)]), translation=[[0, -6], [0], [0]])],
     F(1, 4), pairs=[["L", "M"], ["L", "R"], ["M", "R"]])

# static: A and B share a face at t = 0; C is 1e-30 away from B; the ball D (radius 1/2,
# centre (21/8, 1/2, 3 - 3t)) falls onto C's top z = 1 at t = 1/2 and stays 5/8 from B.
case(MB, "four-bodies-static-contact-and-near-miss",
     [body("A", cube()), body("B", cube([1, 0, 0])), body("C", cube([2 + E30, 0, 0])),
      body("D", balls([[F(21, 8), F(1, 2), 3]], [F(1, 2)]), translation=[[0], [0], [0, -3]])],
     F(0), pairs=[["A", "B"], ["C", "D"]])

# two meshes and two molecules, turning and translating. P: unit cube. Q: octahedron
# (radius 1) turning about its centre (3 - t - t^3/2, 1/2, 1/2): it reaches P's face x = 1
# some time before t = 1 (at t = 1 its centre is at x = 3/2). M1: atoms (1/2, 1/2, z) with
# radius 1/2 and (3/2, 1/2, z) with radius 1/3, z = 3 - 7t/4: atom 0 lands on P's top at
# z = 3/2, t = 6/7 (inside P's top face). M2: ball of radius 1 at (-3 + 2t, 1/2, 1/2)
# touches P's face x = 0 at t = 1 exactly. Which of these and of the other pairs touch is
# the oracle's to say.
case(MB, "four-bodies-mixed-motions",
     [body("P", cube()),
      body("Q", octahedron([0, 0, 0], 1), rotation=about([0, 0, 1], 0, F(1, 2)),
           translation=[[3, -1, 0, F(-1, 2)], [F(1, 2)], [F(1, 2)]]),
      body("M1", balls([[0, 0, 0], [1, 0, 0]], [F(1, 2), F(1, 3)]),
           translation=linear([F(1, 2), F(1, 2), 3], [F(1, 2), F(1, 2), F(5, 4)])),
      body("M2", balls([[0, 0, 0]], [1]), translation=linear([-3, F(1, 2), F(1, 2)], [-1, F(1, 2), F(1, 2)]))],
     "any")


# two first pairs at the same time t = 1/2: the ball B (radius 1/2, centre
# (1/2, 1/3, 5/2 - 2t)) lands inside A's top triangle 2, and C's apex (-1 + 2t, 1/3, 1/4)
# enters A's side x = 0 inside triangle 8 = [0, 4, 2] (y + z = 7/12 < 1). Both go on into
# A, where C's edge meets the ball later (t = 0.79..., a root of 1892t^2 - 3642t + 1697).
case(MB, "two-first-pairs-simultaneous",
     [body("A", cube()),
      body("B", balls([[F(1, 2), F(1, 3), 0]], [F(1, 2)]), translation=[[0], [0], [F(5, 2), -2]]),
      body("C", tet([0, F(1, 3), F(1, 4)], [[-1, 0, 0], [-1, 1, 0], [-1, 0, 1]]),
           translation=[[-1, 2], [0], [0]])],
     F(1, 2), pairs=[["A", "B"], ["A", "C"], ["B", "C"]],
     feat=vt("A", "B", ("triangle", 2), ("sphere", 0)) + vt("A", "C", ("triangle", 8), ("vertex", 0)))

# ----- motions: non-unit quaternions, high-degree translations, screws
MO = "motions"

# vertex-face-grazing-rotation with the quaternion multiplied by 2: (2, 2t - 1, 0, 0).
case(MO, "nonunit-quaternion-scaled-grazing",
     [body("A", BIG_TRI), body("B", tet(*TET_PIN), translation=still([0, 0, 1]),
                               rotation=about([1, 0, 0], F(-1, 2), F(1, 2), scale=2))],
     F(1, 2), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))

# a degree-2 quaternion (1 + t^2, t, 0, t/2) turning a cube that falls onto a plate.
case(MO, "nonunit-quaternion-degree2",
     [body("A", plate(0, -3, 3, -3, 3)),
      body("B", cube([F(-1, 2), F(-1, 2), F(-1, 2)]), translation=[[0], [0], [2, -2]],
           rotation=[[1, 0, 1], [0, 1], [0], [0, F(1, 2)]])],
     "any")

# apex height above the plate (1 - 3t)^3: a triple root at t = 1/3 (degree 3 translation).
case(MO, "translation-degree3-triple-root",
     [body("A", plate()), body("B", tet([F(1, 3), F(1, 4), 0], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]),
                               translation=[[0], [0], pmul(pmul([1, -3], [1, -3]), [1, -3])])],
     F(1, 3), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))

# apex height t^4 - 4t + 1: its root in (0, 1) (0.2541...) is irrational (irreducible quartic).
case(MO, "translation-degree4-irrational",
     [body("A", plate()), body("B", tet([F(1, 3), F(1, 4), 0], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]),
                               translation=[[0], [0], [1, -4, 0, 0, 1]])],
     ("irr", [1, -4, 0, 0, 1], F(25, 100), F(26, 100)),
     feat=vt("A", "B", ("triangle", 0), ("vertex", 0)), options={"time_tolerance": "1e-20"})

# apex height (2/5 - t)(t^4 + 1) (degree 5): first root t = 2/5; the x, y path is cubic.
case(MO, "translation-degree5",
     [body("A", plate(0, -2, 2, -2, 2)),
      body("B", tet([0, 0, 0], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]),
           translation=[[0, 1, 0, -1], [0, 0, F(1, 2)], pmul([F(2, 5), -1], [1, 0, 0, 0, 1])])],
     F(2, 5), feat=vt("A", "B", ("triangle", 1), ("vertex", 0)))

# screw about z (tau = t) advancing -t/2 along z: B's tip (1, 0, 0) is at
# (cos th, sin th, -t/2); it reaches the wall y = 1/2 at sin th = 2t/(1 + t^2) = 1/2,
# t = 2 - sqrt(3) (t^2 - 4t + 1 = 0); the rest of B trails behind (y < 0 until th > 90).
case(MO, "screw-tip-hits-wall-irrational",
     [body("A", mesh([[0, F(1, 2), -3], [3, F(1, 2), -3], [0, F(1, 2), 3]], [[0, 1, 2]])),
      body("B", tet([1, 0, 0], [[0, F(-1, 4), 0], [0, F(-1, 4), F(1, 2)], [F(-1, 4), F(-1, 4), F(1, 4)]]),
           translation=[[0], [0], [0, F(-1, 2)]], rotation=about([0, 0, 1], 0, 1))],
     ("irr", [1, -4, 1], F(26, 100), F(27, 100)), feat=vt("A", "B", ("triangle", 0), ("vertex", 0)))

# screw about z through the plate's centre, advancing down: the apex (1/4, 0, 2 - 4t) is on
# the axis' circle of radius 1/4 and touches the plate z = 0 at t = 1/2 whatever the turn.
case(MO, "screw-onto-plate-rational",
     [body("A", plate(0, -1, 1, -1, 1)),
      body("B", tet([F(1, 4), 0, 0], [[F(1, 4), 0, 1], [-1, 0, 1], [0, 1, 1]]),
           translation=[[0], [0], [2, -4]], rotation=about([0, 0, 1], -1, 2))],
     F(1, 2))

# a screw with a quadratic advance along the tilted axis (1, 1, 1) through the origin.
case(MO, "screw-tilted-axis-quadratic-advance",
     [body("A", cube([1, 1, 1])),
      body("B", octahedron([0, 0, 0], F(1, 2)), translation=[[0, 0, 1], [0, 0, 1], [0, 0, 1]],
           rotation=about([1, 1, 1], 0, 1))],
     "any")

# a quaternion with all four parts of degree 1, non-unit, and a quartic translation.
case(MO, "general-quaternion-quartic-translation",
     [body("A", octahedron([0, 0, 0], 1)),
      body("B", cube([F(-1, 2), F(-1, 2), F(-1, 2)]),
           translation=[[3, 0, 0, 0, -2], [0, 1, -1], [0]],
           rotation=[[3, -1], [1, 2], [0, 1], [-1, 1]])],
     "any")


# apex height (t^2 - t + 1/5)^2 (degree 4): a double root at t = (1 - 1/sqrt(5))/2 =
# 0.27639..., root of 5t^2 - 5t + 1: grazing at an irrational time.
case(MO, "translation-degree4-irrational-double-root",
     [body("A", plate()), body("B", tet([F(1, 3), F(1, 4), 0], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]),
                               translation=[[0], [0], pmul([F(1, 5), -1, 1], [F(1, 5), -1, 1])])],
     ("irr", [1, -5, 5], F(27, 100), F(28, 100)),
     feat=vt("A", "B", ("triangle", 0), ("vertex", 0)), options={"time_tolerance": "1e-24"})


# Regression (bug found in review of issue 4): boxes.cpp's enclose_pose read
# Pose_piece::orad before setting it when W = |r|^2 was not certainly positive on a time
# piece (valgrind). r(t) = (1 - 2t, 0, 0, 1/1000) turns the cube by almost a half turn
# about z through t = 1/2, where W = (1 - 2t)^2 + 10^-6 is tiny, while it falls onto the
# plate; its bottom z = 2 - 3t reaches the plate at t = 2/3 (rotations about z keep z).
case(MO, "bug-boxes-pose-unset-offset-radius",
     [body("A", plate(0, -3, 3, -3, 3)),
      body("B", cube([F(-1, 2), F(-1, 2), 0]), translation=[[0], [0], [2, -3]],
           rotation=[[1, -2], [0], [0], [F(1, 1000)]])],
     F(2, 3))



# Fuzz findings (tests/fuzz): the boxes and bvh broad phases split time pieces 2^24 times
# when the motion's spread never fell below the other body's feature size (a body of
# point-triangles next to a 20,000-unit triangle; coordinates up to 2e36, whose rounding
# slack floors the spread); fixed by boxes::spread_stalled. The scenes are the fuzzers'
# inputs as written (tests/fuzz/crashes/scenes/); the hand answers: the cubes A and B
# touch along x = 1 at t = 0; in the second, the mutated body C still touches B and D.
def fuzz_scene(name):
    with open(os.path.join(TESTS, "fuzz", "crashes", "scenes", name + ".json")) as fh:
        return json.load(fh)["bodies"]


case(MB, "fuzz-spread-floor-degenerate-triangles", fuzz_scene("spread-floor-degenerate-triangles"),
     F(0), pairs=[["A", "B"]])
case(MB, "fuzz-spread-floor-huge-coordinates", fuzz_scene("spread-floor-huge-coordinates"),
     F(0), pairs=[["A", "B"], ["B", "C"], ["C", "D"]])

# ---------------------------------------------------------------- building files

def expectation(res, n_bodies):
    exp = {"collides": res.collides}
    if res.collides:
        t = res.first
        if isinstance(t, F):
            exp["first_contact"] = fraction_str(t)
        else:
            lo, hi = t.enclosure(ENCLOSURE, denominator=10 ** 22)
            exp["first_contact"] = [decimal_str(lo), decimal_str(hi)]
    if n_bodies > 2:
        exp["pairs"] = [[res.bodies[i].name, res.bodies[j].name] for (i, j) in sorted(res.pairs)]
    feats = OB.unambiguous_features(res)
    if feats:
        exp["features"] = feats
    return exp


def check_want(c, res):
    want, name = c["want"], c["category"] + "/" + c["name"]
    if want is None:
        ok = not res.collides
    elif want == "any":
        ok = True
    elif isinstance(want, tuple) and want[0] == "irr":
        _, poly, lo, hi = want
        t = res.first
        ok = res.collides and not isinstance(t, F)
        if ok:
            coeffs = [int(x) for x in t.f.coeffs()]
            ok = coeffs == list(poly) or coeffs == [-x for x in poly]
            ok = ok and time_strictly_in(t, lo, hi)
    else:
        ok = res.collides and isinstance(res.first, F) and res.first == F(want)
    if not ok:
        raise SystemExit("%s: oracle says %r, hand answer %r" % (name, res, want))
    if c["pairs"] is not None:
        got = [[res.bodies[i].name, res.bodies[j].name] for (i, j) in sorted(res.pairs)]
        if got != c["pairs"]:
            raise SystemExit("%s: oracle pairs %r, hand answer %r" % (name, got, c["pairs"]))
    if c["feat"] is not None:
        got = OB.unambiguous_features(res)
        if got != c["feat"]:
            raise SystemExit("%s: oracle features %r (touching %r), hand answer %r"
                             % (name, got, [p.touching for p in res.pair_list], c["feat"]))


def scene_doc(c):
    doc = {"format": "polyccd/1", "name": c["name"], "source": SOURCE, "bodies": c["bodies"]}
    if c["options"]:
        doc["options"] = c["options"]
    return doc


def render(doc):
    """Stable JSON text: one line per body, Raw numbers written as JSON numbers."""
    def enc(x):
        if isinstance(x, Raw):
            return str(x)
        if isinstance(x, dict):
            return "{" + ", ".join("%s: %s" % (json.dumps(k), enc(v)) for k, v in x.items()) + "}"
        if isinstance(x, list):
            return "[" + ", ".join(enc(v) for v in x) + "]"
        return json.dumps(x)
    lines = []
    for k, v in doc.items():
        if k == "bodies":
            lines.append('  "bodies": [\n%s\n  ]' % ",\n".join("    " + enc(b) for b in v))
        else:
            lines.append("  %s: %s" % (json.dumps(k), enc(v)))
    return "{\n" + ",\n".join(lines) + "\n}\n"


def build(c):
    doc = scene_doc(c)
    # the oracle reads the text it will be compared against (exact numbers as in the file)
    parsed = json.loads(render(doc), parse_float=__import__("decimal").Decimal)
    res = OB.solve_scene(parsed)
    check_want(c, res)
    doc["expect"] = expectation(res, len(c["bodies"]))
    return render(doc), res


def all_files(timings=None):
    files = {}
    for c in CASES:
        t0 = time.perf_counter()
        text, _ = build(c)
        if timings is not None:
            timings[c["category"] + "/" + c["name"]] = time.perf_counter() - t0
        rel = os.path.join(c["category"], c["name"] + ".json")
        if rel in files:
            raise SystemExit("duplicate case " + rel)
        files[rel] = text
    return files


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=OUT)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--times", action="store_true")
    args = ap.parse_args()
    timings = {}
    t0 = time.perf_counter()
    files = all_files(timings)
    total = time.perf_counter() - t0
    stale = []
    for rel, text in sorted(files.items()):
        path = os.path.join(args.out, rel)
        old = open(path).read() if os.path.exists(path) else None
        if old != text:
            stale.append(rel)
            if not args.check:
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w") as fh:
                    fh.write(text)
    if args.times:
        for k, v in sorted(timings.items(), key=lambda kv: -kv[1]):
            print("%7.2fs  %s" % (v, k))
    print("%d cases in %.1fs, %d %s" % (len(files), total, len(stale),
                                        "differ from this script" if args.check else "written"))
    if args.check and stale:
        print("\n".join(stale))
        sys.exit(1)


if __name__ == "__main__":
    main()
