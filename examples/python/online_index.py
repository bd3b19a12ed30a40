# One body preprocessed once, then many query bodies against it (the on-line problem).
from fractions import Fraction
import polyccd

# The on-line problem: one body preprocessed once, then any number of queries.
plate = polyccd.Mesh([[-4, -4, 0], [4, -4, 0], [-4, 4, 0], [4, 4, 0]], [[0, 1, 3], [0, 3, 2]])
ix = polyccd.Index(polyccd.Body(plate, name="plate"))
tri = polyccd.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])   # a single triangle
# Query k falls from z = 1 + k to z = 1 - k: it reaches the plate at t = (1 + k) / (2k).
queries = [polyccd.Body(tri, polyccd.Motion.linear([k, 0, 1 + k], [k, 0, 1 - k]), name=f"q{k}")
           for k in range(3)]
results = ix.query_many(queries)
assert [r.collides for r in results] == [False, True, True]
print([str(r.first_contact.exact) for r in results if r.collides])   # ['1', '3/4']

# Prints:
#   ['1', '3/4']
