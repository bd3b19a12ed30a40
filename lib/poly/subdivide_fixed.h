// The exact root counter's halving (de_casteljau_halves_scaled, subdivide.h) on
// fixed-width integers (arith::Fixed_int<N>): the same integers as the GMP version,
// entry for entry, in place of one allocation per number. The counter runs on them
// (subdivide_flat.h) while every vector passes halving_fits below, and otherwise goes on
// with wider integers or GMP from the same values, so its decisions and its budget are
// those of the GMP path, bit for bit.
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
#include <cstdint>
#include <vector>

#include "arith/fixed_int.h"

namespace pccd::poly {

// The bits a row of GMP integers needs for its halving in Fixed_int<N> to be exact, an
// upper bound of s + n (s the largest sig_bits, n the size; 0 for an empty row): the
// bit length of |x| >= sig_bits(x). Fits Fixed_int<N> when <= 64 N.
inline unsigned long halving_bits(const std::vector<arith::Integer> &v) {
  size_t s = 0;
  for (const auto &x : v)
    if (sgn(x) != 0) s = std::max(s, mpz_sizeinbase(x.get_mpz_t(), 2));
  return v.empty() ? 0 : s + v.size();
}

// Whether the row b[0, n) of Fixed_int<N>, 1 <= n <= 64, passes s + n <= 64 N: every
// entry in [-2^(64N-n), 2^(64N-n)), i.e. its top n + 1 bits all equal (one shift of
// the top limb per entry).
template <int N>
bool halving_fits(const arith::Fixed_int<N> *b, int n) {
  for (int i = 0; i < n; ++i) {
    const int64_t top = static_cast<int64_t>(b[i].limb[N - 1]) >> (64 - n);
    if (top != 0 && top != -1) return false;
  }
  return true;
}

// Divides v[0, n) by the largest power of two dividing all its entries (all zero:
// unchanged); the arithmetic shift is exact since those bits are 0.
template <int N>
void drop_common_twos(arith::Fixed_int<N> *v, int n) {
  unsigned k = arith::Fixed_int<N>::kBits;
  for (int i = 0; i < n; ++i) k = std::min(k, v[i].low_bit());
  if (k == arith::Fixed_int<N>::kBits || k == 0) return;
  for (int i = 0; i < n; ++i) v[i].sar(k);
}

// de_casteljau_halves_scaled (subdivide.cpp) of the row b[0, n), 1 <= n <= kMax, that
// passes halving_fits: the same steps, so the same integers, into left[0, n) and
// right[0, n). right may overlap b (b is read into a local row first).
template <int N, int kMax>
void halve_fixed(const arith::Fixed_int<N> *b, int n, arith::Fixed_int<N> *left,
                 arith::Fixed_int<N> *right) {
  arith::Fixed_int<N> w[kMax];
  for (int i = 0; i < n; ++i) w[i] = b[i];
  left[0] = w[0];
  left[0].shl(static_cast<unsigned>(n - 1));
  for (int r = 1; r < n; ++r) {
    for (int i = 0; i + r < n; ++i) w[i].add(w[i + 1]);
    left[r] = w[0];
    left[r].shl(static_cast<unsigned>(n - 1 - r));
  }
  for (int j = 0; j < n; ++j) {
    right[j] = w[j];
    if (j) right[j].shl(static_cast<unsigned>(j));
  }
  drop_common_twos(left, n);
  drop_common_twos(right, n);
}

}  // namespace pccd::poly
