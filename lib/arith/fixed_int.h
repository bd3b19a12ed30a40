// Fixed-width signed integers: N 64-bit limbs in two's complement, least significant
// limb first, on the stack (no allocation). For the exact root counter's Bernstein
// subdivision (poly/subdivide_fixed.h, subdivide_flat.h), whose numbers are sums and shifts of integers of
// a few hundred bits: the same values as GMP's, without a malloc per number.
//
// No operation here checks for overflow: the caller proves a bound first. The contract
// is stated with sig_bits(x), the least s >= 0 with -2^s <= x < 2^s; a Fixed_int<N>
// holds exactly the x with sig_bits(x) <= 64 N - 1. a + b is exact when both have
// sig_bits <= 64 N - 2 (then the sum has sig_bits <= 64 N - 1); x << k is exact when
// sig_bits(x) + k <= 64 N - 1. Conversions from GMP say when a value does not fit.
#pragma once
#include <cstdint>
#include <gmp.h>

#include "arith/rational.h"

namespace pccd::arith {

static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8, "64-bit GMP limbs expected");

template <int N>
struct Fixed_int {
  static constexpr int kBits = 64 * N;  // values: sig_bits <= kBits - 1
  uint64_t limb[N];

  bool negative() const { return (limb[N - 1] >> 63) != 0; }
  bool zero() const {
    uint64_t o = 0;
    for (int i = 0; i < N; ++i) o |= limb[i];
    return o == 0;
  }

  // *this += b (see the header for when this is exact).
  void add(const Fixed_int &b) {
    unsigned __int128 c = 0;
    for (int i = 0; i < N; ++i) {
      c += static_cast<unsigned __int128>(limb[i]) + b.limb[i];
      limb[i] = static_cast<uint64_t>(c);
      c >>= 64;
    }
  }

  // *this <<= k, 0 <= k < kBits (exact when sig_bits + k <= kBits - 1).
  void shl(unsigned k) {
    const unsigned q = k / 64, r = k % 64;
    if (q) {
      for (int i = N - 1; i >= 0; --i) limb[i] = i >= static_cast<int>(q) ? limb[i - q] : 0;
    }
    if (r) {
      for (int i = N - 1; i > 0; --i) limb[i] = (limb[i] << r) | (limb[i - 1] >> (64 - r));
      limb[0] <<= r;
    }
  }

  // *this >>= k arithmetically (floor division by 2^k), 0 <= k < kBits.
  void sar(unsigned k) {
    const unsigned q = k / 64, r = k % 64;
    const uint64_t fill = negative() ? ~uint64_t(0) : 0;
    if (q) {
      for (int i = 0; i < N; ++i) limb[i] = i + static_cast<int>(q) < N ? limb[i + q] : fill;
    }
    if (r) {
      for (int i = 0; i + 1 < N; ++i) limb[i] = (limb[i] >> r) | (limb[i + 1] << (64 - r));
      limb[N - 1] = static_cast<uint64_t>(static_cast<int64_t>(limb[N - 1]) >> r);
    }
  }

  // The index of the lowest set bit (the same for x and -x); kBits for zero.
  unsigned low_bit() const {
    for (int i = 0; i < N; ++i)
      if (limb[i]) return 64 * i + static_cast<unsigned>(__builtin_ctzll(limb[i]));
    return kBits;
  }

  // sig_bits(*this): the bit length of x (x >= 0) or of -x - 1 = ~x (x < 0).
  unsigned sig_bits() const {
    const uint64_t m = negative() ? ~uint64_t(0) : 0;
    for (int i = N - 1; i >= 0; --i) {
      const uint64_t v = limb[i] ^ m;
      if (v) return 64 * i + 64 - static_cast<unsigned>(__builtin_clzll(v));
    }
    return 0;
  }
};

// sig_bits of a GMP integer, as Fixed_int::sig_bits defines it.
inline unsigned long sig_bits(const Integer &z) {
  if (sgn(z) >= 0) return mpz_sizeinbase(z.get_mpz_t(), 2) * (sgn(z) != 0);
  Integer m = -z - 1;  // |z| - 1
  return sgn(m) == 0 ? 0 : mpz_sizeinbase(m.get_mpz_t(), 2);
}

// z as a Fixed_int<N>; false (out untouched or partly written) when it does not fit.
template <int N>
bool to_fixed(const Integer &z, Fixed_int<N> &out) {
  const mpz_srcptr p = z.get_mpz_t();
  const size_t n = mpz_size(p);
  if (n > static_cast<size_t>(N)) return false;
  for (int i = 0; i < N; ++i) out.limb[i] = static_cast<size_t>(i) < n ? mpz_getlimbn(p, i) : 0;
  if (out.negative())  // |z| >= 2^(kBits-1): only z = -2^(kBits-1) fits, as its own complement
    return sgn(z) < 0 && mpz_scan1(p, 0) == static_cast<mp_bitcnt_t>(Fixed_int<N>::kBits - 1);
  if (sgn(z) < 0) {  // two's complement: ~|z| + 1
    unsigned __int128 c = 1;
    for (int i = 0; i < N; ++i) {
      c += ~out.limb[i];
      out.limb[i] = static_cast<uint64_t>(c);
      c >>= 64;
    }
  }
  return true;
}

// x as a GMP integer (always exact).
template <int N>
Integer from_fixed(const Fixed_int<N> &x) {
  uint64_t mag[N];
  const bool neg = x.negative();
  unsigned __int128 c = neg ? 1 : 0;
  for (int i = 0; i < N; ++i) {
    c += neg ? ~x.limb[i] : x.limb[i];
    mag[i] = static_cast<uint64_t>(c);
    c >>= 64;
  }
  Integer z;
  mpz_import(z.get_mpz_t(), N, -1, sizeof(uint64_t), 0, 0, mag);
  if (neg) z = -z;
  return z;
}

// x in M >= N limbs (sign-extended; always exact).
template <int M, int N>
Fixed_int<M> widen(const Fixed_int<N> &x) {
  static_assert(M >= N, "widen only");
  Fixed_int<M> y;
  const uint64_t fill = x.negative() ? ~uint64_t(0) : 0;
  for (int i = 0; i < M; ++i) y.limb[i] = i < N ? x.limb[i] : fill;
  return y;
}

// The sign tests of the counter (poly/subdivide_flat.h), as for Integer.
template <int N>
int sign(const Fixed_int<N> &x) {
  return x.negative() ? -1 : x.zero() ? 0 : 1;
}
template <int N>
bool certainly_positive(const Fixed_int<N> &x) { return sign(x) > 0; }
template <int N>
bool certainly_negative(const Fixed_int<N> &x) { return x.negative(); }
template <int N>
bool certainly_nonpos(const Fixed_int<N> &x) { return x.negative() || x.zero(); }

}  // namespace pccd::arith
