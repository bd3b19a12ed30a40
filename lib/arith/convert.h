// Conversions between the exact and the filtered number types.
#pragma once
#include "arith/interval.h"
#include "arith/rational.h"

namespace pccd::arith {

// An interval certainly containing q (width at most two ulps).
Interval enclose(const Rational &q);

// Number-type-generic helpers used by templated code.
template <class NT> NT from_int(long v);
template <> inline Rational from_int<Rational>(long v) { return Rational(v); }
// Integers below 2^53 in magnitude are exact doubles; callers only pass small ones.
template <> inline Interval from_int<Interval>(long v) { return Interval(static_cast<double>(v)); }

template <class NT> NT from_rational(const Rational &q);
template <> inline Rational from_rational<Rational>(const Rational &q) { return q; }
template <> inline Interval from_rational<Interval>(const Rational &q) { return enclose(q); }
// A point (an exact number of NT) >= q: q itself, or the double just above it.
template <class NT> NT from_rational_up(const Rational &q);
template <> inline Rational from_rational_up<Rational>(const Rational &q) { return q; }
template <> inline Interval from_rational_up<Interval>(const Rational &q) { return Interval(enclose(q).hi); }

}  // namespace pccd::arith
