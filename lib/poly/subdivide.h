// Root counting by Bernstein subdivision: the filter in front of the Tarski queries.
//
// On a piece of (0, 1) with Bernstein coefficients of F and of the conditions G_i:
//   - all coefficients of F of one strict sign: no root;
//   - a condition with all coefficients <= 0: no qualifying root; all > 0: dropped;
//   - Descartes' rule in the Bernstein basis: the number of roots of F in the open
//     piece, with multiplicity, is at most the number V of sign variations of its
//     coefficients and has V's parity; so V = 0 means no root, and V = 1 exactly one
//     simple root (then, with no condition left, one qualifying root);
//   - with exactly one (simple) root of F in the piece, a condition whose common
//     factor H_i = gcd(F, G_i) changes sign across the piece vanishes at that root,
//     so the root does not qualify (H_i divides F, whose only root in the piece is
//     simple, so H_i has at most that root there; the ends are not roots of F). The
//     exact path supplies H_i; with intervals there is no gcd and the rule is off;
//   - otherwise halve the piece (de Casteljau at 1/2) and decide the midpoint itself.
// Every step is exact (Rational) or certified (Interval). The exact path runs on
// integers (integer_multiple, de_casteljau_halves_scaled: each vector up to a positive
// factor, which no test above can see, since each reads the signs of one vector only),
// on fixed-width integers while a proven bound allows (subdivide_flat.h). A piece
// that stays undecided after the budget (a multiple root, a condition vanishing at a
// root, a cluster of roots) makes the whole attempt fail, and the caller counts with the
// Hermite method instead, which needs no separation at all.
#pragma once
#include <type_traits>
#include <utility>
#include <vector>

#include "poly/bernstein.h"
#include "poly/subdivide_flat.h"

namespace pccd::poly {

// x / 2. Intervals: both ends halved exactly when no bit is lost (doubling gives them
// back; any rounding mode), which is what x * [1/2, 1/2] encloses, without its outward
// rounding by an ulp; otherwise (subnormal ends, NaN) that product.
inline Rational half_of(const Rational &x) { return x / 2; }
inline arith::Interval half_of(const arith::Interval &x) {
  const double l = x.lo * 0.5, h = x.hi * 0.5;
  if (l * 2 == x.lo && h * 2 == x.hi) return arith::Interval(l, h);
  return x * arith::Interval(0.5);
}

template <class NT>
void de_casteljau_halves(const std::vector<NT> &b, std::vector<NT> &left, std::vector<NT> &right) {
  const size_t n = b.size();
  std::vector<NT> w = b;
  left.assign(n, w[0]);
  right.assign(n, w[n - 1]);
  for (size_t r = 1; r < n; ++r) {
    for (size_t i = 0; i + r < n; ++i) w[i] = half_of(w[i] + w[i + 1]);
    left[r] = w[0];
    right[n - 1 - r] = w[n - 1 - r];
  }
}

// b times the least common multiple of its denominators (a positive factor), as integers.
std::vector<arith::Integer> integer_multiple(const std::vector<Rational> &b);

// The Bernstein coefficients of p on [0, 1] (degree deg p; the zero polynomial: {0}),
// times one positive factor, as integers: integer_multiple(bernstein_coefficients(p, 0,
// 1)) up to a positive factor, without a fraction on the way. With L the lcm of p's
// denominators and M the lcm of the C(n, i): w_i = L p_i M / C(n, i) (integers), then
// b_k = sum_{i <= k} C(k, i) w_i by n passes of pairwise sums (bernstein.h's closed
// form times L M). Only for readers of signs within the vector (the counter's tests).
std::vector<arith::Integer> bernstein_integer(const Poly<Rational> &p);

// certain_sign_on(p, 0, 1) (bernstein.h) read from bernstein_integer(p): +1 when p > 0 on
// all of [0, 1], -1 when p <= 0 on all of it (the zero polynomial included), else 0.
inline int certain_sign_on_integers(const Poly<Rational> &p) {
  if (p.c.empty()) return -1;
  const std::vector<arith::Integer> b = bernstein_integer(p);
  return all_positive(b) ? 1 : all_nonpositive(b) ? -1 : 0;
}

// The same halves as de_casteljau_halves, each half times its own positive factor, on
// integers: no rational halving, no gcd per step (w[i] + w[i + 1] instead of their mean,
// each entry shifted to the common factor 2^(n-1), then the power of two common to the
// half's entries divided out to keep the numbers short). Only for users that read
// nothing but signs within each vector (Subdivision_counter below).
void de_casteljau_halves_scaled(std::vector<arith::Integer> b, std::vector<arith::Integer> &left,
                                std::vector<arith::Integer> &right);

// Halves for the counter: integers up to one positive factor per vector (its tests read
// signs only: all of one sign, sign variations, the ends, the midpoint); intervals as
// they are (halving is exact there and keeps the enclosures tight).
template <class NT>
void halves_for_signs(std::vector<NT> b, std::vector<NT> &left, std::vector<NT> &right) {
  if constexpr (std::is_same_v<NT, arith::Integer>)
    de_casteljau_halves_scaled(std::move(b), left, right);
  else
    de_casteljau_halves(b, left, right);
}

template <class NT>
class Subdivision_counter {
 public:
  explicit Subdivision_counter(int budget) : budget_(budget) {}

  // The widest fixed-width integers (64-bit limbs: 0, 4, 6, 8, 12, 16, 24 or 32) the
  // integer counter may run on before GMP (subdivide_flat.h); 0: GMP only. The same
  // decisions either way (tests/cpp/test_subdivide_fixed.cpp compares them).
  static constexpr int kFixed_limbs = 32;
  void set_fixed_limbs(int limbs) { fixed_limbs_ = limbs; }
  // The halvings left of the budget (the same on every path: the tests compare it).
  int budget_left() const { return budget_; }

  // Adds to `count` the qualifying roots in the open piece; false when undecided.
  // hbs: Bernstein coefficients of gcd(F, G_i) for each condition (empty: unknown).
  // Rational input runs on integer multiples of each vector (integer_multiple).
  bool count(const std::vector<NT> &fb, std::vector<std::vector<NT>> gbs, long &count,
             std::vector<std::vector<NT>> hbs = {}) {
    try {
      if (hbs.size() != gbs.size()) hbs.assign(gbs.size(), {});
      if constexpr (std::is_same_v<NT, Rational>) {
        Subdivision_counter<arith::Integer> on_integers(budget_);
        std::vector<std::vector<arith::Integer>> gz, hz;
        for (const auto &g : gbs) gz.push_back(integer_multiple(g));
        for (const auto &h : hbs) hz.push_back(integer_multiple(h));
        on_integers.fixed_limbs_ = fixed_limbs_;
        const bool ok = on_integers.run_integers(integer_multiple(fb), std::move(gz), std::move(hz), count);
        budget_ = on_integers.budget_;
        return ok;
      } else if constexpr (std::is_same_v<NT, arith::Integer>) {
        return run_integers(fb, std::move(gbs), std::move(hbs), count);
      }
      return run(fb, std::move(gbs), std::move(hbs), count);
    } catch (const arith::Uncertain &) {
      return false;
    }
  }

 private:
  // The sign of x when certain (always, for exact types). Intervals: arith::sign
  // without its throw, so that an undecided piece fails the count by return values:
  // unwinding the recursion's frames cost more than the counting itself.
  static bool certain_sign(const NT &x, int &s) {
    if constexpr (std::is_same_v<NT, arith::Interval>) {
      if (x.lo > 0) s = 1;
      else if (x.hi < 0) s = -1;
      else if (x.is_point_zero()) s = 0;
      else return false;
    } else {
      s = arith::sign(x);
    }
    return true;
  }

  // Sign variations with certain signs and nonzero ends; -1 when an end is zero or
  // uncertain, kUncertain when another entry's sign is (the count fails).
  static constexpr int kUncertain = -2;
  static int variations(const std::vector<NT> &b) {
    if (!(arith::certainly_positive(b.front()) || arith::certainly_negative(b.front()))) return -1;
    if (!(arith::certainly_positive(b.back()) || arith::certainly_negative(b.back()))) return -1;
    int v = 0, last = 0;
    for (const NT &x : b) {
      int s;
      if (!certain_sign(x, s)) return kUncertain;
      if (s == 0) continue;
      if (last != 0 && s != last) ++v;
      last = s;
    }
    return v;
  }

  using Vectors = std::vector<std::vector<NT>>;

  // GMP integers: on the narrowest Fixed_int<N> (N <= fixed_limbs_) whose halving
  // every vector passes, in the flat layout (subdivide_flat.h), else on GMP. The same
  // values, so the same run.
  bool run_integers(std::vector<NT> fb, Vectors gbs, Vectors hbs, long &count) {
    auto gmp = [this](std::vector<NT> f, Vectors g, Vectors h, long &c) {
      return run(std::move(f), std::move(g), std::move(h), c);
    };
    using Gmp = decltype(gmp);
    if (fixed_limbs_ >= 4 && Flat_counter<4, Gmp>::takes(fb, gbs, hbs)) {
      unsigned long bits = halving_bits(fb);
      for (const auto &v : gbs) bits = std::max(bits, halving_bits(v));
      for (const auto &v : hbs) bits = std::max(bits, halving_bits(v));
      if (bits <= 256) return run_flat<4>(fb, gbs, hbs, count, gmp);
      if (bits <= 384 && fixed_limbs_ >= 6) return run_flat<6>(fb, gbs, hbs, count, gmp);
      if (bits <= 512 && fixed_limbs_ >= 8) return run_flat<8>(fb, gbs, hbs, count, gmp);
      if (bits <= 768 && fixed_limbs_ >= 12) return run_flat<12>(fb, gbs, hbs, count, gmp);
      if (bits <= 1024 && fixed_limbs_ >= 16) return run_flat<16>(fb, gbs, hbs, count, gmp);
      if (bits <= 1536 && fixed_limbs_ >= 24) return run_flat<24>(fb, gbs, hbs, count, gmp);
      if (bits <= 2048 && fixed_limbs_ >= 32) return run_flat<32>(fb, gbs, hbs, count, gmp);
    }
    return run(std::move(fb), std::move(gbs), std::move(hbs), count);
  }

  template <int N, class Gmp>
  bool run_flat(const std::vector<NT> &fb, const Vectors &gbs, const Vectors &hbs, long &count, Gmp &gmp) {
    Flat_counter<N, Gmp> flat(budget_, fixed_limbs_, gmp);
    return flat.run(Flat_counter<N, Gmp>::build(fb, gbs, hbs), count);
  }

  bool run(std::vector<NT> fb, std::vector<std::vector<NT>> gbs,
           std::vector<std::vector<NT>> hbs, long &count) {
    if (all_positive(fb) || all_negative(fb)) return true;
    std::vector<std::vector<NT>> left_g, left_h;
    for (size_t i = 0; i < gbs.size(); ++i) {
      if (all_nonpositive(gbs[i])) return true;
      if (!all_positive(gbs[i])) {
        left_g.push_back(std::move(gbs[i]));
        left_h.push_back(std::move(hbs[i]));
      }
    }
    const int v = variations(fb);
    if (v == kUncertain) return false;
    if (v == 0) return true;
    if (v == 1) {
      if (left_g.empty()) {
        ++count;
        return true;
      }
      for (const auto &h : left_h) {
        int s0, s1;
        if (h.size() < 2) continue;
        if (!certain_sign(h.front(), s0) || !certain_sign(h.back(), s1)) return false;
        if (s0 * s1 < 0) return true;
      }
    }
    if (--budget_ < 0) return false;
    std::vector<NT> fl, fr;
    halves_for_signs(std::move(fb), fl, fr);  // fb, left_g, left_h are not read again
    std::vector<std::vector<NT>> gl(left_g.size()), gr(left_g.size());
    std::vector<std::vector<NT>> hl(left_h.size()), hr(left_h.size());
    for (size_t i = 0; i < left_g.size(); ++i) {
      halves_for_signs(std::move(left_g[i]), gl[i], gr[i]);
      if (!left_h[i].empty()) halves_for_signs(std::move(left_h[i]), hl[i], hr[i]);
    }
    // The midpoint: F(1/2) = fl.back(), G_i(1/2) = gl[i].back() (up to positive factors).
    int sm;
    if (!certain_sign(fl.back(), sm)) return false;
    if (sm == 0) {
      bool ok = true;
      for (size_t i = 0; i < gl.size() && ok; ++i) {
        int sg;
        if (!certain_sign(gl[i].back(), sg)) return false;
        ok = sg > 0;
      }
      if (ok) ++count;
    }
    return run(std::move(fl), std::move(gl), std::move(hl), count) &&
           run(std::move(fr), std::move(gr), std::move(hr), count);
  }

  template <class>
  friend class Subdivision_counter;
  int budget_;
  int fixed_limbs_ = kFixed_limbs;
};

}  // namespace pccd::poly
