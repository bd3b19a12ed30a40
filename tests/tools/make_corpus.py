"""Builds corpus/<kind>/*.json (polyccd-query/1 cases) with expectations computed by the
independent oracle (tests/oracle/oracle.py), never by polyccd.

    python tests/tools/make_corpus.py [--out corpus] [--check]

Hand-constructed cases carry the answer derived by reasoning (`want`); the script stops
if the oracle disagrees with it. Generated cases come from the property-test generators
with a fixed seed. --check only verifies that the files on disk are what this script
would write.
"""
import argparse
import json
import os
import random
import sys
from fractions import Fraction as F

TESTS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The oracles live in tests/oracle/ and import each other by plain name.
sys.path.insert(0, os.path.join(TESTS, "oracle"))
import oracle              # noqa: E402
import oracle_degen        # noqa: E402
import oracle_gen          # noqa: E402
from oracle_corpus_cases import CASES, IRR, Literal   # noqa: E402

SHORT = {"vertex-face": "vf", "edge-edge": "ee", "vertex-edge": "ve",
         "vertex-vertex": "vv", "sphere-sphere": "ss"}
GENERATED_SEED = 7
ENCLOSURE = F(1, 10 ** 15)            # width of the ["lo", "hi"] of irrational times


def number_text(q):
    """Exact text of a number: "1e-30" for powers of ten, a terminating decimal when
    short, else "p/q"."""
    q = F(q)
    for k in range(1, 61):
        if q == F(1, 10 ** k):
            return "1e-%d" % k
        if q == 10 ** k and k >= 6:
            return "1e%d" % k
    s = oracle.decimal_str(q)
    return s if len(s) <= 40 else oracle.fraction_str(q)


def encode(x):
    if isinstance(x, Literal):
        return "@@%s@@" % x
    if isinstance(x, list):
        return [encode(v) for v in x]
    return number_text(x)


def expectation(res):
    exp = {"collides": res.collides}
    if res.first is not None:
        if oracle.is_rational(res.first):
            exp["first_contact"] = oracle.fraction_str(res.first)
        else:
            lo, hi = res.first.enclosure(ENCLOSURE, denominator=10 ** 17)
            exp["first_contact"] = [oracle.decimal_str(lo), oracle.decimal_str(hi)]
    return exp


def check_want(name, res, want, q):
    """The oracle must agree with the answer reasoned out by hand."""
    if want is None:
        ok = not res.collides
    elif isinstance(want, tuple) and want[0] is IRR:
        # (IRR, minimal polynomial or None, approximate value or exact (lo, hi))
        t, poly, where = res.first, want[1], want[2]
        ok = res.collides and not oracle.is_rational(t)
        if ok and poly is not None:
            ok = oracle_gen.trim([int(c) for c in t.f.coeffs()]) == list(poly)
        if ok and isinstance(where, tuple):
            ok = oracle.time_strictly_in(t, *where)
        elif ok:
            ok = abs(t.approx() - where) < 1e-9
    else:
        ok = res.collides and res.first == F(want)
    if not ok:
        raise SystemExit("%s: oracle says %s, hand answer %r\n%s"
                         % (name, oracle.describe(res.first), want, q))


def build_case(name, kind, points, radii, source):
    exact_pts = [[[oracle.parse_number(c) for c in axis] for axis in p] for p in points]
    exact_radii = [oracle.parse_number(r) for r in radii] if radii else None
    res = oracle.solve(kind, exact_pts, exact_radii)
    obj = {"format": "polyccd-query/1", "name": name, "source": source, "kind": kind,
           "points": encode(points)}
    if radii:
        obj["radii"] = encode(list(radii))
    obj["expect"] = expectation(res)
    text = "{\n%s\n}" % ",\n".join("  %s: %s" % (json.dumps(k), json.dumps(v))
                                    for k, v in obj.items())
    for lit in set(_literals(points) + _literals(radii or [])):
        text = text.replace('"@@%s@@"' % lit, lit)
    return text + "\n", res


def _literals(x):
    if isinstance(x, Literal):
        return [str(x)]
    if isinstance(x, list):
        return [v for y in x for v in _literals(y)]
    return []


def generated_cases():
    """A few seeded random and degenerate queries per kind (reproducible)."""
    out = []
    for kind in oracle.KINDS:
        for mode, gen, n in (("random", oracle_gen.random_query, 3),
                             ("degenerate", oracle_degen.degenerate_query, 3)):
            for i in range(n):
                rng = random.Random("%d:%s:%s:%d" % (GENERATED_SEED, kind, mode, i))
                k, pts, radii, label = gen(rng, kind)
                name = "%s-generated-%s-%d" % (SHORT[kind], mode, i)
                src = ("generator: tests/tools/make_corpus.py seed %d (%s query %d of %s): %s"
                       % (GENERATED_SEED, mode, i, kind, label))
                out.append((name, kind, pts, radii, src, "any"))
    return out


def all_files():
    files = {}
    for name, kind, pts, radii, source, want in list(CASES) + generated_cases():
        text, res = build_case(name, kind, pts, radii, source)
        if want != "any":
            check_want(name, res, want, text)
        path = os.path.join(kind, name + ".json")
        if path in files:
            raise SystemExit("duplicate case name " + name)
        files[path] = text
    return files


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(TESTS, "..", "corpus"))
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    files = all_files()
    stale = []
    for rel, text in sorted(files.items()):
        path = os.path.join(args.out, rel)
        old = open(path).read() if os.path.exists(path) else None
        if old != text:
            stale.append(rel)
            if not args.check:
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w") as fh:
                    fh.write(text)
    print("%d cases, %d %s" % (len(files), len(stale),
                               "differ from this script" if args.check else "written"))
    if args.check and stale:
        print("\n".join(stale))
        sys.exit(1)


if __name__ == "__main__":
    main()
