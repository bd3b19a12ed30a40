// The range structure: lifted points of stored primitives in a CGAL Kd_tree, searched
// with conjunctions of clauses of closed halfspaces (range/halfspaces.h).
//
// Each stored primitive i has an exact lifted point enclosed by the interval box
// lifted[i] (computed in interval arithmetic from the exact body coordinates). The tree
// holds the box midpoints; a tree cell, which bounds the midpoints below it, is widened
// by the largest box radius per coordinate (rounded up) before it is tested, so the
// widened cell contains every exact lifted point below it. A leaf point is tested with
// its own interval box. The search is a CGAL fuzzy query whose cell tests are
// cnf_possible / cnf_certain: it reports a superset of the stored primitives whose
// exact lifted point satisfies the query, never fewer (closed halfspaces, outward
// rounding). CGAL builds the tree in O(n log n); build() is called before any search so
// that searches from several threads only read it.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#define CGAL_DISABLE_ROUNDING_MATH_CHECK  // the tree uses only double comparisons
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits.h>

#include "range/halfspaces.h"

namespace pccd::range {

template <int D>
struct Lifted_point {
  std::array<double, D> x;
  uint32_t id;
};

template <int D>
struct Lifted_coords {
  using result_type = const double *;
  const double *operator()(const Lifted_point<D> &p) const { return p.x.data(); }
  const double *operator()(const Lifted_point<D> &p, int) const { return p.x.data() + D; }
};

template <int D>
class Range_tree {
 public:
  using Traits = CGAL::Search_traits<double, Lifted_point<D>, const double *, Lifted_coords<D>,
                                     CGAL::Dimension_tag<D>>;
  using Tree = CGAL::Kd_tree<Traits>;
  using Rect = CGAL::Kd_tree_rectangle<double, CGAL::Dimension_tag<D>>;

  // lifted[i]: the interval box of stored primitive i's lifted point. split: the
  // coordinates the tree may split on (bit k for coordinate k). The others are set to 0
  // in the tree's points (no spread, so CGAL's sliding midpoint never cuts them) and a
  // cell is tested with the hull of all lifted points there: coordinates like n . a0 or
  // |c|^2 - r^2 spread far more than the box coordinates and would take the cuts, while
  // the queries' bounds are on the box coordinates (measured: tests/bench/bench_online.py).
  Range_tree(std::vector<std::array<Interval, D>> lifted, uint32_t split)
      : lifted_(std::move(lifted)), split_(split) {
    std::vector<Lifted_point<D>> pts(lifted_.size());
    radius_.fill(0.0);
    if (!lifted_.empty()) all_ = lifted_[0];
    for (size_t i = 0; i < lifted_.size(); ++i) {
      pts[i].id = static_cast<uint32_t>(i);
      for (int k = 0; k < D; ++k) {
        const Interval &v = lifted_[i][k];
        const double m = 0.5 * v.lo + 0.5 * v.hi;  // inside [lo, hi] in any rounding mode
        pts[i].x[k] = (split_ >> k) & 1 ? m : 0.0;
        radius_[k] = std::max(radius_[k], arith::round_up(std::max(m - v.lo, v.hi - m)));
        all_[k] = Interval(std::min(all_[k].lo, v.lo), std::max(all_[k].hi, v.hi));
      }
    }
    tree_.insert(pts.begin(), pts.end());
    if (!pts.empty()) tree_.build();
  }

  size_t size() const { return lifted_.size(); }
  // The interval box of stored primitive id's lifted point.
  const std::array<Interval, D> &lifted(uint32_t id) const { return lifted_[id]; }

  // Whether some stored point may satisfy q (q tested on the box of all lifted points).
  bool may_hit(const Cnf<D> &q) const { return !lifted_.empty() && cnf_possible(q, all_.data()); }

  // Appends to out the ids of the stored primitives that may satisfy q.
  void search(const Cnf<D> &q, std::vector<uint32_t> &out) const {
    if (lifted_.empty()) return;
    Query query{this, &q};
    Out_it it{&out};
    tree_.search(it, query);
  }

 private:
  std::vector<std::array<Interval, D>> lifted_;
  uint32_t split_;
  std::array<double, D> radius_;
  std::array<Interval, D> all_;  // hull of every lifted box
  Tree tree_;

  struct Query {
    using Point_d = Lifted_point<D>;
    using FT = double;
    using Dimension = CGAL::Dimension_tag<D>;
    const Range_tree *t;
    const Cnf<D> *q;

    bool contains(const Point_d &p) const { return cnf_possible(*q, t->lifted_[p.id].data()); }
    void cell(const Rect &r, Interval *x) const {
      for (int k = 0; k < D; ++k)
        x[k] = (t->split_ >> k) & 1 ? Interval(arith::round_down(r.min_coord(k) - t->radius_[k]),
                                               arith::round_up(r.max_coord(k) + t->radius_[k]))
                                    : t->all_[k];
    }
    bool inner_range_intersects(const Rect &r) const {
      Interval x[D];
      cell(r, x);
      return cnf_possible(*q, x);
    }
    bool outer_range_contains(const Rect &r) const {
      Interval x[D];
      cell(r, x);
      return cnf_certain(*q, x);
    }
  };

  // Output iterator collecting ids.
  struct Out_it {
    std::vector<uint32_t> *out;
    Out_it &operator*() { return *this; }
    Out_it &operator++() { return *this; }
    Out_it operator++(int) { return *this; }
    Out_it &operator=(const Lifted_point<D> &p) {
      out->push_back(p.id);
      return *this;
    }
  };
};

}  // namespace pccd::range
