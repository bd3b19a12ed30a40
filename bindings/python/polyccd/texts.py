"""Number texts of polyccd's file formats and messages (docs/formats.md, "Numbers"),
for applications built on polyccd (polyccd.apps is one). Exact both ways, with the C
library's grammar and size limits.

- ``exact_fraction(text, place)``: the Fraction of "3", "-0.125", "2.5e-7" or "-7/3", or
  InputError / LimitError naming ``place``.
- ``int_from_text(text)``: the int of a decimal text of any length (Python's own int()
  stops at 4,300 digits). The caller checks the characters: int() also takes "_",
  spaces and non-ASCII digits.
- ``ratio_text(p, q)``: the text "p/q" (or "p" when q == 1) of any size.
- ``show(value)``: a short rendering of a bad value for an error message (long inputs
  are cut, so a message never echoes a whole file).
- ``MAX_NUMBER_CHARS``: the longest number text the library reads (PCCD_MAX_NUMBER_CHARS).
"""
from ._numbers import exact_fraction, int_from_text, ratio_text, show
from ._pccd import lib as _lib

#: The longest number text the library reads (PCCD_MAX_NUMBER_CHARS).
MAX_NUMBER_CHARS: int = _lib.PCCD_MAX_NUMBER_CHARS

__all__ = ["exact_fraction", "int_from_text", "ratio_text", "show", "MAX_NUMBER_CHARS"]
