"""The property of the typed-argument tests (tests/test_arguments_*.py): a call with one
argument replaced by a wrong value raises polyccd.InputError (LimitError included)
whose message starts with that argument's place; anything else fails with the call
shown. And coverage: every public name of a module is a case or a listed acceptance,
so a new public name without a case fails."""
import inspect
import os
import re

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import polyccd as P
from argument_cases import ACCEPTED, ACCEPTED_VALUES, NO_ARGUMENTS
from argument_values import kind

EXAMPLES = int(os.environ.get("POLYCCD_ARGUMENT_EXAMPLES", "200"))  # more: a wider search


def accepted(name, arg, value):
    """Whether value is a documented acceptance of argument arg (ACCEPTED_VALUES)."""
    for (n, a), (test, _why) in ACCEPTED_VALUES.items():
        if n in (name, "*") and a == arg and test(value):
            return True
    return False


def refuses_by_name(case):
    """Runs EXAMPLES calls of case, each with one argument (drawn) wrong (drawn)."""
    args = sorted(case.kinds)
    try:  # an argument whose default is None takes None (its documented default)
        none_ok = {a for a, p in inspect.signature(case.call).parameters.items() if p.default is None}
    except (TypeError, ValueError):
        none_ok = set()

    @settings(max_examples=EXAMPLES, deadline=None, database=None, report_multiple_bugs=False,
              derandomize=not os.environ.get("POLYCCD_ARGUMENT_RANDOM"),
              suppress_health_check=list(HealthCheck))
    @given(data=st.data())
    def run(data):
        arg = data.draw(st.sampled_from(args), label="argument")
        values = kind(case.kinds[arg])
        bad = data.draw(values.filter(lambda v: v is not None) if arg in none_ok else values, label="value")
        if accepted(case.name, arg, bad):
            return
        kw = case.valid()
        kw[arg] = bad
        shown = f"{case.name}({arg}={bad!r})"
        try:
            case.call(**kw)
        except P.InputError as e:
            places = case.places.get(arg, ()) + (arg,)
            pattern = rf"^(?:{'|'.join(map(re.escape, places))})(?:[\[.:, ]|$)"
            assert re.match(pattern, str(e)), f"{shown}: the message does not start with {places}: {e}"
            return
        except Exception as e:  # noqa: BLE001 - the property: nothing but InputError
            raise AssertionError(f"{shown}: {type(e).__name__}: {e}") from e
        raise AssertionError(f"{shown}: accepted (not a documented acceptance)")

    run()


def public_names(module):
    """module.__all__; every other public attribute defined by polyccd must be in it."""
    assert hasattr(module, "__all__"), f"{module.__name__} has no __all__"
    for name, value in vars(module).items():
        if name.startswith("_") or inspect.ismodule(value) or name in module.__all__:
            continue
        owner = getattr(value, "__module__", None) or ""
        assert not (owner == module.__name__ and (inspect.isfunction(value) or inspect.isclass(value))), \
            f"{module.__name__}.{name} is public but not in __all__"
    return list(module.__all__)


def uncovered(module, cases):
    """The public callables of module (functions, constructors, methods) with no case
    and no listed acceptance."""
    named = {c.name for c in cases}
    missing = []
    for name in public_names(module):
        value = getattr(module, name)
        if inspect.isclass(value):  # an accepted class's methods are still checked
            if name not in named and name not in ACCEPTED:
                missing.append(name)
            for m, f in vars(value).items():
                f = getattr(value, m)
                if m.startswith("_") or not callable(f) or isinstance(vars(value)[m], property):
                    continue
                if f"{name}.{m}" not in named and f"{name}.{m}" not in NO_ARGUMENTS:
                    missing.append(f"{name}.{m}")
        elif name in ACCEPTED:
            continue
        elif callable(value):
            if name not in named:
                missing.append(name)
        else:
            missing.append(name)
    return missing
