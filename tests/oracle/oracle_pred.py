"""Contact predicates of the test oracle, one per kind, written directly from the
geometry of closed sets (formats.md, "Meaning of a contact").

A predicate decides contact at ONE time tau. All arithmetic is done on polynomials of t
(the coordinates are polynomials, so every derived quantity is too); the only place the
time enters is `ev.sign(p)`, the exact sign of p(tau). The predicates branch on these
signs (degenerate triangle? parallel edges?), and the driver (tests/oracle/oracle.py) records
every polynomial whose sign was asked, which is what makes the answer piecewise constant
between the roots of those polynomials.

Point indices follow formats.md: vertex-face v, f0, f1, f2; edge-edge a0, a1, b0, b1;
vertex-edge v, e0, e1; vertex-vertex a, b; sphere-sphere ca, cb.
"""
from flint import fmpq_poly


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


class Traj:
    """The coordinate polynomials of a query's points, with memoised derived
    polynomials (so that one polynomial object stands for one quantity)."""

    def __init__(self, points, radii=None):
        # points: [[xs, ys, zs], ...] with Fraction coefficients (ascending powers)
        self.P = [tuple(_poly(c) for c in pt) for pt in points]
        self.radii = radii
        self._memo = {}

    def memo(self, key, fn):
        v = self._memo.get(key)
        if v is None:
            v = self._memo[key] = fn()
        return v

    def d(self, i, j):
        """P_j - P_i."""
        return self.memo(("d", i, j), lambda: vsub(self.P[j], self.P[i]))


def _poly(coeffs):
    from oracle_alg import to_fmpq
    return fmpq_poly([to_fmpq(c) for c in coeffs])


def _all_zero(ev, vec):
    return all(ev.sign(c) == 0 for c in vec)


def same_point(T, ev, i, j):
    return _all_zero(ev, T.d(i, j))


def point_in_segment(T, ev, p, a, b):
    """Point p in the closed segment [a, b] (a point when a == b)."""
    if same_point(T, ev, a, b):
        return same_point(T, ev, a, p)
    # on the line: (b - a) x (p - a) == 0; between: (p-a).(b-a) >= 0 and (p-b).(a-b) >= 0
    cr = T.memo(("seg-cross", p, a, b), lambda: vcross(T.d(a, b), T.d(a, p)))
    if not _all_zero(ev, cr):
        return False
    da = T.memo(("seg-dot", p, a, b), lambda: vdot(T.d(a, p), T.d(a, b)))
    if ev.sign(da) < 0:
        return False
    db = T.memo(("seg-dot", p, b, a), lambda: vdot(T.d(b, p), T.d(b, a)))
    return ev.sign(db) >= 0


def point_in_triangle(T, ev, p, a, b, c):
    """Point p in the closed triangle (a, b, c), which may be degenerate."""
    n = T.memo(("tri-normal", a, b, c), lambda: vcross(T.d(a, b), T.d(a, c)))
    if _all_zero(ev, n):
        # collinear or coincident vertices: the triangle is the convex hull of three
        # collinear points, i.e. the union of its three closed edges
        return (point_in_segment(T, ev, p, a, b) or point_in_segment(T, ev, p, b, c)
                or point_in_segment(T, ev, p, c, a))
    plane = T.memo(("tri-plane", p, a, b, c), lambda: vdot(n, T.d(a, p)))
    if ev.sign(plane) != 0:
        return False
    # in the plane: inside the closed triangle iff on the inner side (w.r.t. n) of
    # each directed edge, the triangle being counter-clockwise around n
    for (u, w) in ((a, b), (b, c), (c, a)):
        side = T.memo(("tri-side", p, u, w, a, b, c),
                      lambda: vdot(vcross(T.d(u, w), T.d(u, p)), n))
        if ev.sign(side) < 0:
            return False
    return True


def segments_meet(T, ev, a0, a1, b0, b1):
    """Closed segments [a0, a1] and [b0, b1] (either may be a point) share a point."""
    da, db = T.d(a0, a1), T.d(b0, b1)
    n = T.memo(("ee-normal", a0, a1, b0, b1), lambda: vcross(da, db))
    if _all_zero(ev, n):
        # parallel directions, or a segment is a point: the segments meet iff an
        # endpoint of one lies in the other (their intersection, when not empty, is a
        # segment of their common line whose ends are endpoints of the two)
        return (point_in_segment(T, ev, a0, b0, b1) or point_in_segment(T, ev, a1, b0, b1)
                or point_in_segment(T, ev, b0, a0, a1) or point_in_segment(T, ev, b1, a0, a1))
    r = T.d(a0, b0)
    plane = T.memo(("ee-plane", a0, a1, b0, b1), lambda: vdot(r, n))
    if ev.sign(plane) != 0:
        return False
    # coplanar, non-parallel lines meet at a0 + s da = b0 + u db with
    # s = ((r x db) . n) / |n|^2 and u = ((r x da) . n) / |n|^2; need s, u in [0, 1]
    nn = T.memo(("ee-nn", a0, a1, b0, b1), lambda: vdot(n, n))
    s = T.memo(("ee-s", a0, a1, b0, b1), lambda: vdot(vcross(r, db), n))
    u = T.memo(("ee-u", a0, a1, b0, b1), lambda: vdot(vcross(r, da), n))
    for name, num in (("s", s), ("u", u)):
        if ev.sign(num) < 0:
            return False
        if ev.sign(T.memo(("ee-gap", name, a0, a1, b0, b1), lambda: nn - num)) < 0:
            return False
    return True


def balls_meet(T, ev, ca, cb):
    """Closed balls: |ca - cb|^2 <= (ra + rb)^2."""
    def slack():
        d = T.d(ca, cb)
        rs = T.radii[0] + T.radii[1]
        return _poly([rs * rs]) - vdot(d, d)
    return ev.sign(T.memo(("ball-slack", ca, cb), slack)) >= 0


def contact(kind, T, ev):
    """Contact of the query's primitives at the time behind `ev`."""
    if kind == "vertex-face":
        return point_in_triangle(T, ev, 0, 1, 2, 3)
    if kind == "edge-edge":
        return segments_meet(T, ev, 0, 1, 2, 3)
    if kind == "vertex-edge":
        return point_in_segment(T, ev, 0, 1, 2)
    if kind == "vertex-vertex":
        return same_point(T, ev, 0, 1)
    if kind == "sphere-sphere":
        return balls_meet(T, ev, 0, 1)
    raise ValueError("unknown kind %r" % (kind,))
