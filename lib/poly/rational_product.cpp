// The product of two exact polynomials through integers: a = A / la and b = B / lb with
// A, B integer polynomials and la, lb the lcms of the denominators, so
// a b = (A B) / (la lb). A B is an integer convolution (mpz_addmul, no fraction), and
// each coefficient of the result is reduced once. The generic loop (poly.h) instead
// canonicalizes a fraction at every one of its deg a * deg b products and sums: a
// kinematic chain's motions (dyadic coefficients of 50-400 bits, degrees up to 14) spent
// most of their time in those gcds. Integer inputs (la = lb = 1, the exact stage's
// normal form) skip the reduction altogether.
#include "poly/poly.h"

namespace pccd::poly {

namespace {

// p = num / l with integer num and l the lcm of p's denominators.
void split(const Poly<Rational> &p, std::vector<arith::Integer> *num, arith::Integer *l) {
  *l = 1;
  for (const Rational &x : p.c) mpz_lcm(l->get_mpz_t(), l->get_mpz_t(), x.get_den_mpz_t());
  num->resize(p.c.size());
  for (size_t i = 0; i < p.c.size(); ++i) {
    arith::Integer &n = (*num)[i];
    mpz_divexact(n.get_mpz_t(), l->get_mpz_t(), p.c[i].get_den_mpz_t());
    n *= p.c[i].get_num();
  }
}

}  // namespace

template <>
Poly<Rational> operator*(const Poly<Rational> &a, const Poly<Rational> &b) {
  if (a.c.empty() || b.c.empty()) return Poly<Rational>();
  std::vector<arith::Integer> A, B;
  arith::Integer la, lb;
  split(a, &A, &la);
  split(b, &B, &lb);
  std::vector<arith::Integer> r(A.size() + B.size() - 1);
  for (size_t i = 0; i < A.size(); ++i) {
    if (sgn(A[i]) == 0) continue;
    for (size_t j = 0; j < B.size(); ++j)
      mpz_addmul(r[i + j].get_mpz_t(), A[i].get_mpz_t(), B[j].get_mpz_t());
  }
  const arith::Integer l = la * lb;
  std::vector<Rational> out(r.size());
  for (size_t k = 0; k < r.size(); ++k) {
    out[k] = Rational(r[k], l);
    if (l != 1) out[k].canonicalize();
  }
  return Poly<Rational>(std::move(out));
}

}  // namespace pccd::poly
