#include "bvh/hierarchy.h"

#include <algorithm>
#include <cmath>

#include "util/work_budget.h"

namespace pccd::bvh {

namespace {

// Error bound of a node box (no rounding mode is assumed; u = 2^-53, and each IEEE
// operation in any rounding mode errs by at most 2u relative, plus 2^-1074 absolute on
// underflow, covered by kTiny):
//  - element bounds lo, hi: mesh triangles take the min / max of their vertices' doubles
//    (exact); a ball takes fl(p - r), fl(p + r) with r its radius rounded up, each off
//    by at most 2u |p -+ r| <= 2u (|lo| + |hi|). Every exact point is within pt_err of
//    its double (Body_data::pt_err), so the exact elements lie in
//    [lo - d - pt_err, hi + d + pt_err], d = 2u (|lo| + |hi|); unions take exact min/max.
//  - c = fl(lo/2 + hi/2); fl(hi - c) and fl(c - lo) each err by at most
//    2u (|hi| + |c|) <= 4u (|lo| + |hi|) (|c| <= max(|lo|, |hi|) (1 + 2u)).
// So h = max(fl(hi - c), fl(c - lo)) + 6u (|lo| + |hi|) + pt_err covers the exact box;
// kSlack = 2^-48 = 32u takes 6u and the relative error of the few operations that
// compute h itself.
constexpr double kSlack = 1.0 / (1ull << 48);
constexpr double kTiny = 1e-300;

struct Bounds {
  double lo[3], hi[3];
};

Node make_node(const Bounds &b, double pt_err) {
  Node n;
  for (int a = 0; a < 3; ++a) {
    const double c = 0.5 * b.lo[a] + 0.5 * b.hi[a];
    const double d = std::fmax(b.hi[a] - c, c - b.lo[a]);
    n.c[a] = c;
    n.h[a] = (d + (std::fabs(b.lo[a]) + std::fabs(b.hi[a])) * kSlack + pt_err) * (1 + kSlack) + kTiny;
  }
  return n;
}

Bounds unite(const Bounds &x, const Bounds &y) {
  Bounds u;
  for (int a = 0; a < 3; ++a) {
    u.lo[a] = std::fmin(x.lo[a], y.lo[a]);
    u.hi[a] = std::fmax(x.hi[a], y.hi[a]);
  }
  return u;
}

class Builder {
 public:
  Builder(const Body_data &d, Hierarchy &h) : d_(d), h_(h) {
    const bool mesh = static_cast<bool>(d.mesh);
    const size_t n = mesh ? d.mesh->triangles().size() : d.pts.size();
    box_.resize(n);
    centre_.resize(n);
    for (size_t e = 0; e < n; ++e) {
      Bounds &b = box_[e];
      if (mesh) {
        const auto &t = d.mesh->triangles()[e];
        for (int a = 0; a < 3; ++a) {
          b.lo[a] = std::fmin(std::fmin(d.pts[t[0]][a], d.pts[t[1]][a]), d.pts[t[2]][a]);
          b.hi[a] = std::fmax(std::fmax(d.pts[t[0]][a], d.pts[t[1]][a]), d.pts[t[2]][a]);
        }
      } else {
        for (int a = 0; a < 3; ++a) {
          b.lo[a] = d.pts[e][a] - d.radius_up[e];
          b.hi[a] = d.pts[e][a] + d.radius_up[e];
        }
      }
      // Centres only steer the split (speed); they need no error bound.
      for (int a = 0; a < 3; ++a) centre_[e][a] = static_cast<float>(0.5 * b.lo[a] + 0.5 * b.hi[a]);
    }
    h.elems.resize(n);
    for (size_t e = 0; e < n; ++e) h.elems[e] = static_cast<uint32_t>(e);
    const size_t leaves = (n + kLeaf_size - 1) / kLeaf_size;
    h.nodes.reserve(2 * leaves);
    h.nodes.emplace_back();
    if (n > 0) build(0, 0, static_cast<uint32_t>(n));
    if (mesh) least_indices();
  }

 private:
  const Body_data &d_;
  Hierarchy &h_;
  std::vector<Bounds> box_;
  std::vector<std::array<float, 3>> centre_;

  // Hierarchy::least, children before parents (a node's children come after it).
  void least_indices() {
    constexpr uint32_t kNone = UINT32_MAX;
    h_.least.assign(h_.nodes.size(), {kNone, kNone, kNone});
    for (size_t k = h_.nodes.size(); k-- > 0;) {
      const Node &n = h_.nodes[k];
      auto &m = h_.least[k];
      if (!n.leaf()) {
        for (int i = 0; i < 3; ++i) m[i] = std::min(h_.least[n.first][i], h_.least[n.first + 1][i]);
        continue;
      }
      for (uint32_t i = n.first; i < n.first + n.count; ++i) {
        const uint32_t t = h_.elems[i];
        for (int s = 0; s < 3; ++s) {
          m[0] = std::min(m[0], d_.mesh->triangles()[t][s]);
          if (d_.tri_edges[t][s] >= 0) m[1] = std::min(m[1], static_cast<uint32_t>(d_.tri_edges[t][s]));
        }
        m[2] = std::min(m[2], t);
      }
    }
  }

  // Node k over elems[b, e); returns its bounds (recursion depth ~ log2 n: balanced).
  Bounds build(uint32_t k, uint32_t b, uint32_t e) {
    // One work step per node and per 4,096 elements it scans (util/work_budget.h).
    util::work_step(1 + (e - b) / 4096);
    uint32_t *el = h_.elems.data();
    if (e - b <= kLeaf_size) {
      Bounds u = box_[el[b]];
      for (uint32_t i = b + 1; i < e; ++i) u = unite(u, box_[el[i]]);
      h_.nodes[k] = make_node(u, d_.pt_err);
      h_.nodes[k].first = b;
      h_.nodes[k].count = e - b;
      return u;
    }
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) lo[a] = hi[a] = centre_[el[b]][a];
    for (uint32_t i = b + 1; i < e; ++i)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], centre_[el[i]][a]);
        hi[a] = std::max(hi[a], centre_[el[i]][a]);
      }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    const uint32_t m = b + (e - b) / 2;
    // Ties broken by element index: the tree does not depend on the library's sort.
    std::nth_element(el + b, el + m, el + e, [&](uint32_t x, uint32_t y) {
      const float cx = centre_[x][axis], cy = centre_[y][axis];
      return cx != cy ? cx < cy : x < y;
    });
    const uint32_t child = static_cast<uint32_t>(h_.nodes.size());
    h_.nodes.emplace_back();
    h_.nodes.emplace_back();
    const Bounds u = unite(build(child, b, m), build(child + 1, m, e));
    h_.nodes[k] = make_node(u, d_.pt_err);
    h_.nodes[k].first = child;
    h_.nodes[k].count = 0;
    return u;
  }
};

}  // namespace

Hierarchy::Hierarchy(const Body_data &d) { Builder(d, *this); }

const Hierarchy &hierarchy(const Body_data &d) {
  return d.attached<Hierarchy>([&] { return std::make_shared<const Hierarchy>(d); });
}

}  // namespace pccd::bvh
