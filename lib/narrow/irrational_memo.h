// A body pair's memo of the features whose first-touch polynomial has no rational root,
// shared by its feature pairs (pred::Irrational_features; issue 33).
//
// Why it is sound. With a minimum separation delta, the vertex-vertex feature of points
// a (of A) and b (of B) touches at the times t in [0, 1] where |a(t) - b(t)| = delta,
// and the vertex-edge feature of a point c and an edge (e0, e1) of the other body where
// c's distance to the edge's line is delta. Every query of the pair (Pair_ctx::query)
// builds these features' polynomials from the same point trajectories (traj_q: D times
// the positions, D > 0 the pair's common denominator), the same delta and the same
// scale D; they differ only by a nonzero constant (pred::integral's scaling) and a
// factor positive on [0, 1] (the edge direction taken from the own trajectories or
// from the points; either end first). So all of them have the same roots on [0, 1]. When
// one of them has no rational root at all (the modular test of pred/solve.cpp), no time
// in [0, 1] at which that feature touches is rational; a first time that is a root of
// such a feature in another query is irrational too. The memo is bound to one delta
// (a pair is solved with one; another delta leaves it unused) and lives with its
// Pair_ctx, whose trajectories are fixed.
//
// Only these two kinds are kept: the face and edge-edge features belong to one feature
// pair each (a vertex and a triangle, two edges), so nothing else asks for them.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <mutex>
#include <set>
#include <utility>

#include "pred/solve.h"

namespace pccd::narrow {

class Irrational_memo {
 public:
  // {kind, side of the first point, its index, the other points' indices}.
  using Key = std::array<uint32_t, 5>;

  // Binds the memo to delta on its first use; false when bound to another delta.
  bool bind(const arith::Rational &delta) {
    std::lock_guard<std::mutex> lock(m_);
    if (!bound_) {
      delta_ = delta;
      bound_ = true;
    }
    return delta_ == delta;
  }
  bool has(const Key &k) const {
    std::lock_guard<std::mutex> lock(m_);
    return keys_.count(k) != 0;
  }
  void add(const Key &k) {
    std::lock_guard<std::mutex> lock(m_);
    keys_.insert(k);
  }

 private:
  mutable std::mutex m_;
  std::set<Key> keys_;
  bool bound_ = false;
  arith::Rational delta_;
};

// The memo seen from one query: its points as (side, index of that side's points), in
// the query's order (Pair_ctx::query_points).
class Query_irrational final : public pred::Irrational_features {
 public:
  using Points = std::array<std::pair<int, uint32_t>, 4>;
  Query_irrational(Irrational_memo &memo, const Points &points, int n) : memo_(memo), p_(points), n_(n) {}

  bool has(const pred::Feature &f) const override {
    Irrational_memo::Key k;
    return key(f, k) && memo_.has(k);
  }
  void add(const pred::Feature &f) override {
    Irrational_memo::Key k;
    if (key(f, k)) memo_.add(k);
  }

 private:
  bool valid(int i) const { return i >= 0 && i < n_; }
  // The feature by its bodies' points: vertex-vertex {c, v} as (A's point, B's point);
  // vertex-edge {c, e0, e1} as (c's side, c, the edge's ends in increasing order).
  bool key(const pred::Feature &f, Irrational_memo::Key &k) const {
    const auto &i = f.points;
    if (f.kind == pred::VERTEX_VERTEX && valid(i[0]) && valid(i[1]) && p_[i[0]].first != p_[i[1]].first) {
      const auto &a = p_[i[0]].first == 0 ? p_[i[0]] : p_[i[1]], &b = p_[i[0]].first == 0 ? p_[i[1]] : p_[i[0]];
      k = {0, 0, a.second, b.second, 0};
      return true;
    }
    if (f.kind == pred::VERTEX_EDGE && valid(i[0]) && valid(i[1]) && valid(i[2]) &&
        p_[i[1]].first == p_[i[2]].first && p_[i[0]].first != p_[i[1]].first) {
      const uint32_t e0 = p_[i[1]].second, e1 = p_[i[2]].second;
      k = {1, static_cast<uint32_t>(p_[i[0]].first), p_[i[0]].second, std::min(e0, e1), std::max(e0, e1)};
      return true;
    }
    return false;
  }

  Irrational_memo &memo_;
  Points p_;
  int n_;
};

}  // namespace pccd::narrow
