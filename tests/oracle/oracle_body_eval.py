"""Exact evaluation for the body oracle (oracle_body.py): the sign of a polynomial
predicate on [0, 1] decomposed at its real roots (critical_roots, decompose), roots
compared exactly (Ev). Independent of polyccd."""
from fractions import Fraction

from oracle_alg import (cmp_points, irreducible_factors, lower, roots_in_unit_interval, sign,
                        simplest_between, sort_points, to_fmpq, upper)
from oracle_body_scene import F0, F1


# ---------------------------------------------------------------- exact evaluation

_factor_cache = {}
_root_cache = {}


def _pkey(p):
    return tuple(p.coeffs())


def critical_roots(p):
    """Roots in [0, 1] of the irreducible factors of the non-zero poly p."""
    k = _pkey(p)
    got = _factor_cache.get(k)
    if got is None:
        got = []
        for fkey, f in irreducible_factors(p).items():
            roots = _root_cache.get(fkey)
            if roots is None:
                roots = _root_cache[fkey] = roots_in_unit_interval(fkey, f)
            got.extend(roots)
        _factor_cache[k] = got
    return got


class Ev:
    """Exact signs of rational functions at one time (Fraction or RealRoot)."""
    __slots__ = ("point", "q", "recorded")

    def __init__(self, point, record):
        self.point = point
        self.q = to_fmpq(point) if isinstance(point, Fraction) else None
        self.recorded = [] if record else None

    def _s(self, p):
        if self.q is not None:
            return sign(p(self.q))
        return self.point.sign_of(p)

    def sign(self, rf):
        if self.recorded is not None:
            self.recorded.append(rf)
        sn = self._s(rf.num)
        if sn == 0:
            return 0
        sd = self._s(rf.den)
        if sd <= 0:
            raise AssertionError("oracle_body: a denominator is not > 0")
        return sn * sd


def _pt_key(x):
    return x if isinstance(x, Fraction) else x.key


def decompose(pred):
    """(contact points, first contact) of a predicate pred(ev) -> bool over [0, 1]."""
    crit = [F0, F1]
    seen = set()
    gap_value = {}
    while True:
        crit = sort_points(crit)
        new = []
        keys = []
        for x, y in zip(crit, crit[1:]):
            k = (_pt_key(x), _pt_key(y))
            keys.append(k)
            if k in gap_value:
                continue
            if cmp_points(x, y) >= 0:
                raise AssertionError("oracle_body: critical times out of order")
            ev = Ev(simplest_between(upper(x), lower(y)), record=True)
            gap_value[k] = pred(ev)
            for rf in ev.recorded:
                for p in (rf.num, rf.den):
                    if p.degree() < 1:
                        continue
                    pk = _pkey(p)
                    if pk in seen:
                        continue
                    seen.add(pk)
                    for r in critical_roots(p):
                        if isinstance(r, Fraction) and r in (F0, F1):
                            continue
                        new.append(r)
        have = {_pt_key(x) for x in crit}
        new = [r for r in new if _pt_key(r) not in have]
        # dedupe
        uniq = {}
        for r in new:
            uniq.setdefault(_pt_key(r), r)
        if not uniq:
            break
        crit.extend(uniq.values())
    at = [pred(Ev(x, record=False)) for x in crit]
    for i, k in enumerate(keys):
        if gap_value[k] and not (at[i] and at[i + 1]):
            raise AssertionError("oracle_body: contact set not closed around %r" % (crit[i],))
    first = next((x for x, c in zip(crit, at) if c), None)
    return first
