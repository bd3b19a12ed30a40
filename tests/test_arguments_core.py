"""Every public function and method of polyccd refuses a wrong argument by name (issue
33): hypothesis replaces one argument at a time by a wrong type, shape or value
(argument_values.py) in a valid call (argument_cases.py), 200 examples per callable,
and requires polyccd.InputError starting with the argument's place; every public name
of polyccd is covered or a listed acceptance (argument_cases.ACCEPTED)."""
import pytest

pytest.importorskip("hypothesis")
import polyccd as P  # noqa: E402
from argument_cases import CASES  # noqa: E402
from argument_check import refuses_by_name, uncovered  # noqa: E402


def test_every_public_name_is_covered():
    assert uncovered(P, CASES) == []


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_valid_call_answers(case):
    case.call(**case.valid())


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_wrong_argument_is_refused_by_name(case):
    refuses_by_name(case)
