// Exact rationals: GMP's mpq_class (RAII, always canonical after arithmetic).
#pragma once
#include <gmpxx.h>
#include <string>

namespace pccd::arith {

using Rational = mpq_class;
using Integer = mpz_class;

// Text limits of parse_rational (PCCD_MAX_NUMBER_CHARS, PCCD_MAX_EXPONENT in polyccd.h;
// lib/api/constants.cpp checks that the two agree).
constexpr size_t kMax_number_chars = 100000;
constexpr long kMax_exponent = 100000;

// Parses an exact number: an integer ("-3"), a decimal with optional exponent
// ("0.1" is exactly 1/10, "2.5e-7", ".5", "1E3"), or a fraction of two integers
// ("-7/3", "4/-6" is rejected: the sign goes on the numerator). Leading/trailing
// spaces are not allowed. Throws Input_error naming `where` for anything else
// (empty, "abc", "1/0", "nan", "inf"), Limit_error for text longer than
// kMax_number_chars or an exponent beyond kMax_exponent.
Rational parse_rational(const std::string &text, const std::string &where);

// The exact binary value of a finite double; Input_error naming `where` otherwise.
Rational rational_from_double(double x, const std::string &where);

// "p/q" in lowest terms, or "p" when q = 1.
std::string to_string(const Rational &q);

// The double nearest to q (ties to even), independent of the current rounding mode.
double nearest_double(const Rational &q);

inline int sign(const Rational &q) { return sgn(q); }
inline bool certainly_positive(const Rational &q) { return sgn(q) > 0; }
inline bool certainly_negative(const Rational &q) { return sgn(q) < 0; }
inline bool certainly_nonneg(const Rational &q) { return sgn(q) >= 0; }
inline bool certainly_nonpos(const Rational &q) { return sgn(q) <= 0; }
inline bool is_zero(const Rational &q) { return sgn(q) == 0; }
// The same for integers (the exact root counter's subdivision runs on them).
inline int sign(const Integer &z) { return sgn(z); }
inline bool certainly_positive(const Integer &z) { return sgn(z) > 0; }
inline bool certainly_negative(const Integer &z) { return sgn(z) < 0; }
inline bool certainly_nonpos(const Integer &z) { return sgn(z) <= 0; }

}  // namespace pccd::arith
