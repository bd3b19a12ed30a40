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

std::vector<Integer> bernstein_integer(const Poly<Rational> &p) {
  if (p.c.empty()) return {Integer(0)};
  const size_t n = p.c.size() - 1;
  Integer L = 1, M = 1;
  for (const Rational &x : p.c)
    if (x.get_den() != 1) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den_mpz_t());
  std::vector<Integer> binom(n + 1);  // C(n, i)
  for (size_t i = 0; i <= n; ++i) {
    mpz_bin_uiui(binom[i].get_mpz_t(), n, i);
    mpz_lcm(M.get_mpz_t(), M.get_mpz_t(), binom[i].get_mpz_t());
  }
  std::vector<Integer> w(n + 1);
  for (size_t i = 0; i <= n; ++i) {
    Integer &x = w[i];
    mpz_divexact(x.get_mpz_t(), M.get_mpz_t(), binom[i].get_mpz_t());  // M / C(n, i)
    x *= p.c[i].get_num();
    if (L != 1) {
      Integer q;
      mpz_divexact(q.get_mpz_t(), L.get_mpz_t(), p.c[i].get_den_mpz_t());
      x *= q;
    }
  }
  // Pass r adds w[k - 1] to w[k] for k = n down to r: after pass r, w[k] (k <= r) holds
  // sum_i C(k, i) w_i and w[k] (k > r) sum_{j <= r} C(r, j) w_{k - j}; after pass n all do.
  for (size_t r = 1; r <= n; ++r)
    for (size_t k = n; k >= r; --k) w[k] += w[k - 1];
  return w;
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
// 2^r times de Casteljau's row r. The left half's entry from row r is shifted left by
// n - 1 - r bits, which brings every entry to the one factor 2^(n - 1). The right half
// is w itself at the end (pass r last writes w[n - 1 - r], its entry from row r): w[j]
// shifted left by j bits.
void de_casteljau_halves_scaled(std::vector<Integer> w, std::vector<Integer> &left,
                                std::vector<Integer> &right) {
  const size_t n = w.size();
  left.resize(n);
  if (n == 0) {
    right.clear();
    return;
  }
  mpz_mul_2exp(left[0].get_mpz_t(), w[0].get_mpz_t(), n - 1);
  for (size_t r = 1; r < n; ++r) {
    for (size_t i = 0; i + r < n; ++i) w[i] += w[i + 1];
    mpz_mul_2exp(left[r].get_mpz_t(), w[0].get_mpz_t(), n - 1 - r);
  }
  for (size_t j = 1; j < n; ++j) mpz_mul_2exp(w[j].get_mpz_t(), w[j].get_mpz_t(), j);
  right = std::move(w);
  drop_common_twos(left);
  drop_common_twos(right);
}

}  // namespace pccd::poly
