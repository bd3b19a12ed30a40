#include "arith/rational.h"

#include <cmath>
#include <cctype>

#include "arith/errors.h"

namespace pccd::arith {
namespace {

bool all_digits(const std::string &s, size_t b, size_t e) {
  if (b >= e) return false;
  for (size_t i = b; i < e; ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

[[noreturn]] void bad(const std::string &text, const std::string &where) {
  std::string shown = text.size() > 40 ? text.substr(0, 40) + "..." : text;
  throw Input_error(where + ": \"" + shown +
                    "\" is not a number (expected an integer, a decimal such as "
                    "\"-0.125\" or \"2.5e-7\", or a fraction such as \"-7/3\")");
}

// Parses [+-]digits as an Integer; returns false when malformed.
bool parse_integer(const std::string &s, size_t b, size_t e, Integer &out) {
  bool neg = false;
  if (b < e && (s[b] == '+' || s[b] == '-')) neg = s[b++] == '-';
  if (!all_digits(s, b, e)) return false;
  out.set_str(s.substr(b, e - b), 10);
  if (neg) out = -out;
  return true;
}

}  // namespace

Rational parse_rational(const std::string &text, const std::string &where) {
  if (text.size() > kMax_number_chars)
    throw Limit_error(where + ": number text of " + std::to_string(text.size()) +
                      " characters exceeds the limit of " +
                      std::to_string(kMax_number_chars));
  const size_t n = text.size();
  size_t slash = text.find('/');
  if (slash != std::string::npos) {
    Integer p, q;
    if (!parse_integer(text, 0, slash, p)) bad(text, where);
    // The denominator carries no sign: "4/-6" is rejected to keep the syntax simple.
    if (!all_digits(text, slash + 1, n)) bad(text, where);
    q.set_str(text.substr(slash + 1), 10);
    if (q == 0) throw Input_error(where + ": \"" + text + "\" has a zero denominator");
    Rational r(p, q);
    r.canonicalize();
    return r;
  }
  // Decimal: [+-] digits [. digits] [(e|E) [+-] digits], at least one mantissa digit.
  size_t i = 0;
  bool neg = false;
  if (i < n && (text[i] == '+' || text[i] == '-')) neg = text[i++] == '-';
  std::string digits;
  size_t int_begin = i;
  while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) digits += text[i++];
  size_t int_len = i - int_begin;
  long frac_len = 0;
  if (i < n && text[i] == '.') {
    ++i;
    while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) {
      digits += text[i++];
      ++frac_len;
    }
  }
  if (int_len == 0 && frac_len == 0) bad(text, where);
  long exp10 = 0;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < n && (text[i] == '+' || text[i] == '-')) eneg = text[i++] == '-';
    size_t eb = i;
    while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    if (eb == i) bad(text, where);
    size_t sig = eb;  // leading zeros are no digits of the value: "1e0000000001" is 10
    while (sig + 1 < i && text[sig] == '0') ++sig;
    if (i - sig > 9) throw Limit_error(where + ": exponent of \"" + text + "\" is too large");
    exp10 = std::stol(text.substr(sig, i - sig));
    if (eneg) exp10 = -exp10;
  }
  if (i != n) bad(text, where);
  if (exp10 > kMax_exponent || exp10 < -kMax_exponent)
    throw Limit_error(where + ": exponent of \"" + text + "\" is beyond +-" +
                      std::to_string(kMax_exponent));
  Integer mant(digits, 10);
  if (neg) mant = -mant;
  long e = exp10 - frac_len;
  Integer pow10;
  mpz_ui_pow_ui(pow10.get_mpz_t(), 10, static_cast<unsigned long>(e < 0 ? -e : e));
  Rational r = e >= 0 ? Rational(mant * pow10) : Rational(mant, pow10);
  r.canonicalize();
  return r;
}

Rational rational_from_double(double x, const std::string &where) {
  if (!std::isfinite(x))
    throw Input_error(where + ": " + std::string(std::isnan(x) ? "NaN" : "infinity") +
                      " is not a finite number");
  Rational r;
  mpq_set_d(r.get_mpq_t(), x);  // exact: every finite double is a dyadic rational
  return r;
}

std::string to_string(const Rational &q) { return q.get_str(10); }

double nearest_double(const Rational &q) {
  // mpq_get_d truncates toward zero; the nearest double is that value or its
  // neighbour away from zero. Compare the two distances exactly.
  double d = mpq_get_d(q.get_mpq_t());  // truncates toward zero, exact-value based
  if (!std::isfinite(d)) return d;
  double other = std::nextafter(d, sgn(q) >= 0 ? HUGE_VAL : -HUGE_VAL);
  if (!std::isfinite(other)) return d;
  Rational dq, oq;
  mpq_set_d(dq.get_mpq_t(), d);
  mpq_set_d(oq.get_mpq_t(), other);
  Rational e1 = abs(q - dq), e2 = abs(oq - q);
  return e2 < e1 ? other : d;
}

}  // namespace pccd::arith
