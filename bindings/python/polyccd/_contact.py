"""Contact point and normal of two touching features (pccd_contact_geometry_compute and
pccd_contact_geometry_exact in polyccd.h have the definitions; only conversion here)."""
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING, Optional, Tuple

import numpy as np

from ._errors import InputError, check
from ._numbers import fraction_from_text, ratio_text, show
from ._pccd import ffi, lib
from ._results import ContactTime

if TYPE_CHECKING:
    from ._scene import Body

FEATURES = ("vertex", "edge", "triangle", "sphere", "solid")
NORMAL_STATES = {lib.PCCD_NORMAL_NONE: "none", lib.PCCD_NORMAL_ENCLOSED: "enclosed",
                 lib.PCCD_NORMAL_UNKNOWN: "unknown"}


@dataclass(frozen=True)
class ContactGeometry:
    """A contact point and unit normal at the first contact time t*.

    point_lo <= point <= point_hi (float64 arrays of 3); normal_state "enclosed":
    normal_lo <= the unit normal <= normal_hi, "none": no normal is defined (the arrays
    are None), "unknown": the time enclosure was too wide to decide (the arrays are
    [-1, 1]). When t* is exact, point is the exact point and normal the exact
    unnormalized normal (tuples of 3 Fractions; normal None without one), else None."""
    point_lo: np.ndarray
    point_hi: np.ndarray
    normal_state: str
    normal_lo: Optional[np.ndarray]
    normal_hi: Optional[np.ndarray]
    point: Optional[Tuple[Fraction, Fraction, Fraction]]
    normal: Optional[Tuple[Fraction, Fraction, Fraction]]


def _handle(motion):
    return motion._handle if motion is not None else ffi.NULL


def _exact_text(args, which):
    needed = ffi.new("size_t *")
    buf = ffi.new("char[]", 256)
    rc = lib.pccd_contact_geometry_exact(*args, which, buf, len(buf), needed)
    if rc == lib.PCCD_ERANGE:
        buf = ffi.new("char[]", needed[0])
        rc = lib.pccd_contact_geometry_exact(*args, which, buf, len(buf), needed)
    check(rc)
    return tuple(fraction_from_text(x) for x in ffi.string(buf).decode("ascii").split(" "))


def contact_geometry(body_a: "Body", feature_a: Tuple[str, int], body_b: "Body",
                     feature_b: Tuple[str, int], time: ContactTime) -> ContactGeometry:
    """The ContactGeometry of feature_a of body_a and feature_b of body_b (polyccd.Body;
    features as (kind, index), kind "vertex", "edge", "triangle" or "sphere") touching
    at time (a ContactTime, e.g. a Contact's first_contact)."""
    kinds, indices = [], []
    for place, f in (("feature_a", feature_a), ("feature_b", feature_b)):
        try:
            kind, index = f
        except (TypeError, ValueError):
            raise InputError(f"{place}: expected a pair (kind, index), got {show(f)}") from None
        if kind not in FEATURES:
            raise InputError(f'{place}[0]: expected "vertex", "edge", "triangle", "sphere" or "solid", '
                             f"got {show(kind)}")
        if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or index < 0:
            raise InputError(f"{place}[1]: expected an index >= 0, got {show(index)}")
        kinds.append(FEATURES.index(kind))
        indices.append(int(index))
    lo = time.exact if time.exact is not None else time.lo
    hi = time.exact if time.exact is not None else time.hi
    t_lo = ffi.new("char[]", ratio_text(lo.numerator, lo.denominator).encode("ascii"))
    t_hi = ffi.new("char[]", ratio_text(hi.numerator, hi.denominator).encode("ascii"))
    args = (body_a.shape._handle, _handle(body_a.motion), kinds[0], indices[0], body_b.shape._handle,
            _handle(body_b.motion), kinds[1], indices[1], t_lo, t_hi)
    out = ffi.new("pccd_contact_geometry *")
    out.struct_size = ffi.sizeof("pccd_contact_geometry")
    check(lib.pccd_contact_geometry_compute(*args, out))
    state = NORMAL_STATES[out.normal_state]
    has_normal = state != "none"
    point = normal = None
    if out.exact:
        point = _exact_text(args, 0)
        normal = _exact_text(args, 1) if state == "enclosed" else None
    return ContactGeometry(np.array(list(out.point_lo)), np.array(list(out.point_hi)), state,
                           np.array(list(out.normal_lo)) if has_normal else None,
                           np.array(list(out.normal_hi)) if has_normal else None, point, normal)
