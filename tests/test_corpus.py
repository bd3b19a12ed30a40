"""Every corpus/**/*.json primitive case: polyccd against its `expect` block (formats.md,
EXPECT), and the `expect` block itself against the independent oracle (tests/oracle/oracle.py),
so a wrong hand-written expectation fails too. Scene files (polyccd/1, corpus/bodies/)
are tested by test_scene_corpus.py; test_cli_corpus_passes runs `polyccd corpus` over
the whole directory.
"""
from fractions import Fraction
from pathlib import Path

import pytest

import oracle
import polyccd

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
# Primitive cases only: the scene cases under corpus/bodies/ have their own tests
# (test_scene_corpus.py, against tests/oracle/oracle_body.py).
# The minimum-separation cases (corpus/min-distance/, options.min_distance) have theirs
# too (test_min_distance.py, against tests/oracle/oracle_distance.py).
FILES = sorted(p for p in CORPUS.rglob("*.json")
               if not {"bodies", "min-distance"} & set(p.relative_to(CORPUS).parts))
DEFAULT_TOLERANCE = Fraction(1, 10 ** 12)


def load(path):
    case = oracle.load_case(path)
    if case.get("format") != "polyccd-query/1":
        pytest.skip("%s is not a polyccd-query/1 case" % case.get("format"))
    assert "expect" in case and "collides" in case["expect"], "a corpus case needs expect.collides"
    assert case.get("source"), "a corpus case needs a source line"
    return case


def expected_time(expect):
    """None, a Fraction, or (lo, hi) Fractions with lo < hi."""
    fc = expect.get("first_contact")
    if fc is None:
        return None
    if isinstance(fc, list):
        lo, hi = (oracle.parse_number(x) for x in fc)
        assert lo < hi, "first_contact [lo, hi] needs lo < hi"
        return lo, hi
    return oracle.parse_number(fc)


def engine_value(x):
    """JSON strings go to polyccd as they are (its own exact parser); JSON numbers
    (read as Decimal) as the exact Fraction they denote."""
    return x if isinstance(x, str) else Fraction(x)


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(CORPUS)) for p in FILES])
def test_expectation_matches_oracle(path):
    case = load(path)
    want = oracle.solve_case(case)
    expect = case["expect"]
    assert expect["collides"] == want.collides, "oracle: collides=%s" % want.collides
    t = expected_time(expect)
    if t is None:                          # first_contact is optional
        return
    assert want.collides, "first_contact given for a case without contact"
    if isinstance(t, Fraction):
        assert oracle.is_rational(want.first) and want.first == t, (
            "oracle first contact %s" % oracle.describe(want.first))
    else:
        # corpus rule: a rational first contact time is written exactly
        assert not oracle.is_rational(want.first), (
            "first contact is rational (%s): write it exactly" % oracle.describe(want.first))
        assert oracle.time_strictly_in(want.first, *t), (
            "oracle first contact %s not inside %s" % (oracle.describe(want.first), t))


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(CORPUS)) for p in FILES])
def test_polyccd_meets_expectation(path):
    case = load(path)
    expect = case["expect"]
    tol = oracle.parse_number(case.get("options", {}).get("time_tolerance", "1e-12"))
    points = [[[engine_value(c) for c in axis] for axis in p] for p in case["points"]]
    radii = [engine_value(r) for r in case["radii"]] if "radii" in case else None
    res = polyccd.solve(case["kind"], points, radii, time_tolerance=tol)
    assert res.collides == expect["collides"], res
    fc, t = res.first_contact, expected_time(expect)
    if not expect["collides"]:
        assert fc is None, res
        return
    assert fc is not None and fc.lo <= fc.hi, res
    if isinstance(t, Fraction):
        # an exact rational contact time is reported exactly, whatever the tolerance
        assert fc.exact == t and fc.lo == t and fc.hi == t, res
    elif t is not None:
        lo, hi = t
        assert fc.lo <= hi and lo <= fc.hi, "enclosure does not intersect %s: %r" % (t, res)
        assert fc.hi - fc.lo <= tol, "enclosure wider than %s: %r" % (tol, res)
        # stronger than formats.md asks: the enclosure holds the oracle's exact time
        first = oracle.solve_case(case).first
        assert oracle.time_in(first, fc.lo, fc.hi), (oracle.describe(first), res)


def test_corpus_is_big_enough():
    kinds = {}
    for path in FILES:
        case = oracle.load_case(path)
        kinds[case.get("kind")] = kinds.get(case.get("kind"), 0) + 1
    assert len(FILES) >= 70 and all(kinds.get(k, 0) >= 5 for k in oracle.KINDS), kinds


def test_cli_corpus_passes(run_cli):
    """The command line's own corpus runner (formats.md: `polyccd corpus PATH...`)."""
    out = run_cli("corpus", CORPUS)
    last = out.stdout.strip().splitlines()[-1] if out.stdout.strip() else ""
    every = len(list(CORPUS.rglob("*.json")))  # primitive and scene cases
    assert out.returncode == 0 and last == "%d passed, 0 failed" % every, (
        out.stdout[-3000:] + out.stderr[-3000:])


def test_generated_files_are_up_to_date():
    """The files tests/tools/make_corpus.py writes are on disk unchanged (reproducible data)."""
    import make_corpus
    stale = [rel for rel, text in make_corpus.all_files().items()
             if not (CORPUS / rel).exists() or (CORPUS / rel).read_text() != text]
    assert not stale, "run `python tests/tools/make_corpus.py`: %s" % stale
