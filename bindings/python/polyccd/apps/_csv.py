"""Reading the benchmark CSV query files (docs/formats.md, "Benchmark CSV").

8 rows per query of 7 integer columns x_num, x_den, y_num, y_den, z_num, z_den, truth;
rows: the 4 points at t = 0, then the same 4 points at t = 1. A coordinate that is not
exactly a double (never in the shared set: its denominators are powers of two) is kept
as an exact fraction and the query goes through solve() instead of collides_linear().
"""
import csv
import re
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Dict, List

import numpy as np

from .. import InputError, LimitError
from ..texts import MAX_NUMBER_CHARS, int_from_text, ratio_text, show

CSV_KINDS = ("vertex-face", "edge-edge")
POINTS = 4  # both kinds: v, f0, f1, f2 or a0, a1, b0, b1
ROWS = 2 * POINTS


@dataclass
class QuerySet:
    """The queries of one CSV file: t0, t1 of shape (N, 4, 3) and the truth column."""
    kind: str
    t0: np.ndarray
    t1: np.ndarray
    truth: np.ndarray
    inexact: Dict[int, List] = field(default_factory=dict)  # query -> exact trajectories


def kind_of(path, override=None):
    """The query kind: --kind, else the nearest folder named after a CSV kind."""
    if override is not None:
        return override
    for part in reversed(Path(path).parent.parts):
        if part in CSV_KINDS:
            return part
    raise InputError("cannot tell the query kind: the file is not under a folder named "
                     f"{' or '.join(CSV_KINDS)}; give --kind")


def _value(num, den):
    """(double, exact?) of num/den; the double is None when out of range."""
    if 0 < den <= 2 ** 1022 and den & (den - 1) == 0 and abs(num) <= 2 ** 53:
        return num / den, True  # |num| < 2^53 over a power of two, no underflow: exact
    try:
        x = num / den
    except OverflowError:
        return None, False
    return x, Fraction(x) == Fraction(num, den)


_INTEGER = re.compile(r"[+-]?[0-9]+", re.ASCII)


def _integer(text, line, column):
    """The int of an ASCII decimal integer ("1_000", "\u0661" and " 1 " are not: int()
    takes them), of any length up to the number text limit; errors quote an excerpt."""
    if not _INTEGER.fullmatch(text):
        raise InputError(f"line {line}, column {column}: expected an integer (ASCII digits), "
                         f"got {show(text)}")
    if len(text) > MAX_NUMBER_CHARS:
        raise LimitError(f"line {line}, column {column}: an integer of {len(text)} characters is "
                         f"longer than the limit {MAX_NUMBER_CHARS}")
    return int_from_text(text)


def _rows(path):
    try:
        with open(path, newline="") as f:
            return list(csv.reader(f))
    except OSError as e:
        raise InputError(f"cannot read the file: {e.strerror}") from None
    except (UnicodeDecodeError, csv.Error) as e:
        raise InputError(f"not a CSV text file: {e}") from None


def read_csv(path, kind):
    """The QuerySet of a CSV file, or InputError naming the line."""
    rows = _rows(path)
    if not rows or len(rows) % ROWS:
        raise InputError(f"{len(rows)} rows: expected a positive multiple of {ROWS} "
                         f"({ROWS} rows per query)")
    n = len(rows) // ROWS
    coords = np.empty((n * ROWS, 3))
    inexact_rows = set()  # rows with a coordinate that is not exactly a double
    truth = np.empty(n, dtype=bool)
    for r, row in enumerate(rows):
        line = r + 1
        if len(row) != 7:
            raise InputError(f"line {line}: expected 7 columns, got {len(row)}")
        v = [_integer(x, line, c + 1) for c, x in enumerate(row)]
        if v[6] not in (0, 1):
            raise InputError(f"line {line}: truth must be 0 or 1, got {v[6]}")
        q, first = divmod(r, ROWS)
        if first == 0:
            truth[q] = v[6] == 1
        elif truth[q] != (v[6] == 1):
            raise InputError(f"line {line}: truth {v[6]} disagrees with line {q * ROWS + 1} "
                             "(the first row of the query)")
        for axis in range(3):
            num, den = v[2 * axis], v[2 * axis + 1]
            if den == 0:
                raise InputError(f"line {line}: zero denominator in column {2 * axis + 2}")
            x, ok = _value(num, den)
            coords[r, axis] = x if ok else 0.0
            if not ok:
                inexact_rows.add(r)
    coords = coords.reshape(n, ROWS, 3)
    qs = QuerySet(kind, np.ascontiguousarray(coords[:, :POINTS]),
                  np.ascontiguousarray(coords[:, POINTS:]), truth)
    for q in sorted({r // ROWS for r in inexact_rows}):
        qs.inexact[q] = _trajectories(rows[q * ROWS:(q + 1) * ROWS])
    return qs


def _trajectories(rows):
    """[xs, ys, zs] per point, exact: x(t) = x0 + (x1 - x0) t, as number texts."""
    pts = [[Fraction(int_from_text(row[2 * a]), int_from_text(row[2 * a + 1])) for a in range(3)]
           for row in rows]
    return [[[ratio_text(c.numerator, c.denominator) for c in (x0, x1 - x0)]
             for x0, x1 in zip(pts[k], pts[k + POINTS])] for k in range(POINTS)]
