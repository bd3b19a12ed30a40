"""Independent exact oracle for polyccd primitive queries (tests only).

    res = oracle.solve(kind, points, radii=None)
    res.collides      -> bool
    res.first         -> None | Fraction | oracle_alg.RealRoot (irrational, exact)

Method (deliberately unlike the engine's Hermite/Hankel root counting): a direct
cylindrical decomposition of [0, 1] in t.
  1. The contact predicate of the kind (tests/oracle/oracle_pred.py) is a decision tree over
     exact signs of polynomials of t. Evaluate it at a rational sample of each open gap
     between the current critical times, recording every polynomial whose sign it asks.
  2. Every real root in [0, 1] of every irreducible factor of a recorded, non-zero
     polynomial becomes a critical time. Repeat 1-2 until no new critical time appears.
     Then, on each gap, every polynomial the predicate consults at the sample has a
     constant sign over the gap, so the predicate follows the same branch and gives the
     same answer everywhere in the gap. (A polynomial that is identically zero, e.g. the
     coplanarity determinant of a vertex sliding in a face's plane, has sign 0 for all t
     and adds no critical time.)
  3. Evaluate the predicate exactly AT each critical time (0, 1 and the roots; signs at
     an irrational root come from p mod minimal polynomial, then refinement).
The contact set is closed (continuous motion of closed sets), so a gap in contact has
both of its ends in contact; the oracle asserts this as a self-check. The first contact
time is therefore the first critical time in contact.
"""
import json
from decimal import Decimal
from fractions import Fraction

from oracle_alg import (RealRoot, cmp_points, irreducible_factors, lower,
                        roots_in_unit_interval, sign, simplest_between, sort_points, to_fmpq,
                        upper)
from oracle_pred import Traj, contact

KINDS = ("vertex-face", "edge-edge", "vertex-edge", "vertex-vertex", "sphere-sphere")
NPOINTS = {"vertex-face": 4, "edge-edge": 4, "vertex-edge": 3, "vertex-vertex": 2,
           "sphere-sphere": 2}


# ---------------------------------------------------------------- numbers and files

def parse_number(x):
    """An exact number of formats.md: int, Fraction, Decimal (a JSON number read with
    parse_float=Decimal), float (its exact binary value) or a string "3", "-0.125",
    "2.5e-7", "-7/3"."""
    if isinstance(x, bool):
        raise ValueError("not a number: %r" % (x,))
    if isinstance(x, (int, Fraction, Decimal)):
        return Fraction(x)
    if isinstance(x, float):
        return Fraction(x)               # exact binary value; rejects nan/inf
    if isinstance(x, str):
        return Fraction(x.strip())
    raise ValueError("not a number: %r" % (x,))


def parse_query(obj):
    """A polyccd-query/1 dict -> (kind, points, radii) with Fraction coefficients."""
    kind = obj["kind"]
    if kind not in KINDS:
        raise ValueError("unknown kind %r" % (kind,))
    pts = [[[parse_number(c) for c in axis] for axis in pt] for pt in obj["points"]]
    if len(pts) != NPOINTS[kind] or any(len(pt) != 3 for pt in pts):
        raise ValueError("%s needs %d points of 3 coordinates" % (kind, NPOINTS[kind]))
    radii = None
    if kind == "sphere-sphere":
        radii = [parse_number(r) for r in obj["radii"]]
        if len(radii) != 2 or min(radii) <= 0:
            raise ValueError("sphere-sphere needs two radii > 0")
    return kind, pts, radii


def load_case(path):
    """Reads a JSON case keeping every JSON number exact (floats as Decimal)."""
    with open(path) as fh:
        return json.load(fh, parse_float=Decimal)


def fraction_str(q):
    q = Fraction(q)
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


def query_json(kind, points, radii=None, **extra):
    """A polyccd-query/1 JSON text of a query (every number as an exact string), for
    failure messages that paste straight into corpus/."""
    obj = {"format": "polyccd-query/1", "kind": kind,
           "points": [[[fraction_str(c) for c in axis] for axis in pt] for pt in points]}
    if radii is not None:
        obj["radii"] = [fraction_str(r) for r in radii]
    obj.update(extra)
    return json.dumps(obj)


# ---------------------------------------------------------------- the decomposition

class _Eval:
    """Exact signs of polynomials at one time point (Fraction or RealRoot)."""

    def __init__(self, point, record):
        self.point = point
        self.q = to_fmpq(point) if isinstance(point, Fraction) else None
        self.recorded = {} if record else None

    def sign(self, p):
        if self.recorded is not None:
            self.recorded[id(p)] = p
        if self.q is not None:
            return sign(p(self.q))
        return self.point.sign_of(p)


class Result:
    __slots__ = ("collides", "first", "critical", "point_contact", "gap_contact")

    def __repr__(self):
        return "oracle.Result(collides=%r, first=%r)" % (self.collides, self.first)


def solve(kind, points, radii=None):
    """Exact contact decision and first contact time of a primitive query."""
    points = [[[parse_number(c) for c in axis] for axis in pt] for pt in points]
    if radii is not None:
        radii = [parse_number(r) for r in radii]
    T = Traj(points, radii)

    crit = [Fraction(0), Fraction(1)]
    seen_polys, seen_factors = {}, set()     # seen_polys: id -> poly (kept alive)
    gap_value = {}                         # (key(x), key(y)) -> contact on the gap

    def pkey(x):
        return x if isinstance(x, Fraction) else x.key

    while True:
        crit = sort_points(crit)
        new_roots = []
        gaps = []
        for x, y in zip(crit, crit[1:]):
            k = (pkey(x), pkey(y))
            gaps.append(k)
            if k in gap_value:
                continue
            # sorting need not have compared x and y directly: compare them now, which
            # also refines their isolating intervals apart (upper(x) < lower(y))
            if cmp_points(x, y) >= 0:
                raise AssertionError("oracle: critical times out of order")
            ev = _Eval(simplest_between(upper(x), lower(y)), record=True)
            gap_value[k] = contact(kind, T, ev)
            for pid, p in ev.recorded.items():
                if pid in seen_polys:
                    continue
                seen_polys[pid] = p
                if p.degree() < 0:          # identically zero: sign 0 for all t
                    continue
                for fkey, f in irreducible_factors(p).items():
                    if fkey not in seen_factors:
                        seen_factors.add(fkey)
                        new_roots.extend(r for r in roots_in_unit_interval(fkey, f)
                                         if not (isinstance(r, Fraction) and r in (0, 1)))
        if not new_roots:
            break
        crit.extend(new_roots)

    point_contact = [contact(kind, T, _Eval(x, record=False)) for x in crit]
    gap_contact = [gap_value[k] for k in gaps]
    for i, g in enumerate(gap_contact):
        if g and not (point_contact[i] and point_contact[i + 1]):
            raise AssertionError("oracle: contact set not closed around gap %d of %r"
                                 % (i, crit))
    res = Result()
    res.critical, res.point_contact, res.gap_contact = crit, point_contact, gap_contact
    res.collides = any(point_contact)
    res.first = next((x for x, c in zip(crit, point_contact) if c), None)
    return res


def solve_case(obj):
    kind, pts, radii = parse_query(obj)
    return solve(kind, pts, radii)


# ---------------------------------------------------------------- comparing times

def is_rational(t):
    return isinstance(t, Fraction)


def time_in(t, lo, hi):
    """Exactly: lo <= t <= hi for the oracle's time t (Fraction or RealRoot)."""
    lo, hi = Fraction(lo), Fraction(hi)
    if isinstance(t, Fraction):
        return lo <= t <= hi
    return t.cmp_rational(lo) >= 0 and t.cmp_rational(hi) <= 0


def time_strictly_in(t, lo, hi):
    lo, hi = Fraction(lo), Fraction(hi)
    if isinstance(t, Fraction):
        return lo < t < hi
    return t.cmp_rational(lo) > 0 and t.cmp_rational(hi) < 0


def describe(t):
    """Human-readable exact description of an oracle time."""
    if t is None or isinstance(t, Fraction):
        return repr(t if t is None else fraction_str(t))
    lo, hi = t.enclosure(Fraction(1, 10 ** 20), denominator=10 ** 22)
    return "root of %s in [%s, %s] (~%.17g)" % (t.f, decimal_str(lo), decimal_str(hi),
                                                 t.approx())


def decimal_str(q):
    """Exact decimal string of a Fraction when its denominator divides a power of ten
    (at most 10^60); the fraction "p/q" otherwise."""
    q = Fraction(q)
    for k in range(61):
        n = q * 10 ** k
        if n.denominator == 1:
            break
    else:
        return fraction_str(q)
    if k == 0:
        return str(q.numerator)
    digits = str(abs(n.numerator)).rjust(k + 1, "0")
    return ("-" if q < 0 else "") + digits[:-k] + "." + digits[-k:]


__all__ = ["KINDS", "NPOINTS", "RealRoot", "Result", "solve", "solve_case",
           "parse_number", "parse_query", "load_case", "query_json", "fraction_str", "decimal_str",
           "is_rational", "time_in", "time_strictly_in", "describe"]
