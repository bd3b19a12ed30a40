// Counting real roots of f on an open interval under strict sign conditions, by
// sign determination over Tarski queries (lib/poly/hermite.h):
//
//   #{t in (a, b) : f(t) = 0, g_1(t) > 0, ..., g_l(t) > 0}
//     = 2^-l' * sum over e in {1,2}^l' of TaQ(prod_i g_i^e_i mod f, f)
//
// with the condition g_0 > 0 for the open interval prepended (l' = l + 1). For one root,
// sum_e prod_i sgn(g_i)^e_i = prod_i (sgn g_i + sgn g_i^2) is 2^l' when every g_i > 0
// and 0 otherwise, which gives the identity. Roots are counted without multiplicity.
//
// Before the Tarski queries, exact-or-certified Bernstein tests on [a, b] drop
// conditions that are positive on the whole interval and answer 0 at once when f has
// no root there or some condition is <= 0 on all of it; then Bernstein subdivision
// with Descartes' rule (subdivide.h) usually settles the count. Hermite counting takes
// the residue: clusters of roots beyond the subdivision budget, and (with intervals)
// multiple roots or conditions vanishing at a root.
#pragma once
#include <type_traits>
#include <vector>

#include "poly/bernstein.h"
#include "poly/hermite.h"
#include "poly/gcd.h"
#include "poly/integer.h"
#include "poly/subdivide.h"
#include "util/work_budget.h"

namespace pccd::poly {

// Pieces the subdivision filter may split before handing over to Hermite: enough to
// separate the simple roots of typical contact polynomials (degree <= 30) on the
// short intervals of the bisection, small next to one Hermite count at high degree.
constexpr int kSubdivisionBudget = 48;
// The exact path's alternative is a Hermite count with big integers at every step of
// the bisection, far costlier than a few hundred halvings of reduced polynomials.
constexpr int kExactSubdivisionBudget = 256;

// p / (t - 1) for p(1) = 0 (synthetic division; exact for exact inputs).
template <class NT>
Poly<NT> deflate_at_one(const Poly<NT> &p) {
  const int n = p.degree();
  std::vector<NT> q(n);
  NT carry = arith::from_int<NT>(0);
  for (int i = n; i >= 1; --i) {
    carry = carry + p.c[i];
    q[i - 1] = carry;
  }
  return Poly<NT>(std::move(q));
}

// filters = false skips every filter (tests use it to check the Hermite route alone).
template <class NT>
long count_roots(const Poly<NT> &f, const std::vector<Poly<NT>> &conds, const NT &a,
                 const NT &b, bool filters = true) {
  // One work step per exact count (util/work_budget.h): on numbers of thousands of
  // digits a count is the unit between root-search steps that takes time.
  if constexpr (std::is_same<NT, Rational>::value) util::work_step();
  if (f.degree() < 1) {
    if (f.c.empty()) throw arith::Internal_error("count_roots: f is identically zero");
    return 0;  // a nonzero constant has no root
  }
  // Count on s in (0, 1) with t = a + (b - a) s. Same roots; and with intervals the
  // local polynomial keeps its relative precision on short intervals, where
  // (t - a)(b - t) in the monomial basis of t would drown in rounding errors.
  constexpr bool exact = std::is_same<NT, Rational>::value;
  const NT zero = arith::from_int<NT>(0), one = arith::from_int<NT>(1);
  Poly<NT> F = reparametrize(f, a, b);
  if constexpr (exact) F = primitive_monic_sign(std::move(F));  // same roots, integers, lc > 0
  // The exact path reads the same signs from integer multiples of the Bernstein
  // vectors (subdivide.h: bernstein_integer), the same decisions without fractions.
  if (filters) {
    bool none;
    if constexpr (exact) {
      const std::vector<arith::Integer> fb = bernstein_integer(F);
      none = F.degree() >= 0 && (all_positive(fb) || all_negative(fb));
    } else {
      none = certainly_no_root(F, zero, one);
    }
    if (none) return 0;
  }
  std::vector<Poly<NT>> active;
  for (const Poly<NT> &g : conds) {
    Poly<NT> G = reparametrize(g, a, b);
    int s = 0;
    if constexpr (exact) {
      G = primitive_positive(std::move(G));  // same signs, integers
      if (filters) s = certain_sign_on_integers(G);
    } else if (filters) {
      s = certain_sign_on(G, zero, one);
    }
    if (s < 0) return 0;  // g <= 0 on all of [a, b]
    if (s == 0) active.push_back(std::move(G));
  }
  // Subdivision filter (subdivide.h). Roots exactly at the ends of (0, 1) are not
  // counted; they are divided out first (exact zeros only) so Descartes can apply.
  Poly<NT> Fo = F;
  while (Fo.degree() >= 1 && Poly<NT>::exact_zero(Fo.c.front())) Fo.c.erase(Fo.c.begin());
  while (Fo.degree() >= 1 && Poly<NT>::exact_zero(Fo.eval(one))) Fo = deflate_at_one(Fo);
  if (Fo.degree() < 1) return 0;
  if (filters) {
    long n = 0;
    if constexpr (exact) {
      // The square-free part has the same distinct roots, all simple, so every piece
      // resolves (a double root never shows one sign variation). Only the signs at its
      // roots matter: reduce each condition modulo it (a positive multiple of the
      // remainder), and give the subdivision the common factors gcd(Fs, G_i) to
      // recognise a condition vanishing at a root. The counter runs on integers.
      const Poly<NT> Fs = squarefree_primitive(Fo);  // same distinct roots in (0, 1)
      std::vector<std::vector<arith::Integer>> gz, hz;
      for (const Poly<NT> &g : active) {
        Poly<NT> r = prem_positive(g, Fs);  // deg Fs >= 1: Fo has degree >= 1 here
        if (r.c.empty()) return 0;  // g vanishes at every root of F in (0, 1)
        gz.push_back(bernstein_integer(r));
        Poly<NT> h = gcd(Fs, r);
        hz.push_back(h.degree() >= 1 ? bernstein_integer(h) : std::vector<arith::Integer>{});
      }
      Subdivision_counter<arith::Integer> sub(kExactSubdivisionBudget);
      if (sub.count(bernstein_integer(Fs), std::move(gz), n, std::move(hz))) return n;
    } else {
      std::vector<std::vector<NT>> gbs;
      for (const Poly<NT> &g : active) gbs.push_back(bernstein_coefficients(g, zero, one));
      Subdivision_counter<NT> sub(kSubdivisionBudget);
      if (sub.count(bernstein_coefficients(Fo, zero, one), std::move(gbs), n)) return n;
    }
  }
  // g_0 = s (1 - s)
  active.insert(active.begin(), Poly<NT>(std::vector<NT>{zero, one, -one}));
  arith::sign(F.lc());  // Uncertain unless the degree of f is certain
  Hermite<NT> H(F);
  std::vector<Poly<NT>> g1, g2;  // g_i mod F and g_i^2 mod F
  // Reduction modulo F; the exact path uses positive multiples (pseudo-remainders),
  // which keep every TaQ unchanged and every coefficient an integer.
  auto reduce = [&](const Poly<NT> &p) {
    if constexpr (exact) return prem_positive(p, F); else return rem(p, F);
  };
  for (const Poly<NT> &g : active) {
    g1.push_back(reduce(g));
    g2.push_back(reduce(g1.back() * g1.back()));
  }
  const size_t l = active.size();
  long sum = 0;
  for (size_t mask = 0; mask < (size_t(1) << l); ++mask) {
    Poly<NT> prod = Poly<NT>::constant(one);
    for (size_t i = 0; i < l && !prod.c.empty(); ++i)
      prod = reduce(prod * ((mask >> i & 1) ? g2[i] : g1[i]));
    sum += H.taq(prod);
  }
  const long denom = long(1) << l;
  if (sum < 0 || sum % denom != 0)
    throw arith::Internal_error("count_roots: sign determination gave a non-integer count");
  return sum / denom;
}

// True when t is a root of f (f may be identically zero) with every g_i(t) > 0.
template <class NT>
bool satisfies(const Poly<NT> &f, const std::vector<Poly<NT>> &conds, const NT &t) {
  if (!f.c.empty() && !arith::is_zero(f.eval(t))) return false;
  for (const Poly<NT> &g : conds)
    if (arith::sign(g.eval(t)) <= 0) return false;
  return true;
}

}  // namespace pccd::poly
