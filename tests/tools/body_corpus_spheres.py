"""The cases of the body corpus with ball sets (make_body_corpus.py): spheres-spheres
and spheres-mesh, each answer reasoned out by hand in the comment next to it."""
from fractions import Fraction as F   # noqa: F401  (the cases' numbers)

from body_corpus_shapes import *   # noqa: F401,F403  (the cases' vocabulary)


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
