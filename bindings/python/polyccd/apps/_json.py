"""Exact reading of polyccd JSON files (docs/formats.md).

A JSON number means exactly the decimal written, so numbers are kept as their literal
text (JsonNumber) and parsed by the C library, never by float(). Every error names the
JSON path of the bad value, e.g. `points[2][1][0]: "abc" is not a number`.
"""
import difflib
import json
from dataclasses import dataclass
from fractions import Fraction
from typing import List, Optional, Tuple, Union

from .. import KINDS, InputError
from ..texts import exact_fraction, ratio_text, show
from .. import kind_points
from ._reading import read_bytes, tick

QUERY_FORMAT = "polyccd-query/1"
SCENE_FORMAT = "polyccd/1"


class SceneNotSupported(InputError):
    """A polyccd/1 scene file: not supported yet by the engine."""


class JsonNumber(str):
    """The literal text of a JSON number, e.g. "0.1" (exactly 1/10)."""


class JsonConstant:
    """NaN, Infinity or -Infinity in a file: read, then rejected with its path."""

    def __init__(self, text):
        self.text = text


class _Object(dict):
    """A JSON object that remembers its duplicated keys (rejected with their path)."""
    duplicates = ()


def _object(pairs):
    obj = _Object(pairs)
    if len(obj) != len(pairs):
        seen = set()
        obj.duplicates = [k for k, _ in pairs if k in seen or seen.add(k)]
    return obj


def _number_literal(text):
    # JSON allows 1E5 and 1e+5; hand C the plain form 1e5 (same value).
    tick()  # the command line's --max-seconds covers reading (_reading.py)
    return JsonNumber(text.replace("E", "e").replace("e+", "e"))


def loads(text):
    """Parses JSON text keeping numbers exact; InputError on invalid JSON."""
    if not text.strip():
        raise InputError("empty file (expected a JSON object)")
    try:
        return json.loads(text, parse_float=_number_literal, parse_int=_number_literal,
                          parse_constant=JsonConstant, object_pairs_hook=_object)
    except json.JSONDecodeError as e:
        raise InputError(f"invalid JSON at line {e.lineno} column {e.colno}: {e.msg}") from None
    except RecursionError:
        raise InputError("invalid JSON: nested too deeply") from None


def load(path):
    """Reads and parses a JSON file; InputError on unreadable or invalid content."""
    data = read_bytes(path)  # within the reading limit on its size (_reading.py)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        raise InputError(f"not UTF-8 text (byte {e.start})") from None
    return loads(text)


def describe(value):
    """How a JSON value reads in an error message."""
    if value is True or value is False:
        return "true" if value else "false"
    if value is None:
        return "null"
    if isinstance(value, JsonConstant):
        return value.text
    if isinstance(value, JsonNumber):  # at most a short excerpt of a long number
        text = str(value)
        return text if len(text) <= 60 else f"{text[:40]}... ({len(text)} characters)"
    if isinstance(value, list):
        return "an array"
    if isinstance(value, dict):
        return "an object"
    return show(value)


def _object_at(value, path):
    if not isinstance(value, dict):
        raise InputError(f"{path}: expected a JSON object, got {describe(value)}")
    for key in value.duplicates:
        raise InputError(f"{path}: the key \"{key}\" appears more than once")
    return value


QUERY_KEYS = ("format", "kind", "points", "radii", "options", "expect", "name", "source")
OPTION_KEYS = ("time_tolerance", "min_distance")
EXPECT_KEYS = ("collides", "first_contact")


def known_keys(obj, path, keys):
    """InputError for the first key of obj that is not one of keys, naming it and its
    place and suggesting the nearest known key (a misspelt "rotaton" was ignored and
    the body stood still: issue 23)."""
    for key in obj:
        if key not in keys:
            near = difflib.get_close_matches(key, keys, n=1)
            hint = f' (did you mean "{near[0]}"?)' if near else f" (known: {', '.join(keys)})"
            where = f"{path}." if path != "(top level)" else ""
            raise InputError(f"{where}{show(key)[1:-1]}: unknown key{hint}")


def _list_at(value, path, what, length=None):
    if not isinstance(value, list):
        raise InputError(f"{path}: expected {what}, got {describe(value)}")
    if length is not None and len(value) != length:
        raise InputError(f"{path}: expected {what}, got {len(value)} items")
    return value


def number_at(value, path):
    """The text of a number (a JSON number or a string) for the C library."""
    if isinstance(value, str):  # JsonNumber too; a string's syntax is checked by C
        return str(value)
    raise InputError(f"{path}: {describe(value)} is not a number")


def _string_at(value, path):
    if isinstance(value, str) and not isinstance(value, JsonNumber):
        return value
    raise InputError(f"{path}: expected a string, got {describe(value)}")


@dataclass(frozen=True)
class Expect:
    """The `expect` block of a case: first_contact is exact, (lo, hi) or None."""
    collides: bool
    first_contact: Union[None, Fraction, Tuple[Fraction, Fraction]]
    pairs: Optional[Tuple[Tuple[str, str], ...]] = None  # scenes: body pairs in contact


@dataclass(frozen=True)
class QueryCase:
    """A validated polyccd-query/1 file; numbers are texts for the C library."""
    kind: str
    points: List[List[List[str]]]
    radii: Optional[List[str]]
    time_tolerance: Optional[str]
    expect: Optional[Expect]
    # options.min_distance (an optional extension of formats.md): the first time the
    # closed primitives are within this distance (None: 0, they touch).
    min_distance: Optional[str] = None


def _expect_at(value, path, keys=EXPECT_KEYS):
    obj = _object_at(value, path)
    known_keys(obj, path, keys)
    if "collides" not in obj:
        raise InputError(f"{path}.collides: missing (required: true or false)")
    collides = obj["collides"]
    if collides is not True and collides is not False:
        raise InputError(f"{path}.collides: expected true or false, got {describe(collides)}")
    first, fpath = obj.get("first_contact"), f"{path}.first_contact"
    if first is None:
        pass
    elif isinstance(first, list):
        _list_at(first, fpath, '["lo", "hi"]', 2)
        lo = exact_fraction(number_at(first[0], f"{fpath}[0]"), f"{fpath}[0]")
        hi = exact_fraction(number_at(first[1], f"{fpath}[1]"), f"{fpath}[1]")
        if not lo < hi:
            # the texts as written, each shortened (str() of a Fraction of more than
            # 4,300 digits raised ValueError: crashes/fuzz_readers-expect-long-lo-hi)
            raise InputError(f"{fpath}: expected lo < hi, got [{describe(first[0])}, "
                             f"{describe(first[1])}]")
        first = (lo, hi)
    else:
        first = exact_fraction(number_at(first, fpath), fpath)
    if first is not None and not collides:
        raise InputError(f"{fpath}: given, but {path}.collides is false")
    return Expect(collides, first)


def options_and_labels(top):
    """The options.time_tolerance text of a case (None when absent), checked to be a
    number > 0 here so that the error names the file's path, after checking the
    optional "name" and "source" labels are strings."""
    tolerance = None
    if "options" in top:
        options = _object_at(top["options"], "options")
        known_keys(options, "options", OPTION_KEYS)
        if "time_tolerance" in options:
            path = "options.time_tolerance"
            tolerance = number_at(options["time_tolerance"], path)
            if exact_fraction(tolerance, path) <= 0:
                raise InputError(f"{path}: {show(tolerance)} must be greater than 0")
    for key in ("name", "source"):
        if key in top:
            _string_at(top[key], key)
    return tolerance


def query_case(doc):
    """Validates a parsed query document (formats.md, polyccd-query/1)."""
    top = _object_at(doc, "(top level)")
    fmt = top.get("format")
    if fmt == SCENE_FORMAT:
        raise SceneNotSupported("a scene file (polyccd/1), not a query")
    if fmt != QUERY_FORMAT:
        got = "missing" if "format" not in top else describe(fmt)
        raise InputError(f'format: expected "{QUERY_FORMAT}" or "{SCENE_FORMAT}", got {got}')
    known_keys(top, "(top level)", QUERY_KEYS)
    kind = top.get("kind")
    if kind not in KINDS:
        got = "missing" if "kind" not in top else describe(kind)
        raise InputError(f"kind: expected one of {', '.join(KINDS)}, got {got}")
    n = kind_points(kind)
    if "points" not in top:
        raise InputError(f"points: missing ({kind} queries have {n} point trajectories)")
    trajs = _list_at(top["points"], "points", f"{n} point trajectories ({kind})", n)
    points = []
    for i, traj in enumerate(trajs):
        axes = _list_at(traj, f"points[{i}]", "[xs, ys, zs] (3 coefficient lists)", 3)
        points.append([[number_at(c, f"points[{i}][{a}][{j}]") for j, c in
                        enumerate(_list_at(xs, f"points[{i}][{a}]", "a list of coefficients"))]
                       for a, xs in enumerate(axes)])
    radii = None
    if kind == "sphere-sphere":
        if "radii" not in top:
            raise InputError("radii: missing (a sphere-sphere query needs [ra, rb])")
        radii = [number_at(r, f"radii[{k}]")
                 for k, r in enumerate(_list_at(top["radii"], "radii", "[ra, rb]", 2))]
    elif "radii" in top:
        raise InputError(f"radii: only sphere-sphere queries have radii, not {kind}")
    tolerance = options_and_labels(top)
    expect = _expect_at(top["expect"], "expect") if "expect" in top else None
    return QueryCase(kind, points, radii, tolerance, expect, min_distance_option(top))


def min_distance_option(top):
    """options.min_distance of a query file (None when absent), a number >= 0."""
    options = top.get("options")
    if not isinstance(options, dict) or "min_distance" not in options:
        return None
    path = "options.min_distance"
    text = number_at(options["min_distance"], path)
    if exact_fraction(text, path) < 0:
        raise InputError(f"{path}: {show(text)} must be >= 0")
    return text


def read_query(path):
    """Reads and validates a query file; InputError (or SceneNotSupported) otherwise."""
    return query_case(load(path))


def time_json(first):
    """The JSON object of a ContactTime (None: null)."""
    return None if first is None else {
        "lo": ratio_text(first.lo.numerator, first.lo.denominator),
        "hi": ratio_text(first.hi.numerator, first.hi.denominator),
        "approx": first.approx,
        "exact": None if first.exact is None
        else ratio_text(first.exact.numerator, first.exact.denominator),
    }


def result_json(result):
    """The JSON object of a Result, as `polyccd check` prints it (formats.md)."""
    return {
        "collides": result.collides,
        "first_contact": time_json(result.first_contact),
        "features": [{"kind": f.kind, "points": list(f.points)} for f in result.features],
    }
