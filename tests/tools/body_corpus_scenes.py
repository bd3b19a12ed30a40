"""The body corpus cases of several bodies and of unusual motions (make_body_corpus.py):
multi-body scenes, non-unit quaternions, high-degree translations, screws, and the
scenes the fuzzers found; each answer reasoned out by hand next to it."""
import json
import os
from fractions import Fraction as F   # noqa: F401  (the cases' numbers)

from body_corpus_shapes import *   # noqa: F401,F403  (the cases' vocabulary)

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
