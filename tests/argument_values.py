"""Wrong values for the typed-argument property tests (tests/test_arguments_*.py): for
each kind of argument the public API takes, a hypothesis strategy of values that are
NOT of that kind (wrong types, wrong shapes, wrong values), each of which must be
refused with a polyccd.InputError naming the argument. Values are small: the calls
must stay fast (argument_cases.py)."""
import math
from fractions import Fraction

import numpy as np
from hypothesis import strategies as st


class Opaque:
    """An object of no type polyccd knows (its repr is short, as messages quote it)."""

    def __repr__(self):
        return "Opaque()"


_OTHER = st.sampled_from([Opaque(), {"a": 1}, {1, 2}, b"\x00x", 1j, float("nan"), type,
                          print, Ellipsis, np.array(["x"])])
_NOT_A_NUMBER = st.one_of(st.none(), st.booleans(), st.complex_numbers(max_magnitude=1e3).filter(lambda z: z.imag),
                          st.text(alphabet="ab /.x-e", min_size=0, max_size=4).filter(lambda s: not _is_number(s)),
                          st.sampled_from([float("nan"), float("inf"), -math.inf, [1], (), [], {}, np.bool_(True),
                                           np.array([1.0, 2.0]), "1/0", "nan", "0x10"]),
                          _OTHER)


def _is_number(s):
    try:
        Fraction(s)
        return True
    except (ValueError, ZeroDivisionError):
        return False


def _lists(elements, sizes):
    return st.lists(elements, min_size=sizes[0], max_size=sizes[1])


_REAL = st.one_of(st.integers(-3, 3), st.floats(-2, 2, allow_nan=False), st.fractions(max_denominator=5))
_BAD_ITEM = st.one_of(_NOT_A_NUMBER, _lists(_REAL, (2, 2)))


def _vectors(n):
    """Not a sequence of n real numbers."""
    wrong_len = st.integers(0, 6).filter(lambda k: k != n).flatmap(lambda k: _lists(_REAL, (k, k)))
    bad_item = st.tuples(_lists(_REAL, (n - 1, n - 1)), _BAD_ITEM, st.integers(0, n - 1)).map(
        lambda x: x[0][:x[2]] + [x[1]] + x[0][x[2]:])
    return st.one_of(st.none(), _REAL, st.text(max_size=3), wrong_len, bad_item, _OTHER,
                     st.just(np.zeros((n, 1))))


def _point_lists(width):
    """Not a list of points of `width` numbers (at least one point)."""
    row = _vectors(width)
    good_row = _lists(_REAL, (width, width))
    return st.one_of(st.none(), _REAL, st.text(max_size=3), _OTHER,
                     _lists(good_row, (0, 2)).flatmap(lambda rows: row.map(lambda r: rows + [r])),
                     _lists(_REAL, (width, width)), st.just(np.zeros((2, width + 1))),
                     st.just(np.zeros((1, 2, width))))


def _coefficient_lists(n):
    """Not n coefficient lists ([xs, ys, zs] of a translation, n = 3)."""
    good = _lists(_lists(_REAL, (1, 2)), (n, n))
    bad_row = st.one_of(st.none(), st.text(min_size=1, max_size=3), _OTHER,
                        _lists(_REAL, (0, 2)).flatmap(lambda xs: _BAD_ITEM.map(lambda b: xs + [b])))
    wrong_rows = st.integers(0, 5).filter(lambda k: k != n).flatmap(lambda k: _lists(_lists(_REAL, (1, 2)), (k, k)))
    replaced = st.tuples(good, bad_row, st.integers(0, n - 1)).map(
        lambda x: x[0][:x[2]] + [x[1]] + x[0][x[2] + 1:])
    return st.one_of(st.none(), _REAL, st.text(max_size=3), _OTHER, wrong_rows, replaced)


def _indices(width):
    """Not a list of rows of `width` nonnegative integer indices."""
    bad_index = st.one_of(st.just(-1), st.just(2 ** 40), st.just(0.5), st.just(True), st.just("0"),
                          st.none(), st.just(1.0 + 1j))
    bad_row = st.one_of(_lists(st.integers(0, 2), (0, width - 1)), _lists(st.integers(0, 2), (width + 1, width + 2)),
                        st.tuples(_lists(st.integers(0, 2), (width - 1, width - 1)), bad_index).map(
                            lambda x: x[0] + [x[1]]))
    return st.one_of(st.none(), st.integers(), st.text(max_size=3), _OTHER, bad_row.map(lambda r: [r]),
                     st.just(np.zeros((1, width), dtype=np.float64)), st.just(np.zeros((2,), dtype=np.int64)))


def _choices(valid):
    return st.one_of(st.text(max_size=6).filter(lambda s: s not in valid), st.none(), st.integers(),
                     st.booleans(), _OTHER, st.just(sorted(valid)[:1]))


def _not_instance(none_ok=False):
    """Values of no polyccd or OMPL type (for arguments that take an object of one)."""
    base = st.one_of(st.integers(), st.text(max_size=3), _OTHER, st.lists(st.integers(), max_size=2),
                     st.just(np.zeros(3)))
    return base if none_ok else st.one_of(st.none(), base)


KINDS = {
    "number": _NOT_A_NUMBER,
    "number?": _NOT_A_NUMBER.filter(lambda x: x is not None),
    "int": st.one_of(st.none(), st.booleans(), st.just(1.5), st.just(2.0), st.text(max_size=3), _OTHER,
                     st.just([1]), st.fractions().filter(lambda f: f.denominator != 1)),
    "int?": st.one_of(st.booleans(), st.just(1.5), st.just(2.0), st.text(max_size=3), _OTHER,
                      st.just([1]), st.fractions().filter(lambda f: f.denominator != 1)),
    "bool": st.one_of(st.none(), st.integers().filter(lambda i: i not in (0, 1)), st.just(0.5),
                      st.text(max_size=3), _OTHER, st.just([True])),
    "vector": _vectors(3),
    "quaternion": _vectors(4),
    "points": _point_lists(3),
    "numbers": st.one_of(st.none(), _REAL, st.text(max_size=3), _OTHER, _lists(_REAL, (0, 2)).flatmap(
        lambda xs: _BAD_ITEM.map(lambda b: xs + [b]))),
    "str": st.one_of(st.none(), st.integers(), st.booleans(), _OTHER, st.just(["x"]), st.just(b"x")),
    "str?": st.one_of(st.integers(), st.booleans(), _OTHER, st.just(["x"]), st.just(b"x")),
    "translation": _coefficient_lists(3),
    "rotation": _coefficient_lists(4),
    "triangles": _indices(3),
    "edges": _indices(2),
    "limits": _not_instance(none_ok=True),
    "body": _not_instance(),
    "bodies": st.one_of(st.none(), st.integers(), _OTHER, st.just([5]), st.just([None]), st.just("ab")),
    "motion": _not_instance(none_ok=True),
    "motion!": _not_instance(),
    "path": st.one_of(st.none(), st.integers(), _OTHER, st.just(["a.urdf"]), st.just("no/such/file.urdf"),
                      st.just("bad\0name")),
}


def choices(*valid):
    """Wrong values of an argument that is one of the strings `valid`."""
    return _choices(set(valid))


def kind(name):
    return KINDS[name] if isinstance(name, str) else name
