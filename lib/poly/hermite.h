// Tarski queries by Hermite's method (paper, section 6):
//   TaQ(g, f) = #{t real : f(t) = 0, g(t) > 0} - #{t real : f(t) = 0, g(t) < 0}
// equals the signature of the Hermite matrix H = [Tr(g t^(i+j))]_{i,j<n} of the
// quotient algebra Q[t]/(f), whose entries are h_k = sum_i g_i s_(k+i) with s_k the
// Newton sums of f. Roots are counted without multiplicity.
//
// The signature is read off the leading principal minors D_1..D_n (Jacobi): with r the
// index of the last nonzero minor (= rank of H; a Hankel matrix of a rational series
// of degree r has D_r != 0 by Kronecker's theorem), signature = P - V over the sequence
// 1, D_1, ..., D_r, where P and V count sign permanences and variations. Runs of zero
// minors inside the sequence get signs by the Frobenius rule for Hankel matrices:
// after D_h != 0, D_(h+1) = ... = D_(h+p) = 0, take sgn D_(h+j) = (-1)^(j(j-1)/2) sgn D_h.
//
// The paper's r - V(S) - V(H) formula is not used: it is wrong when g shares a root
// with f. Sign conditions are assembled from TaQs in poly/count.h.
#pragma once
#include <type_traits>
#include <vector>

#include "arith/errors.h"
#include "arith/interval.h"
#include "arith/rational.h"
#include "poly/poly.h"
#include "util/work_budget.h"

namespace pccd::poly {

// Sign vector -> signature by Jacobi's count with the Frobenius rule.
int hankel_signature(const std::vector<int> &minor_signs /* D_1..D_n */);

// Fraction-free (Bareiss) elimination, one template for the three number types:
// Interval (an enclosure of every minor; Uncertain when a sign or a pivot is not
// certain), Rational, and Integer (the exact path, hermite.cpp), where every division
// below is exact (Bareiss: each updated entry is a minor of the original matrix).
inline arith::Integer exact_quotient(const arith::Integer &a, const arith::Integer &b) {
  arith::Integer q;
  mpz_divexact(q.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return q;
}
inline arith::Rational exact_quotient(const arith::Rational &a, const arith::Rational &b) { return a / b; }
inline arith::Interval exact_quotient(const arith::Interval &a, const arith::Interval &b) { return a / b; }
inline int sign_of(const arith::Integer &x) { return sgn(x); }
inline int sign_of(const arith::Rational &x) { return sgn(x); }
inline int sign_of(const arith::Interval &x) { return arith::sign(x); }  // Uncertain if unsure
// A pivot candidate: 1 certainly nonzero, 0 exactly zero, -1 not known (intervals).
inline int pivot_state(const arith::Integer &x) { return sgn(x) != 0; }
inline int pivot_state(const arith::Rational &x) { return sgn(x) != 0; }
inline int pivot_state(const arith::Interval &x) {
  if (x.lo > 0 || x.hi < 0) return 1;
  return x.is_point_zero() ? 0 : -1;
}

// One work step (util/work_budget.h) per exact elimination round, and each row of a
// round counted by cost (a row of long numbers can take long). Nothing for intervals.
template <class NT>
inline void exact_work_step() {
  if constexpr (std::is_same<NT, arith::Rational>::value || std::is_same<NT, arith::Integer>::value)
    util::work_step();
}
// Row i of round k: (n - k) entries m_ij m_kk - m_ik m_kj, each divided by prev.
template <class NT>
inline void row_cost(const std::vector<NT> &m, size_t n, size_t k, size_t i, const NT &prev) {
  exact_cost<NT>([&] {
    std::uint64_t c = 0;
    const std::uint64_t pk = limbs(m[k * n + k]) + limbs(m[i * n + k]) + limbs(prev);
    for (size_t j = k + 1; j < n; ++j) c += (limbs(m[i * n + j]) + limbs(m[k * n + j])) * pk;
    return 2 * c;
  });
}

// The determinant of the n*n matrix m (row-major), by Bareiss elimination with row
// pivoting: a pivot must be certainly nonzero; a column whose candidates are all exactly
// zero gives 0; one with an uncertain candidate and no certain pivot throws Uncertain.
template <class NT>
NT bareiss_determinant(std::vector<NT> m, size_t n) {
  NT prev(1);
  bool negate = false;
  for (size_t k = 0; k < n; ++k) {
    exact_work_step<NT>();
    size_t piv = n;
    bool unsure = false;
    for (size_t i = k; i < n && piv == n; ++i) {
      const int state = pivot_state(m[i * n + k]);
      if (state == 1) piv = i;
      else if (state < 0) unsure = true;
    }
    if (piv == n) {
      if (unsure) throw arith::Uncertain{};
      return NT(0);
    }
    if (piv != k) {
      for (size_t j = 0; j < n; ++j) std::swap(m[k * n + j], m[piv * n + j]);
      negate = !negate;
    }
    for (size_t i = k + 1; i < n; ++i) {
      row_cost(m, n, k, i, prev);
      for (size_t j = k + 1; j < n; ++j)
        m[i * n + j] = exact_quotient(m[i * n + j] * m[k * n + k] - m[i * n + k] * m[k * n + j], prev);
    }
    prev = m[k * n + k];
  }
  return negate ? NT(-m[n * n - 1]) : m[n * n - 1];
}

// Signs of the leading principal minors D_1..D_n of a symmetric matrix (row-major n*n):
// Bareiss without pivoting while the minors are nonzero (in Bareiss form the pivots are
// the minors themselves); after the first zero minor, each remaining minor is computed
// on its own by bareiss_determinant (with pivoting).
template <class NT>
std::vector<int> leading_minor_signs(const std::vector<NT> &a, size_t n) {
  std::vector<int> signs(n, 0);
  std::vector<NT> m = a;
  NT prev(1);
  size_t k = 0;
  // After step k, m[i][j] (i, j > k) is the minor of rows 0..k,i x cols 0..k,j, and
  // m[k][k] is D_(k+1).
  for (; k < n; ++k) {
    exact_work_step<NT>();
    signs[k] = sign_of(m[k * n + k]);
    if (signs[k] == 0) break;
    for (size_t i = k + 1; i < n; ++i) {
      row_cost(m, n, k, i, prev);
      for (size_t j = k + 1; j < n; ++j)
        m[i * n + j] = exact_quotient(m[i * n + j] * m[k * n + k] - m[i * n + k] * m[k * n + j], prev);
    }
    prev = m[k * n + k];
  }
  for (size_t s = k + 1; s < n; ++s) {  // after a zero minor: one determinant each
    std::vector<NT> sub((s + 1) * (s + 1));
    for (size_t i = 0; i <= s; ++i)
      for (size_t j = 0; j <= s; ++j) sub[i * (s + 1) + j] = a[i * n + j];
    signs[s] = sign_of(bareiss_determinant(std::move(sub), s + 1));
  }
  return signs;
}

// Newton sums of f and the Hermite matrices built from them; one per f.
template <class NT>
class Hermite {
 public:
  // f must have a certainly nonzero leading coefficient and degree >= 1.
  explicit Hermite(const Poly<NT> &f) : f_(f), n_(f.degree()) {
    if (n_ < 1) throw arith::Internal_error("Hermite: degree of f below 1");
    const NT &lc = f.lc();
    std::vector<NT> e(n_ + 1);  // monic f = t^n + e_1 t^(n-1) + ... + e_n
    for (int j = 1; j <= n_; ++j) e[j] = f.c[n_ - j] / lc;
    const int kmax = 3 * n_ - 2;  // h_k for k <= 2n-2 uses s up to 2n-2 + (n-1)
    s_.assign(kmax + 1, arith::from_int<NT>(0));
    s_[0] = arith::from_int<NT>(n_);
    for (int k = 1; k <= kmax; ++k) {  // Newton's identities
      NT acc = arith::from_int<NT>(0);
      for (int j = 1; j <= std::min(k - 1, n_); ++j) acc = acc + e[j] * s_[k - j];
      if (k <= n_) acc = acc + arith::from_int<NT>(k) * e[k];
      s_[k] = -acc;
    }
  }
  const Poly<NT> &f() const { return f_; }
  int degree() const { return n_; }

  // TaQ(g, f) for g already reduced modulo f (degree < n).
  int taq(const Poly<NT> &g) const {
    if (g.degree() >= n_) throw arith::Internal_error("Hermite::taq: g not reduced mod f");
    if (g.c.empty()) return 0;
    std::vector<NT> h(2 * n_ - 1, arith::from_int<NT>(0));
    for (int k = 0; k <= 2 * n_ - 2; ++k) {
      NT acc = arith::from_int<NT>(0);
      for (size_t i = 0; i < g.c.size(); ++i) acc = acc + g.c[i] * s_[k + i];
      h[k] = acc;
    }
    std::vector<NT> m(static_cast<size_t>(n_) * n_);
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) m[i * n_ + j] = h[i + j];
    return hankel_signature(leading_minor_signs(m, n_));
  }

 private:
  Poly<NT> f_;
  int n_;
  std::vector<NT> s_;
};

// The exact specialization works in integers: f primitive with lc > 0, g integer.
// With S_k = lc^k s_k (integers by Newton's identities multiplied through) the matrix
// M_ij = lc^(i+j+m) h_(i+j) = lc^m (D H D)_ij, D = diag(lc^i), is congruent to H up
// to the positive factor lc^m, so it has the same signature (Sylvester's law of
// inertia) and leading minors of the same signs; its Bareiss elimination divides
// exactly in the integers.
template <>
class Hermite<Rational> {
 public:
  explicit Hermite(const Poly<Rational> &f);
  int degree() const { return n_; }
  int taq(const Poly<Rational> &g) const;

 private:
  int n_;
  std::vector<arith::Integer> c_;       // coefficients of f
  std::vector<arith::Integer> lc_pow_;  // lc^0 .. lc^(3n)
  std::vector<arith::Integer> S_;       // lc^k s_k
};

}  // namespace pccd::poly
