# Bodies on motions: a ball rolling into a cube's face.
from fractions import Fraction
import polyccd

cube = polyccd.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]],
                    [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                     [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
ball = polyccd.Spheres([[3, "1/2", "1/2"]], ["1/2"])       # centre, radius
# The ball's centre x(t) = 3 - 2t reaches 3/2 (touching the face
# x = 1 at its centre (1, 1/2, 1/2), on the diagonal edge of that face) at t = 3/4.
moving = polyccd.Body(ball, polyccd.Motion.linear([0, 0, 0], [-2, 0, 0]), name="ball")
r = polyccd.check([polyccd.Body(cube, name="cube"), moving], threads=2)
assert r.collides and r.first_contact.exact == Fraction(3, 4)
print(r.first_contact.exact, [(c.a, c.b) for c in r.pairs[0].contacts])

# Prints:
#   3/4 [(('edge', 10), ('sphere', 0))]
