// The poses a robot check's filter (robot.h, link_filter.h) visits: every link's and
// obstacle's pose enclosure on the dyadic pieces and at the dyadic instants of [0, 1],
// each computed once per check, on its first demand, and shared by every body pair
// that asks for it (a link against each obstacle asks for the same piece in turn).
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "motion/chain_path.h"
#include "scene/link_filter.h"
#include "scene/pose_store.h"

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
// the filter visits, each computed once per check. Storage: a Pose_store
// (pose_store.h) borrowed for the check from the thread's, so a check allocates nothing
// once its thread has checked a segment as large (issue 30: the hashed map of per-piece
// vectors and its allocations were about a fifth of a free segment's filter time).
class Piece_poses {
 public:
  Piece_poses(const motion::Chain_path &path, const std::vector<Moving_body> &obstacles)
      : path_(path), obstacles_(obstacles), store_(Pose_store::borrow(path.size(), obstacles.size())),
        still_(&store_->piece(-2, 0, 0)) {}
  ~Piece_poses() { Pose_store::give_back(std::move(store_)); }
  Piece_poses(const Piece_poses &) = delete;
  Piece_poses &operator=(const Piece_poses &) = delete;

  // Link k over the piece: the ball, and the second-order enclosure (link_filter.h) when
  // its chords' growth is at most half the ball's radii (at the coarse pieces the ball
  // is tighter; the choice is a heuristic, both enclosures hold). Made once per piece
  // and base, then handed out as made.
  const Side_piece &link(long base, size_t k, int d, long i) {
    Pose_store::Slots &p = store_->piece(base, d, i);
    if (p.have_side[k]) return p.side[k];
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
    p.side[k] = s;
    p.have_side[k] = 1;
    return p.side[k];
  }
  const enclose::Pose_piece &link_at(long base, size_t k, int d, long i) {
    const double t = std::ldexp(static_cast<double>(i), -d);
    return link_pose(store_->instant(base, d, i), base, k, t, t);
  }
  // A stationary obstacle's pose is the same on every piece and instant: made once.
  const Side_piece &obstacle(size_t k, int d, long i) {
    if (still(k)) return still_side(k);
    Pose_store::Slots &p = store_->piece(-1, d, i);
    if (!p.have_obst[k]) {
      const double a = std::ldexp(static_cast<double>(i), -d), b = std::ldexp(static_cast<double>(i + 1), -d);
      p.obstacles[k] = d == 0 ? enclose::whole_pose(obstacles_[k]) : enclose::enclose_pose(obstacles_[k], a, b);
      p.obst_side[k] = Side_piece{};
      p.obst_side[k].ball = &p.obstacles[k];
      p.have_obst[k] = 1;
    }
    return p.obst_side[k];
  }
  const enclose::Pose_piece &obstacle_at(size_t k, int d, long i) {
    if (still(k)) return *still_side(k).ball;
    Pose_store::Slots &p = store_->instant(-1, d, i);
    if (!p.have_obst[k]) {
      const double t = std::ldexp(static_cast<double>(i), -d);
      p.obstacles[k] = enclose::enclose_pose(obstacles_[k], t, t);
      p.have_obst[k] = 1;
    }
    return p.obstacles[k];
  }

 private:
  bool still(size_t k) const { return obstacles_[k].mo == narrow::identity_motion(); }
  // The still obstacle k's pose (enclose::whole_pose) and Side_piece, in slot k of the
  // store's piece of base -2 (no link base is -2: no other demand finds it).
  const Side_piece &still_side(size_t k) {
    Pose_store::Slots &p = *still_;
    if (!p.have_obst[k]) {
      p.obstacles[k] = enclose::whole_pose(obstacles_[k]);
      p.obst_side[k] = Side_piece{};
      p.obst_side[k].ball = &p.obstacles[k];
      p.obst_side[k].identity = true;
      p.have_obst[k] = 1;
    }
    return p.obst_side[k];
  }
  const enclose::Pose_piece &link_pose(Pose_store::Slots &p, long base, size_t k, double a, double b) {
    if (!p.have_links[k]) {
      path_.enclose_link(a, b, k, base, p.bounds, p.have_bounds);
      p.links[k] = pose_piece(p.bounds[k]);
      p.have_links[k] = 1;
    }
    return p.links[k];
  }

  const motion::Chain_path &path_;
  const std::vector<Moving_body> &obstacles_;
  std::unique_ptr<Pose_store> store_;
  Pose_store::Slots *still_;
};

}  // namespace pccd::scene
