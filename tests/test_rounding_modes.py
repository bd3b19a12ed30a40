"""The same answers, to the bit, under every rounding mode of the caller (issue 15).

Every entry point computes under round-to-nearest internally and restores the caller's
mode (tests/c/test_motion.c checks the restoring); what this test adds is that the
answers themselves do not depend on the mode the caller left: the first-contact
enclosure is the canonical midpoint bisection's (lib/poly/earliest.h), whichever stage
decides each step. The inputs are parsed under round-to-nearest; only the solves run under
the other modes, and the answers are compared without their float approximations (a
Python float made under FE_UPWARD may differ in its last bit; the exact Fractions may
not).
"""
import ctypes
import ctypes.util
import os
from pathlib import Path

import pytest

import polyccd
from polyccd.apps import _corpus, _csv

LIBM = ctypes.CDLL(ctypes.util.find_library("m"))
# glibc on x86-64 (fenv.h): the x87/SSE rounding-control bits.
MODES = {"nearest": 0x000, "downward": 0x400, "upward": 0x800, "towardzero": 0xC00}
QUERY_DIR = Path(os.environ.get("POLYCCD_QUERY_DIR",
                                Path(__file__).resolve().parents[2] / "shared/data/ccd-queries"))
REPO = Path(__file__).resolve().parents[1]


def key(r):
    """An answer without float approximations: collides, exact bounds, features, stage."""
    t = r.first_contact
    times = None if t is None else (t.lo, t.hi, t.exact)
    return (r.collides, times, r.features, r.stage)


def shared_queries():
    out = []
    for path in sorted(QUERY_DIR.rglob("*.csv")):
        qs = _csv.read_csv(path, _csv.kind_of(path))
        for i in range(len(qs.truth)):
            if i in qs.inexact:
                out.append((qs.kind, None, qs.inexact[i]))
            else:
                out.append((qs.kind, (qs.t0[i], qs.t1[i]), None))
    return out


def solve_all(queries, cases):
    answers = []
    for kind, linear, exact in queries:
        if linear is not None:
            answers.append(key(polyccd.solve_linear(kind, *linear)))
        else:
            answers.append(key(polyccd.solve(kind, exact)))
    for case in cases:
        answers.append(key(_corpus.solve_case(case)))
    return answers


def under(mode, fn, *args):
    assert LIBM.fesetround(MODES[mode]) == 0
    try:
        return fn(*args)
    finally:
        LIBM.fesetround(MODES["nearest"])


@pytest.fixture(scope="module")
def inputs():
    if not QUERY_DIR.is_dir():
        pytest.skip(f"no shared query set at {QUERY_DIR}")
    cases = []
    for path in sorted(REPO.glob("corpus/**/*.json")):
        kind, case = _corpus.read_case(path)
        if kind == "query":
            cases.append(case)
    return shared_queries(), cases


@pytest.fixture(scope="module")
def reference(inputs):
    return solve_all(*inputs)


def test_the_mode_really_changes_python_floats():
    # The switch takes effect in this process (else the test below could not fail).
    one, tiny = float("1"), float.fromhex("0x1p-60")  # runtime values: no constant folding
    assert under("upward", lambda: one + tiny) > 1.0
    assert under("nearest", lambda: one + tiny) == 1.0


@pytest.mark.parametrize("mode", ["downward", "upward", "towardzero"])
def test_answers_do_not_depend_on_the_rounding_mode(inputs, reference, mode):
    got = under(mode, solve_all, *inputs)
    assert len(got) == len(reference) > 2000
    diffs = [i for i, (a, b) in enumerate(zip(got, reference)) if a != b]
    assert not diffs, f"{len(diffs)} answers differ under {mode}, first at #{diffs[0]}"
