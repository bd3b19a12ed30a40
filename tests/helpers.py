"""Helpers the Python tests share (one copy each; tests import them by plain name, as
tests/ is on sys.path under pytest): axis-aligned boxes as meshes, and a SceneResult as
comparable values. Nothing here decides an answer: these build inputs and compare
outputs."""
import polyccd as P

# The 12 triangles of a box whose vertex i has bit a of i pick the low (0) or high (1)
# coordinate on axis a; every face outward.
BOX_TRIANGLES = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                 [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]


def box(lo, hi):
    """The axis-aligned box [lo, hi] as a Mesh of 12 triangles (numbers as given)."""
    return P.Mesh([[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)],
                  BOX_TRIANGLES)


def cube(lo, side):
    """The cube of low corner lo and the given side."""
    return box(lo, [x + side for x in lo])


def summary(r):
    """Everything a SceneResult says (stats aside), as comparable values: collides, the
    first contact's enclosure and exact value, every pair in contact (indices, names,
    time, contacts) and the first pairs."""
    def t(ct):
        return None if ct is None else (ct.lo, ct.hi, ct.exact)
    return (r.collides, t(r.first_contact),
            tuple((p.bodies, p.names, t(p.first_contact),
                   tuple((c.a, c.b, t(c.first_contact)) for c in p.contacts)) for p in r.pairs),
            tuple(p.bodies for p in r.first))
