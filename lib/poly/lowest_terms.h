// Exact fractions put in lowest terms within the call's limits.
//
// A fraction of long numbers is reduced by one gcd of its numerator and denominator, an
// operation of GMP that cannot be interrupted and that takes seconds at millions of
// bits (measured on the 2-core reference machine, mpz_gcd of two random numbers:
// 1,000,000 bits 0.26 s, 4,000,000 bits 1.3 s, 8,000,000 bits 2.6 s, 16,000,000 bits
// 6.6 s, each 31 to 34 times the product of the same numbers). Its cost is counted
// (util::work_cost, as every exact operation), so max_work ends a call before it
// deterministically; but a time limit checked before it could be passed by seconds
// (issue 23: Motion.position at a time of 63,000 bits ended 1.3 s past max_seconds).
// So under a time limit, a gcd of numbers of kLong_limbs or more is first predicted:
// the product of the same two numbers is timed, and when kGcd_per_product times that
// would end past the deadline, the call ends now, as its time limit would (a
// Limit_reached naming the gcd and its predicted time). The product costs about 3% of
// the gcd it predicts, and only numbers of half a million bits or more pay for it.
#pragma once
#include "arith/rational.h"

namespace pccd::poly {

// 8,192 limbs = 524,288 bits: a gcd there takes about 0.1 s.
constexpr std::size_t kLong_limbs = std::size_t(1) << 13;
// The measured 31-34 (above), with a margin for a product run at a luckier moment.
constexpr double kGcd_per_product = 48;

// x in lowest terms (mpq_canonicalize) within the limits above. Limit_reached.
void lowest_terms(arith::Rational &x);
// The same for num / den given apart (den != 0): out = num / den in lowest terms.
arith::Rational lowest_terms(const arith::Integer &num, const arith::Integer &den);

}  // namespace pccd::poly
