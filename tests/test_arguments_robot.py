"""Every public function and method of polyccd.robot and polyccd.ompl refuses a wrong
argument by name (issue 33; the property and its conventions: argument_check.py,
argument_cases.py), 200 examples per callable; every public name is covered."""
import pytest

pytest.importorskip("hypothesis")
pytest.importorskip("yourdfpy")
from argument_cases_robot import ompl_cases, robot_cases  # noqa: E402
from argument_check import refuses_by_name, uncovered  # noqa: E402


@pytest.fixture(scope="module")
def cases(tmp_path_factory):
    found, robot = robot_cases(tmp_path_factory.mktemp("arm"))
    try:
        import ompl.base  # noqa: F401
    except ImportError:
        return found, []
    return found, ompl_cases(robot)[0]


def test_every_public_name_is_covered(cases):
    import polyccd.robot
    assert uncovered(polyccd.robot, cases[0]) == []
    if not cases[1]:
        pytest.skip("ompl is not installed")
    import polyccd.ompl
    assert uncovered(polyccd.ompl, cases[1]) == []


def test_valid_calls_answer(cases):
    for case in cases[0] + cases[1]:
        case.call(**case.valid())


def _all_refuse(cases):
    failures = []
    for case in cases:
        try:
            refuses_by_name(case)
        except AssertionError as e:
            failures.append(str(e).splitlines()[0])
    assert not failures, "\n".join(failures)


def test_robot_arguments_are_refused_by_name(cases):
    _all_refuse(cases[0])


def test_ompl_arguments_are_refused_by_name(cases):
    if not cases[1]:
        pytest.skip("ompl is not installed")
    _all_refuse(cases[1])
