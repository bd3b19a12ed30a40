"""Property tests: polyccd.solve against the independent exact oracle (tests/oracle/oracle.py).

Per kind: RANDOM_COUNT random queries (free trajectories, contacts planted at rational
and irrational times, planted then moved off by 10^-k) and DEGENERATE_COUNT deliberately
degenerate ones (tests/oracle/oracle_degen.py: coplanar or collinear for all t, parallel edges,
coincident points, zero-length edges, collinear triangles, grazing double roots, contact
at t = 0 or 1, near misses). Both must agree on `collides` and on the first contact time:
exactly when it is rational; for an irrational time the reported enclosure must contain
it (checked exactly against the oracle's algebraic number) and be at most the time
tolerance wide.

Every query has its own RNG seeded by "SEED:kind:mode:index", so one failing query is
reproducible alone. Set POLYCCD_PROPERTY_SEED to run another sample; counts can be
raised (never lowered) with POLYCCD_PROPERTY_SCALE; POLYCCD_PROPERTY_HEAVY=N adds N
high-degree / 18-digit queries per kind (slow, off by default). Failure messages print the seed and
each failing query as polyccd-query/1 JSON (pastes straight into corpus/).
"""
import os
import random
import time
from fractions import Fraction

import pytest

import oracle
import oracle_degen
import oracle_gen
import polyccd

SEED = int(os.environ.get("POLYCCD_PROPERTY_SEED", "20251122"))
SCALE = max(1, int(os.environ.get("POLYCCD_PROPERTY_SCALE", "1")))
RANDOM_COUNT = 2000 * SCALE
DEGENERATE_COUNT = 500 * SCALE
TOLERANCE = Fraction(1, 10 ** 12)          # polyccd's default time tolerance
MAX_SHOWN = 15                             # failing queries printed in full per test

# Degree 7..12 or 18-digit coefficients: the engine needs seconds to minutes per query
# there (the oracle milliseconds), so these run only on request, e.g.
# POLYCCD_PROPERTY_HEAVY=50 for 50 per kind.
HEAVY_COUNT = int(os.environ.get("POLYCCD_PROPERTY_HEAVY", "0"))

GENERATORS = {"random": (oracle_gen.random_query, RANDOM_COUNT),
              "degenerate": (oracle_degen.degenerate_query, DEGENERATE_COUNT),
              "heavy": (oracle_gen.heavy_query, HEAVY_COUNT)}


def mismatch(kind, pts, radii, want, got, decide_only):
    """Why polyccd's Result `got` disagrees with oracle Result `want` ('' if it agrees)."""
    if got.collides != want.collides:
        return "collides: oracle %s, polyccd %s" % (want.collides, got.collides)
    if decide_only:
        return ""
    fc = got.first_contact
    if not want.collides:
        return "" if fc is None else "first_contact %r reported without contact" % (fc,)
    if fc is None:
        return "no first_contact reported"
    t = want.first
    if fc.hi - fc.lo > TOLERANCE:
        return "enclosure [%s, %s] wider than %s" % (fc.lo, fc.hi, TOLERANCE)
    if oracle.is_rational(t):
        if fc.exact != t or fc.lo != t or fc.hi != t:
            return "first contact: oracle exactly %s, polyccd %r" % (t, fc)
        return ""
    if fc.exact is not None:
        return "first contact: oracle irrational %s, polyccd exact %s" % (
            oracle.describe(t), fc.exact)
    if not oracle.time_in(t, fc.lo, fc.hi):
        return "first contact: oracle %s not in polyccd's [%s, %s]" % (
            oracle.describe(t), fc.lo, fc.hi)
    return ""


def linear_form(kind, pts):
    """(p_t0, p_t1) float arrays when every point moves linearly with coordinates that
    are exact doubles at t = 0 and t = 1 (then solve_linear must agree too), else None."""
    if kind == "sphere-sphere" or any(len(c) > 2 for p in pts for c in p):
        return None
    p0 = [[Fraction(c[0]) if c else Fraction(0) for c in p] for p in pts]
    p1 = [[sum(map(Fraction, c), Fraction(0)) for c in p] for p in pts]
    if any(float(x) != x for p in p0 + p1 for x in p):
        return None
    return [[float(x) for x in p] for p in p0], [[float(x) for x in p] for p in p1]


def run_one(kind, mode, i):
    gen, _ = GENERATORS[mode]
    rng = random.Random("%d:%s:%s:%d" % (SEED, kind, mode, i))
    k, pts, radii, label = gen(rng, kind)
    want = oracle.solve(k, pts, radii)
    decide_only = i % 4 == 3               # every 4th query: also the decide-only path
    try:
        got = polyccd.solve(k, pts, radii)
        why = mismatch(k, pts, radii, want, got, False)
        if not why and decide_only:
            got = polyccd.solve(k, pts, radii, want_time=False)
            why = mismatch(k, pts, radii, want, got, True)
            why = why and "want_time=False: " + why
        lin = linear_form(k, pts)
        if not why and lin:
            why = mismatch(k, pts, radii, want, polyccd.solve_linear(k, *lin), False)
            if not why and polyccd.collides_linear(k, *lin) != want.collides:
                why = "collides_linear: %s" % (not want.collides)
            why = why and "solve_linear / collides_linear: " + why
    except Exception as e:                 # an engine error is a failure of this query
        why = "polyccd raised %s: %s" % (type(e).__name__, e)
    if not why:
        return None, want.collides
    src = "property test seed %d %s/%s #%d: %s" % (SEED, kind, mode, i, label)
    expect = {"collides": want.collides}
    if want.first is not None:
        expect["first_contact"] = (oracle.fraction_str(want.first)
                                   if oracle.is_rational(want.first)
                                   else [oracle.decimal_str(x) for x in
                                         want.first.enclosure(Fraction(1, 10 ** 15),
                                                              denominator=10 ** 17)])
    text = "%s\n    oracle: collides=%s first=%s\n    %s" % (
        why, want.collides, oracle.describe(want.first),
        oracle.query_json(k, pts, radii, expect=expect, source=src))
    return text, want.collides


@pytest.mark.parametrize("mode", sorted(m for m, (_, n) in GENERATORS.items() if n))
@pytest.mark.parametrize("kind", oracle.KINDS)
def test_polyccd_matches_oracle(kind, mode):
    _, count = GENERATORS[mode]
    failures, hits = [], 0
    start = time.time()
    for i in range(count):
        why, collides = run_one(kind, mode, i)
        hits += collides
        if why:
            failures.append("#%d %s" % (i, why))
    elapsed = time.time() - start
    print("%s/%s: %d queries, %d collide, %.1fs" % (kind, mode, count, hits, elapsed))
    # a sample where (almost) nothing or everything collides tests little
    if count >= 100:
        assert count // 10 <= hits <= count - count // 20, (kind, mode, hits)
    assert not failures, "seed %d (POLYCCD_PROPERTY_SEED), %s/%s: %d of %d disagree:\n%s" % (
        SEED, kind, mode, len(failures), count, "\n".join(failures[:MAX_SHOWN]))
