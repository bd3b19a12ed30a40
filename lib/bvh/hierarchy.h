// A bounding-volume hierarchy of one body's elements (the triangles of a mesh, or the
// balls of a sphere set), built once in the body's own frame and kept with the body
// (narrow::Body_attachment): every check, scene and index that uses the body shares it.
//
// Layout: one array of nodes, the root first; an inner node's two children are adjacent
// (first, first + 1); a leaf holds elements elems[first .. first + count). Nodes are
// axis-aligned boxes in midpoint-radius form (c, h), the exact body-frame box
// [c - h, c + h] containing every point of the elements below it (its exact rational
// vertices or ball, not just their doubles): see hierarchy.cpp for the error bound.
//
// Build: top-down, each node split at the median of its elements' box centres along
// the longest axis of those centres (std::nth_element: O(n log n) in all), so the tree
// is balanced (depth ceil(log2(n / kLeaf_size)) + 1) and the build does no allocation
// per node. Axis-aligned boxes, not oriented ones: the swept traversal (bvh_source.h)
// maps each box by an interval enclosure of the rotation, under which an oriented box
// gains nothing over the aligned box of the same body-frame extent, and aligned boxes
// are what the median split makes cheaply. Measured against python-fcl's OBBRSS build
// in tests/bench/bench_bvh.py.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "narrow/moving_body.h"

namespace pccd::bvh {

using narrow::Body_data;

// Elements per leaf at most (measured: tests/bench/bench_bvh.py; one element per leaf
// keeps the leaf pairs exact element pairs, with no box test of their own).
constexpr uint32_t kLeaf_size = 1;

struct Node {
  std::array<double, 3> c, h;  // body-frame box [c - h, c + h] (conservative)
  uint32_t first = 0;          // inner: first child; leaf: first index into elems
  uint32_t count = 0;          // 0: inner node; else the number of elements of the leaf
  bool leaf() const { return count != 0; }
};

struct Hierarchy : narrow::Body_attachment {
  std::vector<Node> nodes;     // nodes[0] is the root
  std::vector<uint32_t> elems; // element indices, leaf by leaf
  // Meshes: per node, the least vertex, edge (Body_data::tri_edges, >= 0) and triangle
  // index of the triangles below it (UINT32_MAX: none): lower bounds of the keys of the
  // feature pairs below a node pair (least_at_zero.h). Empty for sphere sets.
  std::vector<std::array<uint32_t, 3>> least;
  explicit Hierarchy(const Body_data &d);
  // max(h) of node k: the size the traversal compares with a piece's motion spread.
  double size(uint32_t k) const {
    const auto &h = nodes[k].h;
    return h[0] > h[1] ? (h[0] > h[2] ? h[0] : h[2]) : (h[1] > h[2] ? h[1] : h[2]);
  }
};

// The hierarchy of a body: built on the first call (thread-safe), then shared
// (Body_data::attached). pccd_body_new_* builds it with the body.
const Hierarchy &hierarchy(const Body_data &d);

}  // namespace pccd::bvh
