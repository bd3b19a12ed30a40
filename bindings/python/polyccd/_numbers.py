"""Exact conversion of Python numbers to the C library's number strings, and back.

Numbers travel to C as text: an int as its decimal digits, a Fraction as "p/q", a str as
written (the C library parses it and says what is wrong), a float as its exact binary
value "p/q". Nothing here rounds. Python refuses int <-> str conversions of more than
sys.get_int_max_str_digits() (4300) digits, so long integers are converted in pieces.
"""
import numbers
import re
from decimal import Decimal
from fractions import Fraction

import numpy as np

from ._errors import InputError, LimitError
from ._pccd import lib

_SAFE_BITS = 10000  # < 4300 decimal digits: str(n) and int(s) are always allowed
_SAFE_DIGITS = 4000


def show(value):
    """A short readable rendering of a bad value for an error message."""
    if isinstance(value, str):
        text = value if len(value) <= 60 else f"{value[:40]}... ({len(value)} characters)"
        return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, numbers.Integral) and not isinstance(value, bool) \
            and int(value).bit_length() >= _SAFE_BITS:  # repr() refuses > 4,300 digits
        return f"an integer of {int(value).bit_length()} bits"
    try:
        text = repr(value)
    except ValueError:  # e.g. a Fraction of such integers
        return f"a {type(value).__name__} too long to show"
    return text if len(text) <= 60 else text[:40] + "..."


def _digits(n):
    """Decimal digits of n >= 0, whatever its size."""
    if n.bit_length() < _SAFE_BITS:
        return str(n)
    k = n.bit_length() * 3 // 20  # about half of the digits (log10(2) ~ 0.3)
    hi, lo = divmod(n, 10 ** k)
    return _digits(hi) + _digits(lo).rjust(k, "0")


def int_text(n):
    """Decimal text of an int of any size."""
    return "-" + _digits(-n) if n < 0 else _digits(n)


def int_from_text(s):
    """int of a decimal text of any length (optional sign)."""
    if len(s) <= _SAFE_DIGITS:
        return int(s)
    if s[0] in "+-":
        value = int_from_text(s[1:])
        return -value if s[0] == "-" else value
    k = len(s) // 2
    return int_from_text(s[:-k]) * 10 ** k + int_from_text(s[-k:])


def ratio_text(p, q):
    """Text of the rational p/q (q > 0)."""
    return int_text(p) if q == 1 else f"{int_text(p)}/{int_text(q)}"


def fraction_from_text(s):
    """Fraction of the C library's output "p/q" or "p". The C texts are in lowest terms
    with a positive denominator, so a long one is taken as it is: Fraction() would
    divide by the gcd again, and Python's gcd of numbers of millions of digits takes
    minutes (Motion.position at a time of 63,000 bits answers 6 million digits)."""
    num, _, den = s.partition("/")
    if len(s) <= _SAFE_DIGITS:
        return Fraction(int(num), int(den) if den else 1)
    return _coprime(int_from_text(num), int_from_text(den) if den else 1)


def _coprime(n, d):
    """The Fraction n / d of coprime n and d > 0, without a gcd."""
    made = getattr(Fraction, "_from_coprime_ints", None)  # Python 3.12 and later
    if made is not None:
        return made(n, d)
    f = object.__new__(Fraction)
    f._numerator, f._denominator = n, d
    return f


def number_text(value, place):
    """The exact C text of one number, or InputError naming `place`."""
    if isinstance(value, str):
        if "\0" in value:
            raise InputError(f"{place}: {show(value)} contains a NUL character")
        return value
    if isinstance(value, (bool, np.bool_)):
        raise InputError(f"{place}: {value!r} is a boolean, not a number")
    if isinstance(value, numbers.Integral):
        return int_text(int(value))
    if isinstance(value, numbers.Rational):
        return ratio_text(int(value.numerator), int(value.denominator))
    if isinstance(value, Decimal):
        # Its own text ("1E+999999999"), parsed by C within the text limits: Decimal's
        # as_integer_ratio() would build 10^999999999 first (issue 23: it hung).
        if not value.is_finite():
            raise InputError(f"{place}: {show(value)} is not a finite number")
        return str(value)
    as_ratio = getattr(value, "as_integer_ratio", None)  # float, numpy floats, Decimal
    if as_ratio is not None and not isinstance(value, type):
        try:
            p, q = as_ratio()
        except (ValueError, OverflowError):
            raise InputError(f"{place}: {show(value)} is not a finite number") from None
        return ratio_text(p, q)
    raise InputError(f"{place}: {show(value)} is not a number (expected an int, "
                     f"a Fraction, a str or a float; got {type(value).__name__})")


# The number texts of the C library (polyccd.h): an integer, a decimal, a fraction.
_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE]([+-]?[0-9]+))?")
_FRACTION = re.compile(r"([+-]?[0-9]+)/([0-9]+)")


def exact_fraction(text, place):
    """The Fraction of a number text ("3", "-0.125", "2.5e-7", "-7/3"), or InputError.

    For the values the bindings compare themselves (corpus expectations, tolerances).
    Same grammar and size limits as the C library, so a hostile exponent cannot
    exhaust memory here."""
    if len(text) > lib.PCCD_MAX_NUMBER_CHARS:
        raise LimitError(f"{place}: a number of {len(text)} characters is longer than "
                         f"the limit {lib.PCCD_MAX_NUMBER_CHARS}")
    fraction = _FRACTION.fullmatch(text)
    if fraction:
        if int_from_text(fraction.group(2)) == 0:
            raise InputError(f"{place}: {show(text)} has a zero denominator")
        return Fraction(int_from_text(fraction.group(1)), int_from_text(fraction.group(2)))
    decimal = _DECIMAL.fullmatch(text)
    if not decimal:
        raise InputError(f"{place}: {show(text)} is not a number (expected an integer, a "
                         'decimal such as "-0.125" or "2.5e-7", or a fraction such as "-7/3")')
    exponent = decimal.group(1) or "0"
    # Leading zeros aside, more than 9 digits is beyond the limit (as in C): int() is
    # only called on the short text that remains.
    significant = exponent.lstrip("+-").lstrip("0") or "0"
    if len(significant) > 9 or int(significant) > lib.PCCD_MAX_EXPONENT:
        raise LimitError(f"{place}: the exponent of {show(text)} is beyond "
                         f"+-{lib.PCCD_MAX_EXPONENT}")
    mantissa = text.lower().partition("e")[0]
    whole, _, decimals = mantissa.partition(".")
    sign = -1 if whole.startswith("-") else 1
    digits = whole.lstrip("+-") + decimals
    value = Fraction(int_from_text(digits or "0"), 10 ** len(decimals))
    power = int(significant) * (-1 if exponent.startswith("-") else 1)
    return sign * value * Fraction(10) ** power
