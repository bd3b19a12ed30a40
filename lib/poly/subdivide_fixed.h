// The exact root counter's halving (de_casteljau_halves_scaled, subdivide.h) on
// fixed-width integers (arith::Fixed_int<N>): the same integers as the GMP version,
// entry for entry, on the stack instead of one allocation per number. The counter
// (Subdivision_counter in subdivide.h) runs on them while every vector passes
// fits_halving below, and otherwise continues on GMP integers with the same values, so
// its decisions and its budget are those of the GMP path, bit for bit.
//
// Where the bound comes from: a row of n entries x with -2^s <= x < 2^s (s the largest
// sig_bits, fixed_int.h). Pass r of the halving holds sums of 2^r entries of the row,
// in [-2^(s+r), 2^(s+r)), r <= n - 1; each output entry is such a sum from pass r
// shifted left by n - 1 - r bits (left half) or a pass-r sum shifted by j <= n - 1 - r
// (right half: w[j] last written by pass n - 1 - j), so every output lies in
// [-2^(s+n-1), 2^(s+n-1)): exact in Fixed_int<N> when s + n - 1 <= 64 N - 1. Sums and
// shifts are exact modulo 2^(64 N) in two's complement, so the outputs are the true
// integers once they fit, whatever the intermediate rows did; dropping the common
// power of two (an arithmetic shift right of values that fit) keeps them exact.
#pragma once
#include <algorithm>
#include <vector>

#include "arith/fixed_int.h"

namespace pccd::poly {

template <class>
struct is_fixed_int : std::false_type {};
template <int N>
struct is_fixed_int<arith::Fixed_int<N>> : std::true_type {};

// The bits a vector needs for its halving to be exact: s + n (s its largest sig_bits,
// n its size; 0 for an empty vector). Fits Fixed_int<N> when <= 64 N.
template <int N>
unsigned halving_bits(const std::vector<arith::Fixed_int<N>> &v) {
  unsigned s = 0;
  for (const auto &x : v) s = std::max(s, x.sig_bits());
  return v.empty() ? 0 : s + static_cast<unsigned>(v.size());
}
// For GMP integers an upper bound: the bit length of |x| >= sig_bits(x).
inline unsigned long halving_bits(const std::vector<arith::Integer> &v) {
  size_t s = 0;
  for (const auto &x : v)
    if (sgn(x) != 0) s = std::max(s, mpz_sizeinbase(x.get_mpz_t(), 2));
  return v.empty() ? 0 : s + v.size();
}

// halving_bits(v) <= 64 N, read from the top limbs: for n = |v| <= 64, every entry in
// [-2^(64N-n), 2^(64N-n)), i.e. its top n + 1 bits all equal (a shift of the top limb).
template <int N>
bool halving_fits(const std::vector<arith::Fixed_int<N>> &v) {
  const size_t n = v.size();
  if (n > 64) return halving_bits(v) <= static_cast<unsigned>(64 * N);
  if (n == 0) return true;
  for (const auto &x : v) {
    const int64_t top = static_cast<int64_t>(x.limb[N - 1]) >> (64 - n);
    if (top != 0 && top != -1) return false;
  }
  return true;
}

template <int N>
void drop_common_twos(std::vector<arith::Fixed_int<N>> &v) {
  unsigned k = arith::Fixed_int<N>::kBits;
  for (const auto &x : v) k = std::min(k, x.low_bit());
  if (k == arith::Fixed_int<N>::kBits || k == 0) return;  // all zero, or an odd entry
  for (auto &x : v) x.sar(k);  // exact: k low bits of every entry are 0
}

// de_casteljau_halves_scaled (subdivide.cpp) on Fixed_int<N>, for a row that passes
// halving_bits(w) <= 64 N: the same steps, so the same integers.
template <int N>
void de_casteljau_halves_scaled(std::vector<arith::Fixed_int<N>> w,
                                std::vector<arith::Fixed_int<N>> &left,
                                std::vector<arith::Fixed_int<N>> &right) {
  const size_t n = w.size();
  left.resize(n);
  if (n == 0) {
    right.clear();
    return;
  }
  left[0] = w[0];
  left[0].shl(static_cast<unsigned>(n - 1));
  for (size_t r = 1; r < n; ++r) {
    for (size_t i = 0; i + r < n; ++i) w[i].add(w[i + 1]);
    left[r] = w[0];
    left[r].shl(static_cast<unsigned>(n - 1 - r));
  }
  for (size_t j = 1; j < n; ++j) w[j].shl(static_cast<unsigned>(j));
  right = std::move(w);
  drop_common_twos(left);
  drop_common_twos(right);
}

// Vectors of GMP integers as Fixed_int<N> and back (every entry must fit: the callers
// check halving_bits first, which implies sig_bits <= 64 N - 1).
template <int N>
std::vector<arith::Fixed_int<N>> to_fixed(const std::vector<arith::Integer> &v) {
  std::vector<arith::Fixed_int<N>> out(v.size());
  for (size_t i = 0; i < v.size(); ++i) arith::to_fixed(v[i], out[i]);
  return out;
}
template <int N>
std::vector<arith::Integer> from_fixed(const std::vector<arith::Fixed_int<N>> &v) {
  std::vector<arith::Integer> out(v.size());
  for (size_t i = 0; i < v.size(); ++i) out[i] = arith::from_fixed(v[i]);
  return out;
}

}  // namespace pccd::poly
