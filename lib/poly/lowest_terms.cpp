#include "poly/lowest_terms.h"

#include <chrono>
#include <cstdio>
#include <limits>
#include <string>

#include "poly/poly.h"
#include "util/work_budget.h"

namespace pccd::poly {

void lowest_terms(arith::Rational &x) {
  const std::uint64_t n = mpz_size(x.get_num_mpz_t()), d = mpz_size(x.get_den_mpz_t());
  util::work_cost([&] { return n * d; });  // the gcd (util/work_budget.h)
  util::Work_budget *b = util::current_budget();
  if (b && n >= kLong_limbs && d >= kLong_limbs) {
    const double left = b->seconds_left();
    if (left < std::numeric_limits<double>::infinity()) {
      const auto start = std::chrono::steady_clock::now();
      arith::Integer product = x.get_num() * x.get_den();
      const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double predicted = kGcd_per_product * took;
      if (predicted >= left - took) {
        char what[160];
        std::snprintf(what, sizeof what, "the gcd of two numbers of %llu and %llu bits (about %.2g s)",
                      static_cast<unsigned long long>(mpz_sizeinbase(x.get_num_mpz_t(), 2)),
                      static_cast<unsigned long long>(mpz_sizeinbase(x.get_den_mpz_t(), 2)), predicted);
        b->stop_ahead(what);
      }
    }
  }
  x.canonicalize();
}

arith::Rational lowest_terms(const arith::Integer &num, const arith::Integer &den) {
  arith::Rational out;
  mpz_set(out.get_num_mpz_t(), num.get_mpz_t());
  mpz_set(out.get_den_mpz_t(), den.get_mpz_t());
  lowest_terms(out);
  return out;
}

}  // namespace pccd::poly
