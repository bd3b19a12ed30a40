"""The geometry of one body pair for the body oracle (oracle_body.py): every
vertex-triangle, edge-edge and ball pair's first contact time (Pair), with the
conservative interval pruning over 32 time pieces (poly_range, rf_range)."""
from fractions import Fraction

from flint import fmpq_poly

from oracle_alg import to_fmpq
from oracle_body_eval import Ev
from oracle_body_scene import F0, RF, _poly, rot_matrix, vcross, vdot, vsub

PIECES = 32  # time pieces of the pruning


# ---------------------------------------------------------------- geometry of one pair

class Pair:
    """Points of bodies A and B in the body frame of A, with memoised quantities."""

    def __init__(self, A, B):
        MA, WA = rot_matrix(A.rotation)
        MB, WB = rot_matrix(B.rotation)
        den = WA * WB
        # MA^T MB and MA^T (o_B - o_A) W_B
        MAtMB = [[sum((MA[k][i] * MB[k][j] for k in range(3)), _poly([0])) for j in range(3)]
                 for i in range(3)]
        dO = [B.translation[k] - A.translation[k] for k in range(3)]
        off = [sum((MA[k][i] * dO[k] for k in range(3)), _poly([0])) * WB for i in range(3)]
        self.den = den
        self.P = {}
        self.radius = {}
        self.moving = set()
        for tag, body, const in (("A", A, True), ("B", B, False)):
            pts = body.vertices if body.kind == "mesh" else body.centers
            for k, q in enumerate(pts):
                key = (tag, k)
                if const:
                    self.P[key] = tuple(RF(_poly([c])) for c in q)
                else:
                    qq = [to_fmpq(c) for c in q]
                    self.P[key] = tuple(RF(sum((MAtMB[i][j] * qq[j] for j in range(3)), off[i]),
                                           den) for i in range(3))
                    self.moving.add(key)
            if body.kind == "spheres":
                for k, r in enumerate(body.radii):
                    self.radius[(tag, k)] = r
        self.memo = {}

    def m(self, key, fn):
        v = self.memo.get(key)
        if v is None:
            v = self.memo[key] = fn()
        return v

    def d(self, i, j):
        """P_j - P_i."""
        return self.m(("d", i, j), lambda: vsub(self.P[j], self.P[i]))

    # ----------------------------------------------------------- predicates at one time

    def zero(self, ev, vec):
        return all(ev.sign(c) == 0 for c in vec)

    def point_in_segment(self, ev, p, a, b):
        """Point p in the closed segment [a, b] (a point when a == b)."""
        if self.zero(ev, self.d(a, b)):
            return self.zero(ev, self.d(a, p))
        if not self.zero(ev, self.m(("sx", a, b, p), lambda: vcross(self.d(a, b), self.d(a, p)))):
            return False
        s = self.m(("sd", a, b, p), lambda: vdot(self.d(a, p), self.d(a, b)))
        if ev.sign(s) < 0:
            return False
        rest = self.m(("sr", a, b, p),
                      lambda: vdot(self.d(a, b), self.d(a, b)) - s)
        return ev.sign(rest) >= 0

    def point_in_triangle(self, ev, p, a, b, c):
        """Point p in the closed triangle (a, b, c), possibly degenerate."""
        n = self.m(("n", a, b, c), lambda: vcross(self.d(a, b), self.d(a, c)))
        if self.zero(ev, n):
            return (self.point_in_segment(ev, p, a, b) or self.point_in_segment(ev, p, b, c)
                    or self.point_in_segment(ev, p, a, c))
        if ev.sign(self.m(("pl", a, b, c, p), lambda: vdot(n, self.d(a, p)))) != 0:
            return False
        # barycentric numerators ((v_j - p) x (v_k - p)) . n, all >= 0 (they sum to |n|^2)
        for u, w in ((b, c), (c, a), (a, b)):
            lam = self.m(("bary", u, w, p, a, b, c),
                         lambda: vdot(vcross(self.d(p, u), self.d(p, w)), n))
            if ev.sign(lam) < 0:
                return False
        return True

    def segments_meet(self, ev, a0, a1, b0, b1):
        """Closed segments [a0, a1] and [b0, b1] share a point."""
        u, v = self.d(a0, a1), self.d(b0, b1)
        n = self.m(("en", a0, a1, b0, b1), lambda: vcross(u, v))
        if self.zero(ev, n):
            return (self.point_in_segment(ev, a0, b0, b1) or self.point_in_segment(ev, a1, b0, b1)
                    or self.point_in_segment(ev, b0, a0, a1) or self.point_in_segment(ev, b1, a0, a1))
        w = self.d(a0, b0)
        if ev.sign(self.m(("ep", a0, a1, b0, b1), lambda: vdot(w, n))) != 0:
            return False
        nn = self.m(("enn", a0, a1, b0, b1), lambda: vdot(n, n))
        # a0 + s u = b0 + r v:  s |n|^2 = (w x v).n,  r |n|^2 = (w x u).n
        for tag, other in (("s", v), ("r", u)):
            num = self.m(("e" + tag, a0, a1, b0, b1), lambda: vdot(vcross(w, other), n))
            if ev.sign(num) < 0:
                return False
            if ev.sign(self.m(("e" + tag + "1", a0, a1, b0, b1), lambda: nn - num)) < 0:
                return False
        return True

    def balls_meet(self, ev, ca, cb):
        def slack():
            d = self.d(ca, cb)
            R = self.radius[ca] + self.radius[cb]
            return RF(_poly([R * R])) - vdot(d, d)
        return ev.sign(self.m(("bb", ca, cb), slack)) >= 0

    def ball_meets_triangle(self, ev, c, a, b, cc):
        r2 = self.radius[c] ** 2
        for v in (a, b, cc):
            s = self.m(("bv", c, v), lambda: RF(_poly([r2])) - vdot(self.d(c, v), self.d(c, v)))
            if ev.sign(s) >= 0:
                return True
        for u, w in ((a, b), (b, cc), (cc, a)):
            e = self.d(u, w)
            if ev.sign(self.m(("bed", u, w, c), lambda: vdot(self.d(u, c), e))) <= 0:
                continue
            if ev.sign(self.m(("bed", w, u, c), lambda: vdot(self.d(w, c), self.d(w, u)))) <= 0:
                continue
            s = self.m(("be", c, u, w), lambda: vdot(e, e) * r2
                       - vdot(vcross(e, self.d(u, c)), vcross(e, self.d(u, c))))
            if ev.sign(s) >= 0:
                return True
        n = self.m(("n", a, b, cc), lambda: vcross(self.d(a, b), self.d(a, cc)))
        for u, w in ((a, b), (b, cc), (cc, a)):
            side = self.m(("bside", u, w, c, a, b, cc),
                          lambda: vdot(vcross(self.d(u, w), self.d(u, c)), n))
            if ev.sign(side) <= 0:
                return False
        h = self.m(("bh", c, a, b, cc), lambda: vdot(n, self.d(a, c)))
        s = self.m(("bf", c, a, b, cc), lambda: vdot(n, n) * r2 - h * h)
        return ev.sign(s) >= 0

    def face_interior_contact(self, t, c, a, b, cc):
        """At time t: the ball's centre projects strictly inside the non-degenerate
        triangle at distance exactly r from the face's plane: the nearest point of the
        triangle is then in the open face (and unique), so that is where they touch."""
        ev = Ev(t, record=False)
        n = self.m(("n", a, b, cc), lambda: vcross(self.d(a, b), self.d(a, cc)))
        if self.zero(ev, n):
            return False
        for u, w in ((a, b), (b, cc), (cc, a)):
            if ev.sign(self.m(("bside", u, w, c, a, b, cc),
                              lambda: vdot(vcross(self.d(u, w), self.d(u, c)), n))) <= 0:
                return False
        r2 = self.radius[c] ** 2
        h = self.m(("bh", c, a, b, cc), lambda: vdot(n, self.d(a, c)))
        s = self.m(("bf", c, a, b, cc), lambda: vdot(n, n) * r2 - h * h)
        return ev.sign(s) == 0

    # ----------------------------------------------------------- pruning boxes

    def boxes(self):
        """Per point: list over PIECES of ((lo, hi) x 3), exact rational bounds."""
        out = {}
        cuts = [Fraction(i, PIECES) for i in range(PIECES + 1)]
        for key, pt in self.P.items():
            if key not in self.moving:
                c = tuple((to_frac(rf.num(to_fmpq(0))),) * 2 for rf in pt)
                out[key] = [c] * PIECES
                continue
            out[key] = [tuple(rf_range(rf, t0, t1) for rf in pt)
                        for t0, t1 in zip(cuts, cuts[1:])]
        return out


def to_frac(q):
    return Fraction(int(q.p), int(q.q))


def poly_range(p, t0, t1):
    m, h = (t0 + t1) / 2, to_fmpq((t1 - t0) / 2)
    q = p(fmpq_poly([to_fmpq(m), 1]))
    cs = q.coeffs()
    if not cs:
        return F0, F0
    c0 = cs[0]
    bound, hk = to_fmpq(0), to_fmpq(1)
    for c in cs[1:]:
        hk *= h
        bound += abs(c) * hk
    return to_frac(c0 - bound), to_frac(c0 + bound)


def rf_range(rf, t0, t1):
    a, b = poly_range(rf.num, t0, t1)
    c, d = poly_range(rf.den, t0, t1)
    if c <= 0:
        return None                                   # no bound on this piece
    qs = (a / c, a / d, b / c, b / d)
    return min(qs), max(qs)


def _union(boxes, grow=F0):
    """Box (per piece) enclosing the given point boxes, grown by `grow`."""
    out = []
    for per in zip(*boxes):
        if any(ax is None for b in per for ax in b):
            out.append(None)
            continue
        out.append(tuple((min(b[i][0] for b in per) - grow, max(b[i][1] for b in per) + grow)
                         for i in range(3)))
    return out


def _may_meet(bx, by):
    for p, q in zip(bx, by):
        if p is None or q is None or None in p or None in q:   # no bound on this piece
            return True
        if all(p[i][0] <= q[i][1] and q[i][0] <= p[i][1] for i in range(3)):
            return True
    return False
