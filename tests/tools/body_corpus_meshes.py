"""The mesh-mesh cases of the body corpus (make_body_corpus.py): each a scene, the
answer reasoned out by hand in the comment next to it."""
from fractions import Fraction as F   # noqa: F401  (the cases' numbers)

from body_corpus_shapes import *   # noqa: F401,F403  (the cases' vocabulary)


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

# Issue 31 (the range phase's static pass at t = 0 searches the query side's edges only
# against stored triangles near a query triangle: lib/range/range_index.cpp,
# near_at_zero): three parallel needles (long thin triangles in the planes x = z + 2k,
# k = 0, 1, 2) and a spike whose edge Q0 Q1 passes through (4, 1/4, 2), inside needle 1
# (x = z + 2, 0 <= y <= 1 - z/10) at t = 0; the needles' edges miss the spike, so only the search
# over the spike's edges finds the contact. First contact t = 0.
NEEDLES3 = mesh([[0, 0, 0], [10, 0, 10], [0, 1, 0], [2, 0, 0], [12, 0, 10], [2, 1, 0],
                 [4, 0, 0], [14, 0, 10], [4, 1, 0]], [[0, 1, 2], [3, 4, 5], [6, 7, 8]])
SPIKE = mesh([["4.5", "0.25", "1.5"], ["3.5", "0.25", "2.5"], ["3.5", "0.3125", "2.5"]],
             [[0, 1, 2]])
case(MM, "range-static-pass-spike-through-needle",
     [body("needles", NEEDLES3), body("spike", SPIKE, translation=[[0, 0], [0, 1], [0, 0]])],
     F(0))
