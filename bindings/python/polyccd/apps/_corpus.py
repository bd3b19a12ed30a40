"""Corpus cases: solve a case file and compare the answer with its `expect` block
(docs/formats.md, "EXPECT")."""
import glob
from fractions import Fraction
from pathlib import Path

from .. import Error, InputError, solve
from .. import check as check_scene
from ..texts import exact_fraction, ratio_text
from ._json import SceneNotSupported, load, query_case
from ._scene_file import scene_from_doc

DEFAULT_TOLERANCE = "1e-12"


def files_under(paths, pattern):
    """The files matching pattern under each path (a file is taken as it is), sorted
    per path. A path that does not exist but is a glob pattern (`data/**/*.csv`, from a
    shell without globstar or quoted) is expanded here. InputError when nothing is there."""
    found = []
    for p in map(Path, paths):
        if p.is_dir():
            found.extend(sorted(q for q in p.rglob(pattern) if q.is_file()))
        elif p.exists():
            found.append(p)
        elif glob.has_magic(str(p)) and glob.glob(str(p), recursive=True):
            found.extend(files_under(sorted(glob.glob(str(p), recursive=True)), pattern))
        else:
            raise InputError(f"{p}: no such file or directory")
    return found


def solve_case(case, limits=None):
    """The Result of a validated QueryCase (its time tolerance applies)."""
    return solve(case.kind, case.points, case.radii,
                 time_tolerance=case.time_tolerance or DEFAULT_TOLERANCE, limits=limits,
                 min_distance=case.min_distance)


def _text(x):
    return ratio_text(x.numerator, x.denominator)


def _shown(first):
    if first.exact is not None:
        return f"exactly {_text(first.exact)}"
    return f"[{_text(first.lo)}, {_text(first.hi)}] (not exact)"


def read_case(path):
    """("query", QueryCase) or ("scene", (bodies, options, expect)) of a case file."""
    doc = load(path)
    try:
        return "query", query_case(doc)
    except SceneNotSupported:
        return "scene", scene_from_doc(doc)


def solve_scene_case(scene, limits=None, **kw):
    """The SceneResult of (bodies, options, expect) (its time tolerance applies)."""
    bodies, options, _ = scene
    return check_scene(bodies, time_tolerance=options.time_tolerance or DEFAULT_TOLERANCE,
                       limits=limits, min_distance=options.min_distance, **kw)


def compare(expect, result, tolerance):
    """Reasons why result does not meet expect (empty when it passes)."""
    if expect.pairs is not None and hasattr(result, "pairs"):
        got = tuple(p.names for p in result.pairs)
        if got != expect.pairs:
            return [f"pairs: expected {[list(p) for p in expect.pairs]}, got {[list(p) for p in got]}"]
    if result.collides != expect.collides:
        return [f"collides: expected {str(expect.collides).lower()}, "
                f"got {str(result.collides).lower()}"]
    want, got = expect.first_contact, result.first_contact
    if want is None or got is None:
        return []
    if isinstance(want, Fraction):
        if got.exact != want:
            return [f"first_contact: expected exactly {_text(want)}, got {_shown(got)}"]
        return []
    lo, hi = want
    reasons = []
    if got.exact is not None and not lo < got.exact < hi:
        reasons.append(f"first_contact: expected in ({_text(lo)}, {_text(hi)}), "
                       f"got {_shown(got)}")
    elif got.hi < lo or got.lo > hi:
        reasons.append(f"first_contact: the reported {_shown(got)} does not intersect "
                       f"the expected [{_text(lo)}, {_text(hi)}]")
    if got.hi - got.lo > tolerance:
        reasons.append(f"first_contact: the reported enclosure is {float(got.hi - got.lo):.3g}"
                       f" wide, wider than the time tolerance {_text(tolerance)}")
    return reasons


def check_case(path):
    """Reasons why the case file at path fails (empty when it passes). A file that
    cannot be read, parsed or solved fails with its error message."""
    try:
        what, case = read_case(path)
        expect = case.expect if what == "query" else case[2]
        if expect is None:
            return ["no expect block (a corpus case needs expect.collides)"]
        given = case.time_tolerance if what == "query" else case[1].time_tolerance
        tolerance = exact_fraction(given or DEFAULT_TOLERANCE, "options.time_tolerance")
        result = solve_case(case) if what == "query" else solve_scene_case(case)
    except InputError as e:
        return [str(e)]
    except (Error, MemoryError) as e:  # a bug or no memory: this case fails, others go on
        return [f"{type(e).__name__}: {e}"]
    return compare(expect, result, tolerance)
