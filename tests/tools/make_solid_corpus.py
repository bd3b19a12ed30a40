"""Builds corpus/solids/<name>.json (polyccd/1 scenes with solid meshes, "solid": true)
whose expectations come from the independent solid oracle (tests/oracle/oracle_solid.py:
exact ray parity in Fractions over the surface oracle), never from polyccd.

    python tests/tools/make_solid_corpus.py [--check]

Every case carries the answer reasoned out by hand (`want`: the first contact, or None
for no contact); the script stops when the oracle disagrees. --check only verifies
that the files on disk are what this script writes.
"""
import argparse
import json
import os
import sys
from fractions import Fraction as F

TESTS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(TESTS, "oracle"))
import oracle_solid               # noqa: E402
from oracle import fraction_str   # noqa: E402

SOURCE = "tests/tools/make_solid_corpus.py (oracle: tests/oracle/oracle_solid.py)"
OUT = os.path.join(TESTS, "..", "corpus", "solids")

# The 12 outward triangles of the box whose corner i has the signs of the bits of i
# (polyccd.Mesh.box's order; the diagonal 3-5 of face x = + passes through (h, 0, 0)).
BOX_TRIS = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
            [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]


def js(x):
    """A number for JSON: an int, or an exact fraction string."""
    x = F(x)
    return int(x) if x.denominator == 1 else "%d/%d" % (x.numerator, x.denominator)


def box(h, c=(0, 0, 0), inward=False):
    """(vertices, triangles) of the box of half extents h (a number or 3) about c."""
    h = [F(x) for x in h] if isinstance(h, (list, tuple)) else [F(h)] * 3
    c = [F(x) for x in c]
    v = [[c[k] + (h[k] if i >> k & 1 else -h[k]) for k in range(3)] for i in range(8)]
    return v, [t[::-1] for t in BOX_TRIS] if inward else [list(t) for t in BOX_TRIS]


def union(*parts):
    verts, tris = [], []
    for v, t in parts:
        tris += [[k + len(verts) for k in tri] for tri in t]
        verts += v
    return verts, tris


def prism(poly, z0, z1, fan_from=0):
    """The closed prism over a counter-clockwise polygon (star-shaped from vertex
    fan_from), outward triangles."""
    n = len(poly)
    v = [[x, y, z0] for x, y in poly] + [[x, y, z1] for x, y in poly]
    t = []
    for i in range(n):
        j = (i + 1) % n
        t += [[i, j, n + j], [i, n + j, n + i]]
    for k in range(1, n - 1):
        a, b = (fan_from + k) % n, (fan_from + k + 1) % n
        t += [[fan_from, b, a], [n + fan_from, n + a, n + b]]
    return v, t


def ring(outer, inner, z0, z1):
    """A square ring (a torus of genus 1): the prism over the square of half side outer
    minus the square of half side inner, outward triangles; checked closed and
    consistently oriented here (every directed edge once, its reverse once)."""
    corners = [(1, 1), (-1, 1), (-1, -1), (1, -1)]            # counter-clockwise
    v = [[F(a) * outer, F(b) * outer, F(z)] for z in (z0, z1) for a, b in corners]
    v += [[F(a) * inner, F(b) * inner, F(z)] for z in (z0, z1) for a, b in corners]
    o = lambda i, top: (i % 4) + 4 * top                        # noqa: E731
    n = lambda i, top: 8 + (i % 4) + 4 * top                    # noqa: E731
    t = []
    for i in range(4):
        t += [[o(i, 1), o(i + 1, 1), n(i + 1, 1)], [o(i, 1), n(i + 1, 1), n(i, 1)]]   # top, +z
        t += [[o(i, 0), n(i + 1, 0), o(i + 1, 0)], [o(i, 0), n(i, 0), n(i + 1, 0)]]   # bottom
        t += [[o(i, 0), o(i + 1, 0), o(i + 1, 1)], [o(i, 0), o(i + 1, 1), o(i, 1)]]   # outer wall
        t += [[n(i, 0), n(i + 1, 1), n(i + 1, 0)], [n(i, 0), n(i, 1), n(i + 1, 1)]]   # inner wall
    directed = [(tri[k], tri[(k + 1) % 3]) for tri in t for k in range(3)]
    assert len(set(directed)) == len(directed) and all((b, a) in set(directed) for a, b in directed)
    return v, t


OCTAHEDRON = ([[2, 0, 0], [-2, 0, 0], [0, 2, 0], [0, -2, 0], [0, 0, 2], [0, 0, -2]],
              [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
TETRA = lambda a, b, c, d: ([a, b, c, d], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])  # noqa: E731
L_SHAPE = prism([(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)], 0, 2, fan_from=3)


def mesh(name, vt, motion=None, solid=False):
    body = {"name": name, "mesh": {"vertices": [[js(x) for x in v] for v in vt[0]],
                                   "triangles": vt[1]}}
    if solid:
        body["solid"] = True
    if motion:
        body["motion"] = motion
    return body


def spheres(name, centers, radii, motion=None):
    body = {"name": name, "spheres": {"centers": [[js(x) for x in c] for c in centers],
                                      "radii": [js(r) for r in radii]}}
    if motion:
        body["motion"] = motion
    return body


def lin(p0, p1):
    p0, p1 = [F(x) for x in p0], [F(x) for x in p1]
    return {"translation": [[js(a), js(b - a)] if a != b else [js(a)] for a, b in zip(p0, p1)]}


BIG = box(2)
CASES = []


def case(name, bodies, want):
    CASES.append((name, bodies, want))


# A box inside a box: t = 0 as solids, never as surfaces (1 x 1 moves 0.5 inside 4 x 4).
case("box-inside-solid-box", [mesh("big", BIG, solid=True), mesh("small", box("1/2"), lin([0, 0, 0], ["1/2", 0, 0]))], F(0))
case("box-inside-surface-box", [mesh("big", BIG), mesh("small", box("1/2"), lin([0, 0, 0], ["1/2", 0, 0]))], None)
case("solid-box-inside-solid-box", [mesh("small", box("1/2"), lin([0, 0, 0], [0, "1/2", 0]), solid=True), mesh("big", BIG, solid=True)], F(0))
# Touching at t = 0: faces on x = 2 from outside and from inside (surface contacts).
case("boxes-touching-outside-at-t0", [mesh("big", BIG, solid=True), mesh("small", box("1/2", ["5/2", 0, 0]), lin([0, 0, 0], [1, 0, 0]))], F(0))
case("box-touching-inner-face-at-t0", [mesh("big", BIG, solid=True), mesh("small", box("1/2", ["3/2", 0, 0]), lin([0, 0, 0], [-1, 0, 0]))], F(0))
# A tetrahedron's vertex exactly on the solid's face / edge / vertex at t = 0, moving away
# (from outside), or inside and moving inwards.
case("vertex-on-face-at-t0-outside", [mesh("big", BIG, solid=True), mesh("tet", TETRA([2, "1/2", "3/10"], [3, 0, 0], [3, 1, 0], [3, 0, 1]), lin([0, 0, 0], [1, 0, 0]))], F(0))
case("vertex-on-edge-at-t0-outside", [mesh("big", BIG, solid=True), mesh("tet", TETRA([2, 2, "3/10"], [3, 3, 0], [3, 4, 0], [4, 3, 1]), lin([0, 0, 0], [1, 1, 0]))], F(0))
case("vertex-on-vertex-at-t0-outside", [mesh("big", BIG, solid=True), mesh("tet", TETRA([2, 2, 2], [3, 3, 3], [4, 3, 3], [3, 3, 4]), lin([0, 0, 0], [1, 1, 1]))], F(0))
case("vertex-on-face-at-t0-inside", [mesh("big", BIG, solid=True), mesh("tet", TETRA([2, "1/2", "3/10"], [1, 0, 0], [1, 1, 0], [1, 0, 1]), lin([0, 0, 0], [-1, 0, 0]))], F(0))
# Leaving through the wall: inside at t = 0, so 0. Entering: the surface time,
# x = 5 - 5t - 1/2 = 2 at t = 1/2.
case("box-leaves-through-wall", [mesh("big", BIG, solid=True), mesh("small", box("1/2"), lin([0, 0, 0], [5, 0, 0]))], F(0))
case("box-enters-from-outside", [mesh("big", BIG, solid=True), mesh("small", box("1/2"), lin([5, 0, 0], [0, 0, 0]))], F(1, 2))
# A non-convex solid (L-shaped prism over [0, 4]^2 minus (2, 4]^2, z in [0, 2]): a box
# in the notch, inside the hull but outside the solid, moving within it: none; a box in
# the arm: 0.
case("l-shape-box-in-notch", [mesh("L", L_SHAPE, solid=True), mesh("small", box("1/4", [3, 3, 1]), lin([0, 0, 0], ["1/2", "1/2", 0]))], None)
case("l-shape-box-in-arm", [mesh("L", L_SHAPE, solid=True), mesh("small", box("1/4", [3, 1, 1]), lin([0, 0, 0], ["1/2", 0, 0]))], F(0))
# A hollow solid (outer box outward, inner box inward: winding 0 in the cavity): a box
# in the cavity, none; a box in the wall, 0.
HOLLOW = union(box(2), box(1, inward=True))
case("hollow-box-in-cavity", [mesh("shell", HOLLOW, solid=True), mesh("small", box("1/4"), lin([0, 0, 0], ["1/2", 0, 0]))], None)
case("hollow-box-in-wall", [mesh("shell", HOLLOW, solid=True), mesh("small", box("1/4", ["3/2", 0, 0]), lin([0, 0, 0], [0, "1/4", 0]))], F(0))
# A torus-like solid (square ring: [-2, 2]^2 minus (-1, 1)^2, z in [0, 1]): a box in the
# hole, inside the hull but outside the solid: none; a box in the ring: 0.
RING = ring(2, 1, 0, 1)
case("ring-box-in-hole", [mesh("ring", RING, solid=True), mesh("small", box("1/4", [0, 0, "1/2"]), lin([0, 0, 0], ["1/4", "1/4", 0]))], None)
case("ring-box-in-ring", [mesh("ring", RING, solid=True), mesh("small", box("1/4", ["3/2", 0, "1/2"]), lin([0, 0, 0], [0, 1, 0]))], F(0))
# Degenerate rays: a ball at the box's centre (the +x ray meets the diagonal 3-5), at the
# octahedron's centre (through its vertex (2, 0, 0)); a ball whose +x ray runs in the
# plane of the face y = 2, outside: none.
case("ball-at-centre-ray-on-diagonal", [mesh("big", BIG, solid=True), spheres("ball", [[0, 0, 0]], ["1/2"])], F(0))
case("ball-in-octahedron-ray-through-vertex", [mesh("oct", OCTAHEDRON, solid=True), spheres("ball", [[0, 0, 0]], ["1/4"], lin([0, 0, 0], [0, "1/4", 0]))], F(0))
case("ball-outside-ray-in-face-plane", [mesh("big", BIG, solid=True), spheres("ball", [[-3, 2, 0]], ["1/2"])], None)
# Frames at t = 0: a thin box (4 x 1/2 x 1/2) turned a quarter about z at t = 0
# (quaternion (1, 0, 0, 1)) lies along y: a ball at (0, 3/2, 0) is inside, one at
# (3/2, 0, 0) outside; the rod also moves up by 1/10.
ROD = box([2, "1/4", "1/4"])
TURNED = {"rotation": [[1], [0], [0], [1, "1/5"]], "translation": [[0], [0], [0, "1/10"]]}
case("turned-rod-holds-ball", [mesh("rod", ROD, TURNED, solid=True), spheres("ball", [[0, "3/2", 0]], ["1/10"])], F(0))
case("turned-rod-misses-ball", [mesh("rod", ROD, TURNED, solid=True), spheres("ball", [["3/2", 0, 0]], ["1/10"])], None)
# One vertex per surface component: a mesh of two boxes, the first (vertex 0) outside
# the solid, the second inside: 0. An unused vertex inside is not the body: none.
case("two-components-second-inside", [mesh("big", BIG, solid=True), mesh("pair", union(box("1/4", [5, 0, 0]), box("1/4")), lin([0, 0, 0], [0, 0, "1/2"]))], F(0))
case("unused-vertex-inside", [mesh("big", BIG, solid=True), mesh("tri", ([[0, 0, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0]], [[1, 2, 3]]))], None)
# Three bodies: a ball inside the solid box, a surface box far away.
case("three-bodies-ball-inside", [mesh("big", BIG, solid=True), spheres("ball", [[1, 1, 1]], ["1/2"]), mesh("far", box("1/2", [10, 0, 0]))], F(0))


def build(name, bodies, want):
    doc = {"format": "polyccd/1", "name": name, "source": SOURCE, "bodies": bodies}
    ans = oracle_solid.solve(doc)
    got = ans.first if ans.collides else None
    if got != want:
        raise SystemExit("%s: the oracle says %r, the case wants %r" % (name, got, want))
    names = [b["name"] for b in bodies]
    exp = {"collides": ans.collides}
    if ans.collides:
        exp["first_contact"] = fraction_str(ans.first)
        exp["pairs"] = [[names[i], names[j]] for i, j in sorted(ans.pairs)]
    doc["expect"] = exp
    lines = ["{", '  "format": "polyccd/1",', '  "name": %s,' % json.dumps(name),
             '  "source": %s,' % json.dumps(SOURCE), '  "bodies": [']
    lines.append(",\n".join("    " + json.dumps(b) for b in bodies))
    lines += ["  ],", '  "expect": %s' % json.dumps(exp), "}"]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    bad = 0
    for name, bodies, want in CASES:
        text = build(name, bodies, want)
        path = os.path.join(OUT, name + ".json")
        if args.check:
            with open(path) as fh:
                bad += fh.read() != text
        else:
            with open(path, "w") as fh:
                fh.write(text)
    print("%d cases%s" % (len(CASES), ", %d differ" % bad if args.check else ""))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
