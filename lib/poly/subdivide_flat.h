// Subdivision_counter's run (subdivide.h) on fixed-width integers with one buffer per
// piece: F's Bernstein vector, then each condition's G_i and H_i (empty: unknown), all
// Fixed_int<N> entries of one std::vector, so a halving allocates one buffer (the left
// half; the right half overwrites the parent's buffer) instead of one vector per
// polynomial and one GMP number per entry. The same tests in the same order on the same
// integers (subdivide_fixed.h: the halving gives GMP's values entry for entry), so the
// same decisions, counts and budget as the GMP run; a piece whose halving could leave
// Fixed_int<N> (halving_fits) goes on at the next width (next_fixed_width, within the
// caller's cap) or on GMP integers through the caller's `gmp` (bool(f, gs, hs, count)).
#pragma once
#include <cstdint>
#include <vector>

#include "poly/subdivide_fixed.h"

namespace pccd::poly {

// The widths in 64-bit limbs, each about 1.5x the last (fewer unused limbs than
// doubling): 4, 6, 8, 12, 16, 24, 32; 0 past the last.
constexpr int next_fixed_width(int n) {
  return n < 4 ? 4 : n < 32 ? (n % 3 == 0 ? n / 3 * 4 : n / 2 * 3) : 0;
}

template <int N, class Gmp>
class Flat_counter {
 public:
  using F = arith::Fixed_int<N>;
  using Vec = std::vector<arith::Integer>;
  static constexpr int kMaxConditions = 15, kMaxSize = 16;

  // Segment 0 is F, 2j + 1 is G_j, 2j + 2 is H_j: entries [start[s], start[s + 1]).
  struct Piece {
    std::vector<F> d;
    int m = 0;
    uint16_t start[2 * kMaxConditions + 2];
    F *seg(int s) { return d.data() + start[s]; }
    int size(int s) const { return start[s + 1] - start[s]; }
  };

  Flat_counter(int &budget, int cap, Gmp &gmp) : budget_(budget), cap_(cap), gmp_(gmp) {}

  // Whether the flat layout takes these vectors (at most kMaxConditions conditions, F
  // not empty, no vector longer than kMaxSize); the width is the caller's check.
  static bool takes(const Vec &fb, const std::vector<Vec> &gbs, const std::vector<Vec> &hbs) {
    if (fb.empty() || fb.size() > kMaxSize || gbs.size() > kMaxConditions) return false;
    for (size_t j = 0; j < gbs.size(); ++j)
      if (gbs[j].size() > kMaxSize || hbs[j].size() > kMaxSize) return false;
    return true;
  }
  // The piece of those vectors (takes() true, every entry of sig_bits <= 64 N - 1).
  static Piece build(const Vec &fb, const std::vector<Vec> &gbs, const std::vector<Vec> &hbs) {
    Piece p;
    p.m = static_cast<int>(gbs.size());
    std::vector<const Vec *> segs{&fb};
    for (size_t j = 0; j < gbs.size(); ++j) {
      segs.push_back(&gbs[j]);
      segs.push_back(&hbs[j]);
    }
    size_t off = 0;
    for (size_t s = 0; s < segs.size(); ++s) {
      p.start[s] = static_cast<uint16_t>(off);
      off += segs[s]->size();
    }
    p.start[segs.size()] = static_cast<uint16_t>(off);
    p.d.resize(off);
    for (size_t s = 0; s < segs.size(); ++s)
      for (size_t i = 0; i < segs[s]->size(); ++i) arith::to_fixed((*segs[s])[i], p.d[p.start[s] + i]);
    return p;
  }

  bool run(Piece p, long &count) {
    if (!fits(p)) return escape(p, count);
    const int nf = p.size(0);
    const F *f = p.seg(0);
    if (all_sign(f, nf, 1) || all_sign(f, nf, -1)) return true;
    int kept[kMaxConditions], nk = 0;
    for (int j = 0; j < p.m; ++j) {
      const F *g = p.seg(2 * j + 1);
      const int ng = p.size(2 * j + 1);
      bool nonpos = true;
      for (int i = 0; i < ng && nonpos; ++i) nonpos = arith::certainly_nonpos(g[i]);
      if (nonpos) return true;
      if (!all_sign(g, ng, 1)) kept[nk++] = j;
    }
    const int v = variations(f, nf);
    if (v == 0) return true;
    if (v == 1) {
      if (nk == 0) {
        ++count;
        return true;
      }
      for (int k = 0; k < nk; ++k) {
        const int s = 2 * kept[k] + 2, nh = p.size(s);
        if (nh < 2) continue;
        if (arith::sign(p.seg(s)[0]) * arith::sign(p.seg(s)[nh - 1]) < 0) return true;
      }
    }
    if (--budget_ < 0) return false;
    // The children's layout: F, then the kept conditions' G and H. The right half is
    // written over the parent's buffer: a segment's new start is at most its old one
    // and halve() reads its input first, so no unread segment is overwritten.
    Piece left;
    left.m = nk;
    int src[2 * kMaxConditions + 1], ns = 0;
    src[ns++] = 0;
    for (int k = 0; k < nk; ++k) {
      src[ns++] = 2 * kept[k] + 1;
      src[ns++] = 2 * kept[k] + 2;
    }
    int off = 0;
    for (int s = 0; s < ns; ++s) {
      left.start[s] = static_cast<uint16_t>(off);
      off += p.size(src[s]);
    }
    left.start[ns] = static_cast<uint16_t>(off);
    left.d.resize(off);
    for (int s = 0; s < ns; ++s)
      if (p.size(src[s]) > 0)
        halve(p.seg(src[s]), p.size(src[s]), left.d.data() + left.start[s], p.d.data() + left.start[s]);
    p.d.resize(off);
    p.m = nk;
    for (int s = 0; s <= ns; ++s) p.start[s] = left.start[s];
    // The midpoint: F(1/2) and G_i(1/2) are the left halves' last entries.
    if (arith::sign(left.d[nf - 1]) == 0) {
      bool ok = true;
      for (int k = 0; k < nk && ok; ++k) ok = arith::sign(left.d[left.start[2 * k + 2] - 1]) > 0;
      if (ok) ++count;
    }
    return run(std::move(left), count) && run(std::move(p), count);
  }

 private:
  static bool all_sign(const F *b, int n, int s) {
    for (int i = 0; i < n; ++i)
      if (arith::sign(b[i]) != s) return false;
    return true;
  }
  // Sign variations; -1 when an end is zero (Subdivision_counter::variations).
  static int variations(const F *b, int n) {
    if (b[0].zero() || b[n - 1].zero()) return -1;
    int v = 0, last = 0;
    for (int i = 0; i < n; ++i) {
      const int s = arith::sign(b[i]);
      if (s == 0) continue;
      if (last != 0 && s != last) ++v;
      last = s;
    }
    return v;
  }
  static bool fits(Piece &p) {
    for (int s = 0; s <= 2 * p.m; ++s)
      if (!halving_fits(p.seg(s), p.size(s))) return false;  // n <= kMaxSize < 64
    return true;
  }
  static __attribute__((noinline)) void halve(const F *b, int n, F *left, F *right) {
    halve_fixed<N, kMaxSize>(b, n, left, right);  // its row on this frame only
  }
  // The piece on the next width, or on GMP integers, from the same values.
  bool escape(Piece &p, long &count) {
    constexpr int M = next_fixed_width(N);
    if constexpr (M != 0) {
      if (M <= cap_) {
        typename Flat_counter<M, Gmp>::Piece w;
        w.m = p.m;
        for (int s = 0; s <= 2 * p.m + 1; ++s) w.start[s] = p.start[s];
        w.d.resize(p.d.size());
        for (size_t i = 0; i < p.d.size(); ++i) w.d[i] = arith::widen<M>(p.d[i]);
        return Flat_counter<M, Gmp>(budget_, cap_, gmp_).run(std::move(w), count);
      }
    }
    auto vec = [&](int s) {
      Vec v(p.size(s));
      for (int i = 0; i < p.size(s); ++i) v[i] = arith::from_fixed(p.seg(s)[i]);
      return v;
    };
    std::vector<Vec> gs, hs;
    for (int j = 0; j < p.m; ++j) {
      gs.push_back(vec(2 * j + 1));
      hs.push_back(vec(2 * j + 2));
    }
    return gmp_(vec(0), std::move(gs), std::move(hs), count);
  }

  int &budget_;
  int cap_;
  Gmp &gmp_;
};

}  // namespace pccd::poly
