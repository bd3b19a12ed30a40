"""Exact real algebraic numbers in [0, 1] for the test oracle (tests/oracle/oracle.py).

Independent of the engine: no root counting by Hermite/Hankel forms. A polynomial with
rational coefficients is factored into irreducible factors over Q (python-flint); the
real roots of each factor come from Arb's certified complex root isolation, and every
isolating interval is re-checked here with exact rational arithmetic (a sign change at
its rational endpoints). An irrational root is then refined by exact bisection.

Exactness rests on two facts about an irreducible f of degree >= 2:
  * f has no rational root, so f(q) != 0 for every rational q (bisection never stalls,
    and comparisons with a rational always terminate);
  * for any rational polynomial p, p(alpha) == 0 iff f divides p (decided by p % f).
Two distinct irreducible (primitive, positive leading coefficient) factors share no
root, so two roots of different factors are always separable by refinement.
"""
from fractions import Fraction
from functools import cmp_to_key

from flint import fmpq, fmpq_poly, fmpz_poly


def to_fmpq(x):
    x = Fraction(x)
    return fmpq(x.numerator, x.denominator)


def sign(x):
    return (x > 0) - (x < 0)


def primitive_key(f):
    """fmpz_poly (or fmpq_poly) -> tuple of integer coefficients of its primitive
    part with positive leading coefficient (the canonical name of a factor)."""
    c = [int(v) for v in f.coeffs()]
    if isinstance(f, fmpq_poly):
        den = int(f.denom())
        c = [int(v * den) for v in f.coeffs()]
    g = 0
    for v in c:
        g = _gcd(g, v)
    if c[-1] < 0:
        g = -g
    return tuple(v // g for v in c)


def _gcd(a, b):
    while b:
        a, b = b, a % b
    return abs(a)


def _dyadic(a):
    """Exact Fraction value of an exact arb (a midpoint or a radius)."""
    m, e = a.man_exp()
    m, e = int(m), int(e)
    return Fraction(m * 2 ** e) if e >= 0 else Fraction(m, 2 ** -e)


class RealRoot:
    """An irrational real root of an irreducible integer polynomial f (degree >= 2),
    given by an isolating interval lo < alpha < hi with rational endpoints."""

    __slots__ = ("f", "fq", "lo", "hi", "slo", "key")

    def __init__(self, f, lo, hi, key):
        self.f = f                       # fmpz_poly, irreducible, degree >= 2
        self.fq = fmpq_poly(f)
        self.lo, self.hi = Fraction(lo), Fraction(hi)
        self.slo = self._sgn(self.lo)
        shi = self._sgn(self.hi)
        if self.slo == 0 or shi == 0 or self.slo == shi:
            raise AssertionError("oracle: not an isolating interval %r" % (self,))
        self.key = key                   # (factor key, index): identity of the root

    def _sgn(self, q):
        return sign(self.fq(to_fmpq(q)))

    def bisect(self):
        mid = (self.lo + self.hi) / 2
        s = self._sgn(mid)
        if s == 0:
            raise AssertionError("oracle: rational root of an irreducible factor")
        if s == self.slo:
            self.lo = mid
        else:
            self.hi = mid

    def width(self):
        return self.hi - self.lo

    def refine(self, width):
        """Shrink the interval below `width` (a positive Fraction)."""
        while self.hi - self.lo > width:
            self.bisect()

    def cmp_rational(self, q):
        """-1, 0 or 1 as alpha <, ==, > q (never 0: alpha is irrational)."""
        q = Fraction(q)
        while self.lo <= q <= self.hi:
            self.bisect()
        return 1 if q < self.lo else -1

    def enclosure(self, width, denominator=None):
        """(lo, hi) with lo < alpha < hi and hi - lo <= width. With `denominator`
        (e.g. 10**20) both ends are multiples of 1/denominator, which gives short
        exact decimal strings; width must then be >= 2/denominator."""
        width = Fraction(width)
        if denominator is None:
            self.refine(width)
            return self.lo, self.hi
        self.refine(width / 4)
        lo = Fraction((self.lo * denominator).__floor__(), denominator)
        hi = Fraction((self.hi * denominator).__ceil__(), denominator)
        if lo == self.lo:
            lo -= Fraction(1, denominator)
        if hi == self.hi:
            hi += Fraction(1, denominator)
        if hi - lo > width:
            raise ValueError("denominator too small for this width")
        return lo, hi

    def approx(self):
        self.refine(Fraction(1, 2 ** 60))
        return float((self.lo + self.hi) / 2)

    def sign_of(self, p):
        """Exact sign of the rational polynomial p (fmpq_poly) at alpha."""
        r = p % self.fq
        if r.degree() < 0:
            return 0
        while True:
            # r(mid + y) = c0 + c1 y + ...; |r(x) - c0| <= sum |ck| rad^k on the interval
            mid = (self.lo + self.hi) / 2
            rad = to_fmpq((self.hi - self.lo) / 2)
            q = r(fmpq_poly([to_fmpq(mid), 1]))
            cs = q.coeffs()
            c0 = cs[0] if cs else fmpq(0)
            bound, radk = fmpq(0), fmpq(1)
            for c in cs[1:]:
                radk *= rad
                bound += abs(c) * radk
            if abs(c0) > bound:
                return sign(c0)
            for _ in range(4):
                self.bisect()

    def __repr__(self):
        return "RealRoot(%s, [%s, %s])" % (self.f, self.lo, self.hi)


def cmp_points(a, b):
    """Exact comparison of two points (Fraction or RealRoot)."""
    if isinstance(a, Fraction):
        if isinstance(b, Fraction):
            return sign(a - b)
        return -b.cmp_rational(a)
    if isinstance(b, Fraction):
        return a.cmp_rational(b)
    if a.key == b.key:
        return 0
    while not (a.hi < b.lo or b.hi < a.lo):
        if a.width() >= b.width():
            a.bisect()
        else:
            b.bisect()
    return -1 if a.hi < b.lo else 1


def sort_points(points):
    return sorted(points, key=cmp_to_key(cmp_points))


def upper(x):
    return x if isinstance(x, Fraction) else x.hi


def lower(x):
    return x if isinstance(x, Fraction) else x.lo


def simplest_between(a, b):
    """The rational with the least denominator strictly between a < b (Stern-Brocot)."""
    fl = a.__floor__()
    if fl + 1 < b:
        # an integer lies strictly inside: take the one nearest to zero... any works
        return Fraction(fl + 1)
    # a and b share the integer part fl (or b == fl + 1)
    fa, fb = a - fl, b - fl                  # 0 <= fa < fb <= 1
    if fa == 0:
        # (0, fb): 1/n with n the least integer such that 1/n < fb
        n = (1 / fb).__floor__() + 1
        return fl + Fraction(1, n)
    # recurse on reciprocals: x in (fa, fb) <=> 1/x in (1/fb, 1/fa)
    return fl + 1 / simplest_between(1 / fb, 1 / fa)


def irreducible_factors(p):
    """Irreducible factors of a non-zero fmpq_poly, as {key: fmpz_poly} (degree >= 1)."""
    out = {}
    if p.degree() < 1:
        return out
    _, facs = p.factor()
    for g, _mult in facs:
        key = primitive_key(g)
        if len(key) >= 2:
            out[key] = fmpz_poly(list(key))
    return out


def roots_in_unit_interval(key, f):
    """The roots of the irreducible factor f in [0, 1]: Fractions (degree 1) or
    RealRoots with isolating intervals inside (0, 1)."""
    if f.degree() == 1:
        c0, c1 = key
        r = Fraction(-c0, c1)
        return [r] if 0 <= r <= 1 else []
    out = []
    for c, _mult in f.complex_roots():
        if not (c.imag.is_exact() and c.imag.is_zero()):
            continue                      # Arb certifies: a non-real root
        mid, rad = _dyadic(c.real.mid()), _dyadic(c.real.rad())
        lo, hi = mid - rad, mid + rad
        if hi < 0 or lo > 1:
            continue
        if rad == 0:
            raise AssertionError("oracle: exact root of an irreducible factor")
        r = RealRoot(f, lo, hi, (key, len(out)))
        while r.lo < 0 < r.hi or r.lo < 1 < r.hi:
            r.bisect()
        if 0 < r.lo and r.hi < 1:
            out.append(r)
    # The balls are disjoint (Arb) and were checked for a sign change each; make the
    # ordering explicit for callers that compare roots of the same factor.
    for i, a in enumerate(out):
        for b in out[i + 1:]:
            if not (a.hi < b.lo or b.hi < a.lo):
                raise AssertionError("oracle: overlapping isolating intervals")
    return out
