"""Flag and plain-float arguments: conversions only (their meaning is the caller's).

flag(): a True / False option (first_contact, all_contacts, ...): a bool, a numpy bool
or the int 0 or 1; anything else (None, 2, "yes", a list) is an InputError naming it,
where Python's truthiness would silently read it.
real(): a number the bindings take as a float64 (Mesh.box extents, Mesh.cylinder's
radius and height, which are documented as floats): an int, float or numpy real
number, or a Fraction (its nearest double); not a bool, str, complex or None.
"""
import numbers

import numpy as np

from ._errors import InputError
from ._numbers import show


def flag(value, place: str) -> bool:
    if isinstance(value, (bool, np.bool_)) or (isinstance(value, numbers.Integral) and value in (0, 1)):
        return bool(value)
    raise InputError(f"{place}: expected True or False, got {show(value)}")


def real(value, place: str) -> float:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        raise InputError(f"{place}: expected a real number, got {show(value)}")
    try:
        return float(value)
    except OverflowError:
        raise InputError(f"{place}: {show(value)} is beyond the double range") from None
