#include "poly/subdivide.h"

#include <algorithm>
#include <climits>

namespace pccd::poly {

using arith::Integer;

std::vector<Integer> integer_multiple(const std::vector<Rational> &b) {
  Integer L = 1;
  for (const Rational &x : b)
    if (x.get_den() != 1) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den_mpz_t());
  std::vector<Integer> z(b.size());
  for (size_t i = 0; i < b.size(); ++i) {
    if (L == 1) {
      z[i] = b[i].get_num();
    } else {
      mpz_divexact(z[i].get_mpz_t(), L.get_mpz_t(), b[i].get_den_mpz_t());
      z[i] *= b[i].get_num();
    }
  }
  return z;
}

namespace {

// Divides every entry of v by the largest power of two dividing them all (v's entries
// all zero: unchanged): a positive factor.
void drop_common_twos(std::vector<Integer> &v) {
  mp_bitcnt_t k = ULONG_MAX;
  for (const Integer &x : v)
    if (sgn(x) != 0) k = std::min<mp_bitcnt_t>(k, mpz_scan1(x.get_mpz_t(), 0));
  if (k == ULONG_MAX || k == 0) return;
  for (Integer &x : v) mpz_tdiv_q_2exp(x.get_mpz_t(), x.get_mpz_t(), k);  // exact
}

}  // namespace

// w[i] <- w[i] + w[i + 1] is 2 (w[i] + w[i + 1]) / 2, so after r passes the row holds
// 2^r times de Casteljau's row r. The halves' entry from row r is shifted left by
// n - 1 - r bits, which brings every entry to the one factor 2^(n - 1).
void de_casteljau_halves_scaled(const std::vector<Integer> &b, std::vector<Integer> &left,
                                std::vector<Integer> &right) {
  const size_t n = b.size();
  left.assign(n, Integer(0));
  right.assign(n, Integer(0));
  if (n == 0) return;
  std::vector<Integer> w = b;
  mpz_mul_2exp(left[0].get_mpz_t(), w[0].get_mpz_t(), n - 1);
  mpz_mul_2exp(right[n - 1].get_mpz_t(), w[n - 1].get_mpz_t(), n - 1);
  for (size_t r = 1; r < n; ++r) {
    for (size_t i = 0; i + r < n; ++i) w[i] += w[i + 1];
    mpz_mul_2exp(left[r].get_mpz_t(), w[0].get_mpz_t(), n - 1 - r);
    mpz_mul_2exp(right[n - 1 - r].get_mpz_t(), w[n - 1 - r].get_mpz_t(), n - 1 - r);
  }
  drop_common_twos(left);
  drop_common_twos(right);
}

}  // namespace pccd::poly
