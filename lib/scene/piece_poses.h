// The poses a robot check's filter (robot.h, link_filter.h) visits: every link's and
// obstacle's pose enclosure on the dyadic pieces and at the dyadic instants of [0, 1],
// each computed once per check, on its first demand.
#pragma once
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "motion/chain_path.h"
#include "scene/link_filter.h"

namespace pccd::scene {

// The link's ball (motion/chain_path.h) in the form enclose::frame_box maps boxes with
// (pivot 0): every entry of R(t) - Rm is at most ||R(t) - Rm||_2 <= eps, every
// coordinate of o(t) - om at most |o(t) - om|_2 <= rho.
inline enclose::Pose_piece pose_piece(const motion::Pose_bounds &p) {
  enclose::Pose_piece out;
  bool finite = std::isfinite(p.eps) && std::isfinite(p.rho);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      out.Rm[i][j] = p.Rm[i][j];
      out.Rr[i][j] = p.eps;
    }
    out.om[i] = p.om[i];
    out.orad[i] = p.rho;
    finite = finite && std::isfinite(p.om[i]);
  }
  out.finite = finite;
  return out;
}

// The poses of every link and obstacle on the dyadic pieces and at the dyadic instants
// the filter visits, each computed once per check.
class Piece_poses {
 public:
  Piece_poses(const motion::Chain_path &path, const std::vector<Moving_body> &obstacles)
      : path_(path), obstacles_(obstacles) {}

  // Link k over the piece: the ball, and the second-order enclosure (link_filter.h) when
  // its chords' growth is at most half the ball's radii (at the coarse pieces the ball
  // is tighter; the choice is a heuristic, both enclosures hold).
  Side_piece link(long base, size_t k, int d, long i) {
    Piece &p = at(base, d, i);
    const double a = std::ldexp(static_cast<double>(i), -d), b = std::ldexp(static_cast<double>(i + 1), -d);
    Side_piece s;
    s.ball = &link_pose(p, base, k, a, b);
    path_.derivatives_link(a, b, k, base, p.derivs, p.have_derivs);
    const motion::Path_derivs &D = p.derivs[k];
    const double gr = arith::round_up(std::ldexp(D.d2, -2 * d - 3)), go = arith::round_up(std::ldexp(D.o2, -2 * d - 3));
    if (std::isfinite(gr) && std::isfinite(go) && gr <= 0.5 * s.ball->Rr[0][0] && go <= 0.5 * s.ball->orad[0]) {
      s.at_a = &link_at(base, k, d, i);
      s.at_b = &link_at(base, k, d, i + 1);
      s.g_rot = gr;
      s.g_off = go;
    }
    return s;
  }
  const enclose::Pose_piece &link_at(long base, size_t k, int d, long i) {
    const double t = std::ldexp(static_cast<double>(i), -d);
    return link_pose(instant(base, d, i), base, k, t, t);
  }
  Side_piece obstacle(size_t k, int d, long i) {
    Piece &p = with_obstacles(at(-1, d, i));
    if (!p.have_obstacle[k]) {
      const double a = std::ldexp(static_cast<double>(i), -d), b = std::ldexp(static_cast<double>(i + 1), -d);
      p.obstacles[k] = still(k) || d == 0 ? enclose::whole_pose(obstacles_[k]) : enclose::enclose_pose(obstacles_[k], a, b);
      p.have_obstacle[k] = true;
    }
    Side_piece s;
    s.ball = &p.obstacles[k];
    s.identity = still(k);
    return s;
  }
  const enclose::Pose_piece &obstacle_at(size_t k, int d, long i) {
    Piece &p = with_obstacles(instant(-1, d, i));
    if (!p.have_obstacle[k]) {
      const double t = std::ldexp(static_cast<double>(i), -d);
      p.obstacles[k] = still(k) ? enclose::whole_pose(obstacles_[k]) : enclose::enclose_pose(obstacles_[k], t, t);
      p.have_obstacle[k] = true;
    }
    return p.obstacles[k];
  }

 private:
  // The poses over one piece or at one instant, each link's made on its first demand
  // (with its ancestors': motion/chain_path.h, enclose_link).
  struct Piece {
    std::vector<motion::Pose_bounds> bounds;
    std::vector<char> have_bounds;
    std::vector<enclose::Pose_piece> links;
    std::vector<char> have_links;
    std::vector<motion::Path_derivs> derivs;  // pieces only
    std::vector<char> have_derivs;
    std::vector<enclose::Pose_piece> obstacles;
    std::vector<bool> have_obstacle;
  };
  // A stationary obstacle's pose is the same on every piece.
  bool still(size_t k) const { return obstacles_[k].mo == narrow::identity_motion(); }
  // A piece's link and obstacle slots are made on the first demand of their kind (a
  // piece relative to a link base never holds obstacles).
  Piece &with_obstacles(Piece &p) {
    if (p.have_obstacle.empty()) {
      p.obstacles.resize(obstacles_.size());
      p.have_obstacle.assign(obstacles_.size() + 1, false);  // + 1: never empty after this
    }
    return p;
  }
  const enclose::Pose_piece &link_pose(Piece &p, long base, size_t k, double a, double b) {
    if (p.have_links.empty()) {
      p.links.resize(path_.size());
      p.have_links.assign(path_.size(), 0);
    }
    if (!p.have_links[k]) {
      path_.enclose_link(a, b, k, base, p.bounds, p.have_bounds);
      p.links[k] = pose_piece(p.bounds[k]);
      p.have_links[k] = 1;
    }
    return p.links[k];
  }
  // Looked up through a one-entry memo: the filter asks for both sides of a pair on the
  // same piece in a row, and a side's pieces run through depths at one index pattern.
  Piece &at(long base, int d, long i) { return find(pieces_, last_piece_, {base, d, i}); }
  // The instant i / 2^d, kept under its lowest terms (the end of one piece is the start
  // of the next, and of pieces of other depths).
  Piece &instant(long base, int d, long i) {
    while (d > 0 && i % 2 == 0) {
      i /= 2;
      --d;
    }
    if (i == 0) d = 0;
    return find(instants_, last_instant_, {base, d, i});
  }

  const motion::Chain_path &path_;
  const std::vector<Moving_body> &obstacles_;
  // Keyed by (base, depth, index): links relative to link base (-1: the world, and the
  // obstacles), on the piece or at the instant index / 2^depth. Hashed (the filter asks
  // for a pose per pair and piece: an ordered map's lookups were 2-3% of a check);
  // unordered_map never moves its elements, so the references handed out stay valid.
  struct Key {
    long base;
    int d;
    long i;
    bool operator==(const Key &o) const { return base == o.base && d == o.d && i == o.i; }
  };
  struct Key_hash {
    size_t operator()(const Key &k) const {
      uint64_t h = static_cast<uint64_t>(k.i) * 0x9E3779B97F4A7C15ull;  // Fibonacci hashing
      h ^= (static_cast<uint64_t>(k.base + 1) << 8 | static_cast<uint64_t>(k.d)) * 0xC2B2AE3D27D4EB4Full;
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  using Map = std::unordered_map<Key, Piece, Key_hash>;
  struct Memo {
    Key key{0, -1, 0};  // depth -1: no key yet
    Piece *piece = nullptr;
  };
  static Piece &find(Map &m, Memo &last, const Key &k) {
    if (!(last.piece && last.key == k)) last = {k, &m[k]};
    return *last.piece;
  }
  Map pieces_, instants_;
  Memo last_piece_, last_instant_;
};

}  // namespace pccd::scene
