// The range structure: lifted points of stored primitives in a kd-tree whose every node
// keeps the interval hull of ALL the lifted coordinates below it, searched with
// conjunctions of clauses of closed halfspaces (range/halfspaces.h).
//
// Each stored primitive i has an exact lifted point enclosed by the interval box
// lifted[i] (computed in interval arithmetic from the exact body coordinates). A node's
// hull is the union of the boxes below it, so it contains every exact lifted point below
// it; the search enters a node only if cnf_possible(hull), reports it whole if
// cnf_certain(hull), and tests a leaf's points with their own boxes. It reports a
// superset of the stored primitives whose exact lifted point satisfies the query, never
// fewer (closed halfspaces, outward rounding).
//
// Splits: median of the box midpoints along the split coordinate (bit k of `split`)
// whose spread below the node is the largest relative to its spread over the whole tree
// (scale-free: box corners, normals and moments have different units), equal values
// ordered by the other split coordinates (build, below). Only the box
// coordinates are split on (the queries' cheap bounds are on them), but the hulls are
// tight in every coordinate: where the plane offset n . a0 or an edge's moment follows
// the position (parallel slivers, needles, fans: tests/bench/bench_adversarial.py), the
// contact clauses prune whole subtrees. The CGAL Kd_tree used before kept only the split
// coordinates' cells, testing the others with the hull of the whole tree, so those
// clauses pruned nothing above the leaves and a query with no candidate still visited
// every stored primitive whose box met its own (quadratic on those families).
// Build O(n log n); searches only read the tree (several threads at once).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "range/halfspaces.h"
#include "util/work_budget.h"

namespace pccd::range {

template <int D>
class Range_tree {
 public:
  // lifted[i]: the interval box of stored primitive i's lifted point. split: the
  // coordinates the tree may split on (bit k for coordinate k).
  Range_tree(std::vector<std::array<Interval, D>> lifted, uint32_t split)
      : lifted_(std::move(lifted)), split_(split) {
    const uint32_t n = static_cast<uint32_t>(lifted_.size());
    order_.resize(n);
    mid_.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
      order_[i] = i;
      for (int k = 0; k < D; ++k) {  // NaN (an infinite box): 0, so the splits stay ordered
        const double m = 0.5 * lifted_[i][k].lo + 0.5 * lifted_[i][k].hi;
        mid_[i][k] = m == m ? m : 0.0;
      }
    }
    if (n == 0) return;
    nodes_.reserve(2 * (n / kLeaf + 1));
    build(0, n, nullptr);
    mid_.clear();
    mid_.shrink_to_fit();
  }

  size_t size() const { return lifted_.size(); }
  // The interval box of stored primitive id's lifted point.
  const std::array<Interval, D> &lifted(uint32_t id) const { return lifted_[id]; }

  // Whether some stored point may satisfy q (q tested on the hull of all lifted points).
  bool may_hit(const Cnf<D> &q) const { return !nodes_.empty() && cnf_possible(q, nodes_[0].hull.data()); }

  // Whether some stored point may satisfy q (as search() reporting one; stops there).
  bool any(const Cnf<D> &q) const {
    bool found = false;
    visit(q, [&](uint32_t, uint32_t) { return found = true; });
    return found;
  }

  // Appends to out the ids of the stored primitives that may satisfy q.
  void search(const Cnf<D> &q, std::vector<uint32_t> &out) const {
    visit(q, [&](uint32_t begin, uint32_t end) {
      out.insert(out.end(), order_.begin() + begin, order_.begin() + end);
      return false;
    });
  }

 private:
  static constexpr uint32_t kLeaf = 8;
  struct Node {
    std::array<Interval, D> hull;
    uint32_t begin, end;
    uint32_t left;  // index of the left child (the right one follows it); 0: a leaf
  };
  std::vector<std::array<Interval, D>> lifted_;
  uint32_t split_;
  std::vector<uint32_t> order_;              // primitive ids, each node's a range of it
  std::vector<std::array<double, D>> mid_;   // box midpoints (building only)
  std::vector<Node> nodes_;                  // nodes_[0]: the root
  std::array<double, D> root_spread_{};

  // The search: report(begin, end) for each run order_[begin, end) of points that may
  // satisfy q (a whole node where q certainly holds, or one leaf point); stops when
  // report returns true.
  template <class Report>
  void visit(const Cnf<D> &q, Report report) const {
    if (nodes_.empty()) return;
    uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node &nd = nodes_[stack[--top]];
      if (!cnf_possible(q, nd.hull.data())) continue;
      if (nd.left == 0) {  // leaf: each point with its own box
        for (uint32_t i = nd.begin; i < nd.end; ++i)
          if (cnf_possible(q, lifted_[order_[i]].data()) && report(i, i + 1)) return;
        continue;
      }
      if (cnf_certain(q, nd.hull.data())) {
        if (report(nd.begin, nd.end)) return;
        continue;
      }
      stack[top++] = nd.left + 1;
      stack[top++] = nd.left;
    }
  }

  // Builds the node of order_[begin, end) at nodes_[at] (appended when at is null).
  void build(uint32_t begin, uint32_t end, uint32_t *at) {
    // One work step per node and per 4,096 items it scans (util/work_budget.h): an index
    // over a million triangles builds its trees for seconds, and its limits must hold.
    util::work_step(1 + (end - begin) / 4096);
    const uint32_t me = at ? *at : static_cast<uint32_t>(nodes_.size());
    if (!at) nodes_.push_back(Node());
    Node nd;
    nd.begin = begin;
    nd.end = end;
    nd.left = 0;
    nd.hull = lifted_[order_[begin]];
    std::array<double, D> lo, hi;
    for (int k = 0; k < D; ++k) lo[k] = hi[k] = mid_[order_[begin]][k];
    for (uint32_t i = begin; i < end; ++i) {
      const auto &b = lifted_[order_[i]];
      for (int k = 0; k < D; ++k) {
        nd.hull[k] = Interval(std::min(nd.hull[k].lo, b[k].lo), std::max(nd.hull[k].hi, b[k].hi));
        lo[k] = std::min(lo[k], mid_[order_[i]][k]);
        hi[k] = std::max(hi[k], mid_[order_[i]][k]);
      }
    }
    if (me == 0)
      for (int k = 0; k < D; ++k) root_spread_[k] = hi[k] - lo[k];
    // The split coordinates by decreasing relative spread (ties: the lower k first).
    std::array<int, D> key;
    std::array<double, D> rel;
    int nkey = 0;
    for (int k = 0; k < D; ++k) {
      if (!((split_ >> k) & 1) || !(root_spread_[k] > 0) || !(hi[k] > lo[k])) continue;
      rel[k] = (hi[k] - lo[k]) / root_spread_[k];
      key[nkey++] = k;
    }
    std::stable_sort(key.begin(), key.begin() + nkey, [&](int a, int b) { return rel[a] > rel[b]; });
    if (end - begin <= kLeaf || nkey == 0) {  // small, or every split coordinate constant
      nodes_[me] = nd;
      return;
    }
    // Median of the first key, ties broken by the next keys, then the id. Without the
    // tie-break, a run of equal values (one edge direction of many parallel plates, one
    // box side of stacked slivers) is cut anywhere: both children then hold every layer
    // of that run, interleaved, and a query between two layers enters both, at every
    // such level (about sqrt n nodes per query on plates; with it, a few per level).
    const uint32_t half = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + half, order_.begin() + end,
                     [&](uint32_t a, uint32_t b) {
                       for (int j = 0; j < nkey; ++j)
                         if (mid_[a][key[j]] != mid_[b][key[j]]) return mid_[a][key[j]] < mid_[b][key[j]];
                       return a < b;
                     });
    nd.left = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back(Node());
    nodes_.push_back(Node());
    nodes_[me] = nd;
    uint32_t l = nd.left, r = nd.left + 1;
    build(begin, half, &l);
    build(half, end, &r);
  }
};

}  // namespace pccd::range
