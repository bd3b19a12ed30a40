"""Result types of a solve, read from a pccd_result handle."""
import threading
from dataclasses import dataclass
from fractions import Fraction
from typing import Optional, Tuple

import numpy as np

from ._errors import InputError, InternalError, check
from ._numbers import fraction_from_text, show
from ._pccd import ffi, lib

KINDS = ("vertex-face", "edge-edge", "vertex-edge", "vertex-vertex", "sphere-sphere")
STAGES = {lib.PCCD_STAGE_BOUNDS: "bounds", lib.PCCD_STAGE_BERNSTEIN: "bernstein",
          lib.PCCD_STAGE_INTERVAL: "interval", lib.PCCD_STAGE_EXACT: "exact"}
_UNUSED = 2 ** (8 * ffi.sizeof("size_t")) - 1  # (size_t)-1: an unused feature point entry


@dataclass(frozen=True)
class ContactTime:
    """The first contact time t*: lo <= t* <= hi; exact is t* when it is rational."""
    lo: Fraction
    hi: Fraction
    exact: Optional[Fraction]
    approx: float

    def __reduce__(self):
        """Pickles the Fractions as integer pairs (a Fraction pickles as its decimal
        text, slow to parse back for the many results of a distributed batch)."""
        e = self.exact
        return _unpickled_time, (self.lo.numerator, self.lo.denominator, self.hi.numerator,
                               self.hi.denominator, None if e is None else e.numerator,
                               None if e is None else e.denominator, self.approx)


def _unpickled_time(lo_n, lo_d, hi_n, hi_d, e_n, e_d, approx):
    lo = Fraction(lo_n, lo_d)
    hi = lo if (hi_n, hi_d) == (lo_n, lo_d) else Fraction(hi_n, hi_d)
    exact = None if e_n is None else (lo if (e_n, e_d) == (lo_n, lo_d) else Fraction(e_n, e_d))
    return ContactTime(lo, hi, exact, approx)


@dataclass(frozen=True)
class Feature:
    """Touching features: a kind of KINDS and the query point indices, in its order."""
    kind: str
    points: Tuple[int, ...]


@dataclass(frozen=True)
class Result:
    """Whether the primitives touch during [0, 1], when first, and how."""
    collides: bool
    first_contact: Optional[ContactTime]
    features: Tuple[Feature, ...]
    stage: str


class _Scratch(threading.local):
    """Per-thread output cells reused by every read (no allocation per call)."""

    def __init__(self):
        self.int_out = ffi.new("int *")
        self.size_out = ffi.new("size_t *")
        self.double_out = ffi.new("double *")
        self.buf = ffi.new("char[]", 256)
        self.points = ffi.new("size_t[4]")


_scratch = _Scratch()


def _time_text(res, which, buf):
    needed = _scratch.size_out
    rc = lib.pccd_result_time(res, which, buf, len(buf), needed)
    if rc == lib.PCCD_ERANGE:
        buf = ffi.new("char[]", needed[0])
        rc = lib.pccd_result_time(res, which, buf, len(buf), needed)
    check(rc)
    return ffi.string(buf).decode("ascii")


def _contact_time(res):
    buf = _scratch.buf
    lo = fraction_from_text(_time_text(res, 0, buf))
    hi = fraction_from_text(_time_text(res, 1, buf))
    flag = _scratch.int_out
    check(lib.pccd_result_time_is_exact(res, flag))
    exact = fraction_from_text(_time_text(res, 2, buf)) if flag[0] else None
    approx = _scratch.double_out
    check(lib.pccd_result_time_approx(res, approx))
    return ContactTime(lo, hi, exact, approx[0])


def _features(res):
    count = _scratch.size_out
    check(lib.pccd_result_feature_count(res, count))
    kind = _scratch.int_out
    points = _scratch.points
    features = []
    for i in range(count[0]):
        check(lib.pccd_result_feature(res, i, kind, points))
        if not 0 <= kind[0] < len(KINDS):
            raise InternalError(f"feature {i} has the unknown kind {kind[0]}")
        features.append(Feature(KINDS[kind[0]], tuple(int(p) for p in points if p != _UNUSED)))
    return tuple(features)


def read_result(res):
    """The Result held by a solved pccd_result handle."""
    out = _scratch.int_out
    check(lib.pccd_result_collides(res, out))
    collides = bool(out[0])
    check(lib.pccd_result_stage(res, out))
    if out[0] not in STAGES:
        raise InternalError(f"the result reports the unknown stage {out[0]}")
    stage = STAGES[out[0]]
    if not collides:
        return _NO_CONTACT[stage]  # immutable, so one shared object per stage
    return Result(collides, _contact_time(res), _features(res), stage)


_NO_CONTACT = {stage: Result(False, None, (), stage) for stage in STAGES.values()}


@dataclass(frozen=True)
class Answers:
    """The answers of n results (Result or SceneResult, e.g. Index.query_many's) as
    numpy arrays, entry k of result k: collides (bool), exact (bool: the first contact
    time is known exactly), approx (float64: the library's double near the first time,
    NaN without contact), lo, hi (object arrays of Fraction: the exact enclosure, None
    without contact)."""
    collides: np.ndarray
    exact: np.ndarray
    approx: np.ndarray
    lo: np.ndarray
    hi: np.ndarray

    def __len__(self):
        return len(self.collides)


def answers(results):
    """The Answers of a sequence of Result or SceneResult objects (nothing computed:
    the results' own values, gathered into arrays)."""
    from ._solve import _items  # _solve imports this module
    results = _items(results, "results", "a sequence of Result or SceneResult objects")
    for k, r in enumerate(results):
        if not (hasattr(r, "collides") and hasattr(r, "first_contact")):
            raise InputError(f"results[{k}]: expected a Result or SceneResult, got {show(r)}")
    n = len(results)
    collides = np.fromiter((r.collides for r in results), dtype=bool, count=n)
    firsts = [r.first_contact for r in results]
    exact = np.fromiter((f is not None and f.exact is not None for f in firsts), dtype=bool,
                        count=n)
    approx = np.fromiter((np.nan if f is None else f.approx for f in firsts),
                         dtype=np.float64, count=n)
    lo, hi = np.empty(n, dtype=object), np.empty(n, dtype=object)
    lo[:] = [None if f is None else f.lo for f in firsts]
    hi[:] = [None if f is None else f.hi for f in firsts]
    return Answers(collides, exact, approx, lo, hi)

