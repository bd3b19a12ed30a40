#include "poly/subdivide.h"

namespace pccd::poly {

using arith::Integer;

// On integers: w[i] <- w[i] + w[i + 1] is 2 (w[i] + w[i + 1]) / 2, so after r passes the
// row holds 2^r times de Casteljau's row r (times L, the first step's common
// denominator). The halves' entry from row r is shifted left by n - 1 - r bits, which
// brings every entry to the one factor c = 2^(n - 1) L > 0.
void de_casteljau_halves_scaled(const std::vector<Rational> &b, std::vector<Rational> &left,
                                std::vector<Rational> &right) {
  const size_t n = b.size();
  left.assign(n, Rational(0));
  right.assign(n, Rational(0));
  if (n == 0) return;
  Integer L = 1;
  for (const Rational &x : b)
    if (x.get_den() != 1) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den_mpz_t());
  std::vector<Integer> w(n);
  for (size_t i = 0; i < n; ++i) {
    if (L == 1) {
      w[i] = b[i].get_num();
    } else {
      mpz_divexact(w[i].get_mpz_t(), L.get_mpz_t(), b[i].get_den_mpz_t());
      w[i] *= b[i].get_num();
    }
  }
  Integer t;
  auto put = [&](Rational &out, const Integer &x, size_t shift) {
    mpz_mul_2exp(t.get_mpz_t(), x.get_mpz_t(), shift);
    mpq_set_z(out.get_mpq_t(), t.get_mpz_t());  // an integer: already canonical
  };
  put(left[0], w[0], n - 1);
  put(right[n - 1], w[n - 1], n - 1);
  for (size_t r = 1; r < n; ++r) {
    for (size_t i = 0; i + r < n; ++i) w[i] += w[i + 1];
    put(left[r], w[0], n - 1 - r);
    put(right[n - 1 - r], w[n - 1 - r], n - 1 - r);
  }
}

}  // namespace pccd::poly
