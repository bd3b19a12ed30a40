"""Cross-check of the Hermite/Hankel root counting (lib/poly/count.h, hermite.h)
against an independent route: sympy's exact real-root isolation (Sturm sequences and
rational isolating intervals), on random and deliberately degenerate polynomials
(multiple roots, roots shared by f and g, roots exactly at the interval ends, zero
Hankel minors that need the Frobenius rule).

The probe binary build/poly_probe (tests/cpp/poly_probe.cpp) prints, per query, the
exact count, the interval-filter count ("u" when the filter is unsure), TaQ(g1, f) and
the exact count by the Hermite route alone (no Bernstein/Descartes filters).
"""
import os
import random
import subprocess
from fractions import Fraction

import pytest
import sympy

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROBE = os.path.join(ROOT, "build", "poly_probe")
T = sympy.Symbol("t")
SEED = 20261122


def _poly(coeffs):
    return sympy.Poly(list(reversed([sympy.Rational(c.numerator, c.denominator) for c in coeffs])), T)


def _sign_at_root(g, p, c, d):
    """Sign of g at the only root of the irreducible p in [c, d] (exact)."""
    if g.is_zero:
        return 0
    if g.rem(p).is_zero:
        return 0
    while g.count_roots(c, d) > 0:
        c, d = p.refine_root(c, d, eps=(d - c) / 4)
    return 1 if g.eval((c + d) / 2) > 0 else -1


def oracle(f, gs, a, b):
    """#{t in (a, b): f(t) = 0, all g(t) > 0} and TaQ(g1, f) over the reals."""
    fp = _poly(f)
    gps = [_poly(g) for g in gs]
    a, b = sympy.Rational(a.numerator, a.denominator), sympy.Rational(b.numerator, b.denominator)
    count, taq = 0, 0
    for p, _mult in fp.factor_list()[1]:
        if p.degree() < 1:
            continue
        for (c, d), _m in p.intervals():
            c, d = sympy.Rational(c), sympy.Rational(d)
            if p.degree() == 1:
                r = -p.all_coeffs()[1] / p.all_coeffs()[0]
                inside = a < r < b
                signs = [int(sympy.sign(g.eval(r))) for g in gps]
            else:  # irrational root: refine until it is clear of a and b
                while (c <= a <= d) or (c <= b <= d):
                    c, d = p.refine_root(c, d, eps=(d - c) / 4)
                inside = a < c and d < b
                signs = [_sign_at_root(g, p, c, d) for g in gps]
            if inside and all(s > 0 for s in signs):
                count += 1
            if gps:
                taq += signs[0]
            else:
                taq += 1
    return count, taq


def _fmt(c):
    return f"{c.numerator}/{c.denominator}"


def run_probe(cases):
    lines = []
    for f, gs, a, b in cases:
        parts = [f"{_fmt(a)} {_fmt(b)}", " ".join(_fmt(c) for c in f)]
        parts += [" ".join(_fmt(c) for c in g) for g in gs]
        lines.append(" | ".join(parts))
    out = subprocess.run([PROBE], input="\n".join(lines) + "\n", capture_output=True, text=True,
                         check=True).stdout.split("\n")
    return [tuple(x.split()) for x in out if x.strip()]


def mul(p, q):
    r = [Fraction(0)] * (len(p) + len(q) - 1)
    for i, x in enumerate(p):
        for j, y in enumerate(q):
            r[i + j] += x * y
    return r


def random_degenerate(rng, a, b):
    """f as a product of (t - r)^m with r often at a, b or shared with g."""
    pool = [a, b, (a + b) / 2, Fraction(rng.randint(-6, 6), rng.randint(1, 4))]
    f = [Fraction(rng.choice([1, -2, 3]))]
    roots = []
    for _ in range(rng.randint(1, 4)):
        r = rng.choice(pool)
        roots.append(r)
        f = mul(f, [-r, Fraction(1)] * 1)
        if rng.random() < 0.4:
            f = mul(f, [-r, Fraction(1)])
    if rng.random() < 0.5:  # an irreducible quadratic factor (irrational or complex roots)
        f = mul(f, [Fraction(rng.choice([-2, -3, 2, 5])), Fraction(0), Fraction(1)])
    gs = []
    for _ in range(rng.randint(0, 3)):
        g = [Fraction(rng.randint(-3, 3)), Fraction(rng.randint(-3, 3))]
        if rng.random() < 0.5 and roots:
            g = mul(g, [-rng.choice(roots), Fraction(1)])
        gs.append(g)
    return f, gs


def random_generic(rng):
    f = [Fraction(rng.randint(-20, 20), rng.randint(1, 5)) for _ in range(rng.randint(2, 8))]
    if f[-1] == 0:
        f[-1] = Fraction(1)
    gs = [[Fraction(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(rng.randint(1, 5))]
          for _ in range(rng.randint(0, 2))]
    return f, gs


@pytest.mark.skipif(not os.path.exists(PROBE), reason="build/poly_probe not built (make test builds it)")
def test_hermite_counts_match_sympy():
    rng = random.Random(SEED)
    cases = []
    for i in range(600):
        a = Fraction(rng.randint(-3, 1), rng.randint(1, 3))
        b = a + Fraction(rng.randint(1, 8), rng.randint(1, 3))
        f, gs = random_degenerate(rng, a, b) if i % 2 else random_generic(rng)
        cases.append((f, gs, a, b))
    got = run_probe(cases)
    assert len(got) == len(cases)
    checked_interval = 0
    for (f, gs, a, b), (exact, inter, taq, hermite) in zip(cases, got):
        want_count, want_taq = oracle(f, gs, a, b)
        msg = f"seed {SEED}: f={f} g={gs} on ({a}, {b})"
        assert int(exact) == want_count, msg
        assert int(hermite) == want_count, msg
        assert int(taq) == want_taq, msg
        if inter != "u":
            checked_interval += 1
            assert int(inter) == want_count, msg
    assert checked_interval > 100  # the interval filter must decide a good share


def test_frobenius_rule_zero_minors():
    # t^3 - 1: Hankel minors 3, 0, -27 (a zero run of length one); one real root.
    # t^4 - 1 (roots +-1, +-i): s = 4,0,0,0,4,...: minors 4, 0, 0, -256; a run of two.
    # t^4 + 1: minors 4, 0, 0, 256, a run of two between equal signs; no real root.
    # (t^2 + 1)^2 (t - 1): a rank-deficient Hermite matrix.
    cases = [
        ([Fraction(1), Fraction(0), Fraction(0), Fraction(0), Fraction(1)], [], Fraction(-5), Fraction(5)),
        ([Fraction(-1), Fraction(0), Fraction(0), Fraction(1)], [], Fraction(-5), Fraction(5)),
        ([Fraction(-1), Fraction(0), Fraction(0), Fraction(0), Fraction(1)], [], Fraction(-5), Fraction(5)),
        (mul(mul([Fraction(1), Fraction(0), Fraction(1)], [Fraction(1), Fraction(0), Fraction(1)]),
             [Fraction(-1), Fraction(1)]), [], Fraction(0), Fraction(2)),
    ]
    got = run_probe(cases)
    assert [int(g[0]) for g in got] == [0, 1, 2, 1]
    assert [int(g[2]) for g in got] == [0, 1, 2, 1]
    assert [int(g[3]) for g in got] == [0, 1, 2, 1]


def random_sparse(rng):
    """c t^n + d t^m + e: Newton sums with many zeros, so zero runs of Hankel minors."""
    n = rng.randint(2, 8)
    f = [Fraction(0)] * (n + 1)
    f[n] = Fraction(rng.choice([1, -1, 2]))
    f[0] = Fraction(rng.choice([1, -1, 2, -3, 4]))
    if rng.random() < 0.4:
        f[rng.randint(1, n - 1)] = Fraction(rng.choice([1, -2]))
    gs = [] if rng.random() < 0.5 else [[Fraction(rng.randint(-2, 2)), Fraction(1)]]
    return f, gs


@pytest.mark.skipif(not os.path.exists(PROBE), reason="build/poly_probe not built (make test builds it)")
def test_sparse_polynomials_zero_minor_runs():
    rng = random.Random(SEED + 1)
    cases = []
    for _ in range(300):
        f, gs = random_sparse(rng)
        cases.append((f, gs, Fraction(rng.choice([-3, -1, 0])), Fraction(rng.choice([1, 2, 3]))))
    for (f, gs, a, b), (exact, _inter, taq, hermite) in zip(cases, run_probe(cases)):
        want_count, want_taq = oracle(f, gs, a, b)
        assert (int(exact), int(taq), int(hermite)) == (want_count, want_taq, want_count), \
            f"f={f} g={gs} on ({a}, {b})"

