# Moving primitives: a vertex falling through a triangle, a point grazing a plane.
from fractions import Fraction
import polyccd

# A vertex falls through a static triangle in the plane z = 0.
hit = polyccd.solve_linear("vertex-face",
                           [[0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]],   # t = 0
                           [[0.25, 0.25, -1], [0, 0, 0], [1, 0, 0], [0, 1, 0]])  # t = 1
assert hit.collides and hit.first_contact.exact == Fraction(1, 2)
# A point on a parabola grazing the plane z = 0 at t = 1/3: z(t) = (3t - 1)^2 / 9.
graze = polyccd.solve("vertex-face", [[["1/4"], ["1/4"], ["1/9", "-2/3", 1]],
                                      [[0], [0], [0]], [[1], [0], [0]], [[0], [1], [0]]])
print(graze.first_contact.exact, graze.features)  # 1/3 (Feature(kind='vertex-face', ...),)

# Prints:
#   1/3 (Feature(kind='vertex-face', points=(0, 1, 2, 3)),)
