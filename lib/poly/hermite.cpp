#include "poly/hermite.h"

namespace pccd::poly {

int hankel_signature(const std::vector<int> &d) {
  // r = index of the last nonzero minor; the sequence is 1, D_1, ..., D_r.
  size_t r = d.size();
  while (r > 0 && d[r - 1] == 0) --r;
  std::vector<int> seq(r + 1);
  seq[0] = 1;
  for (size_t i = 1; i <= r; ++i) seq[i] = d[i - 1];
  // Frobenius rule for each run of zeros that follows a nonzero entry seq[h].
  for (size_t i = 1; i <= r; ++i) {
    if (seq[i] != 0) continue;
    size_t h = i - 1;  // seq[h] != 0: runs are filled left to right
    for (size_t j = 1; h + j <= r && d[h + j - 1] == 0; ++j) {
      long e = static_cast<long>(j) * static_cast<long>(j - 1) / 2;
      seq[h + j] = (e % 2 == 0) ? seq[h] : -seq[h];
    }
  }
  int sig = 0;
  for (size_t i = 0; i < r; ++i) sig += (seq[i] == seq[i + 1]) ? 1 : -1;
  return sig;
}

}  // namespace pccd::poly

namespace pccd::poly {

using arith::Integer;

Hermite<Rational>::Hermite(const Poly<Rational> &f) : n_(f.degree()) {
  if (n_ < 1) throw arith::Internal_error("Hermite: degree of f below 1");
  for (const Rational &x : f.c) {
    if (x.get_den() != 1) throw arith::Internal_error("Hermite: f is not an integer polynomial");
    c_.push_back(x.get_num());
  }
  if (sgn(c_.back()) <= 0) throw arith::Internal_error("Hermite: lc(f) must be positive");
  const int kmax = 3 * n_ - 2;
  lc_pow_.assign(kmax + 2, Integer(1));
  for (int k = 1; k < kmax + 2; ++k) lc_pow_[k] = lc_pow_[k - 1] * c_.back();
  S_.assign(kmax + 1, Integer(0));
  S_[0] = n_;
  for (int k = 1; k <= kmax; ++k) {
    util::work_cost([&] {  // the products of Newton's identity (util/work_budget.h)
      std::uint64_t c = 0;
      for (int j = 1; j <= std::min(k, n_); ++j)
        c += (limbs(c_[n_ - j]) + limbs(lc_pow_[j - 1])) * (limbs(S_[k - j]) + limbs(lc_pow_[j - 1]));
      return c;
    });
    Integer acc = 0;
    for (int j = 1; j <= std::min(k - 1, n_); ++j) acc += c_[n_ - j] * lc_pow_[j - 1] * S_[k - j];
    if (k <= n_) acc += k * c_[n_ - k] * lc_pow_[k - 1];
    S_[k] = -acc;
  }
}

int Hermite<Rational>::taq(const Poly<Rational> &g) const {
  if (g.degree() >= n_) throw arith::Internal_error("Hermite::taq: g not reduced mod f");
  if (g.c.empty()) return 0;
  const int m = g.degree();
  std::vector<Integer> gi;
  for (const Rational &x : g.c) {
    if (x.get_den() != 1) throw arith::Internal_error("Hermite::taq: g is not an integer polynomial");
    gi.push_back(x.get_num());
  }
  std::vector<Integer> h(2 * n_ - 1);
  for (int k = 0; k <= 2 * n_ - 2; ++k) {
    util::work_cost([&] {
      std::uint64_t c = 0;
      for (int i = 0; i <= m; ++i) c += (limbs(gi[i]) + limbs(lc_pow_[m - i])) * (limbs(S_[k + i]) + 1);
      return c;
    });
    Integer acc = 0;
    for (int i = 0; i <= m; ++i) acc += gi[i] * S_[k + i] * lc_pow_[m - i];
    h[k] = acc;
  }
  std::vector<Integer> mat(static_cast<size_t>(n_) * n_);
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j) mat[i * n_ + j] = h[i + j];
  return hankel_signature(leading_minor_signs(mat, n_));
}

}  // namespace pccd::poly
