#include "scene/robot.h"

#include <algorithm>
#include <map>
#include <string>

#include "motion/chain_path.h"
#include "scene/link_filter.h"

namespace pccd::scene {

namespace {

// The link's ball (motion/chain_path.h) in the form enclose::frame_box maps boxes with
// (pivot 0): every entry of R(t) - Rm is at most ||R(t) - Rm||_2 <= eps, every
// coordinate of o(t) - om at most |o(t) - om|_2 <= rho.
enclose::Pose_piece pose_piece(const motion::Pose_bounds &p) {
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

// The poses of every link and obstacle on the dyadic pieces the filter visits, each
// computed once per check.
class Piece_poses {
 public:
  Piece_poses(const motion::Chain_path &path, const std::vector<Moving_body> &obstacles)
      : path_(path), obstacles_(obstacles) {}

  const enclose::Pose_piece &link(size_t k, int d, long i) { return at(d, i, true).links[k]; }
  const enclose::Pose_piece &obstacle(size_t k, int d, long i) {
    Piece &p = at(d, i, false);
    if (!p.have_obstacle[k]) {
      const double a = std::ldexp(static_cast<double>(i), -d), b = std::ldexp(static_cast<double>(i + 1), -d);
      // A stationary obstacle's pose is the same on every piece.
      const bool still = obstacles_[k].mo == narrow::identity_motion();
      p.obstacles[k] = d == 0 || still ? enclose::whole_pose(obstacles_[k]) : enclose::enclose_pose(obstacles_[k], a, b);
      p.have_obstacle[k] = true;
    }
    return p.obstacles[k];
  }

 private:
  struct Piece {
    std::vector<enclose::Pose_piece> links;
    std::vector<enclose::Pose_piece> obstacles;
    std::vector<bool> have_obstacle;
  };
  Piece &at(int d, long i, bool links) {
    Piece &p = pieces_[{d, i}];
    if (p.have_obstacle.empty()) {
      p.obstacles.resize(obstacles_.size());
      p.have_obstacle.assign(obstacles_.size() + 1, false);  // + 1: never empty after this
    }
    if (links && p.links.empty()) {
      const double a = std::ldexp(static_cast<double>(i), -d), b = std::ldexp(static_cast<double>(i + 1), -d);
      path_.enclose(a, b, bounds_);
      p.links.reserve(bounds_.size());
      for (const motion::Pose_bounds &x : bounds_) p.links.push_back(pose_piece(x));
    }
    return p;
  }

  const motion::Chain_path &path_;
  const std::vector<Moving_body> &obstacles_;
  std::map<std::pair<int, long>, Piece> pieces_;
  std::vector<motion::Pose_bounds> bounds_;
};

}  // namespace

Scene_report check_robot(const Robot_model &r, const double *q0, const double *q1,
                         const std::vector<Scene_body> &obstacles, const Scene_options &opt,
                         const Robot_options &ro) {
  const motion::Chain_path path(r.chain, q0, q1);  // Input_error for a rejected segment
  const std::vector<Moving_body> obst = prepare_bodies(obstacles, "obstacles");
  const size_t nr = r.bodies.size();
  if (nr + obst.size() < 2) throw arith::Input_error("obstacles: nothing to check (one body, no obstacle)");
  std::vector<Pair_plan> plans;
  for (size_t i = 0; i < nr; ++i) {
    if (ro.self_collision)
      for (size_t j = i + 1; j < nr; ++j) {
        const size_t g = r.bodies[i].group, h = r.bodies[j].group;
        if (g != h && !r.allowed.count({std::min(g, h), std::max(g, h)})) plans.push_back({i, j, 0.0});
      }
    for (size_t k = 0; k < obst.size(); ++k) plans.push_back({i, nr + k, 0.0});
  }

  if (ro.filter) {
    Piece_poses poses(path, obst);
    const double reach = opt.reach;
    auto side = [&](size_t k) -> Pose_of {
      if (k < nr) return [&, link = r.bodies[k].link](int d, long i) -> const enclose::Pose_piece & {
        return poses.link(link, d, i);
      };
      return [&, k](int d, long i) -> const enclose::Pose_piece & { return poses.obstacle(k - nr, d, i); };
    };
    auto data = [&](size_t k) -> const Body_data & { return k < nr ? *r.bodies[k].body : *obst[k - nr].data; };
    std::vector<Pair_plan> kept;
    for (Pair_plan p : plans) {
      p.lower = first_uncleared(data(p.i), side(p.i), data(p.j), side(p.j), reach);
      if (p.lower <= 1) kept.push_back(p);
    }
    std::stable_sort(kept.begin(), kept.end(),
                     [](const Pair_plan &x, const Pair_plan &y) { return x.lower < y.lower; });
    plans = std::move(kept);
  }

  // The exact motions of the links of the pairs left, built on the first demand.
  std::vector<bool> needed(r.chain.size(), false);
  for (const Pair_plan &p : plans) {
    needed[r.bodies[p.i].link] = true;
    if (p.j < nr) needed[r.bodies[p.j].link] = true;
  }
  std::vector<motion::Rigid_motion> motions;
  std::vector<motion::Mat3_poly> rn;
  std::vector<std::shared_ptr<const narrow::Motion_data>> link_data(r.chain.size());
  std::vector<std::unique_ptr<Moving_body>> robot_mb(nr);
  bool built = false;
  auto body = [&](size_t k) -> const Moving_body & {
    if (k >= nr) return obst[k - nr];
    if (!robot_mb[k]) {
      if (!built)
        motions = r.chain.segment_motions(q0, q1, &rn, &needed, ro.check_link ? &ro.check_link : nullptr);
      built = true;
      const size_t L = r.bodies[k].link;
      if (!link_data[L]) link_data[L] = narrow::prepare_motion(motions[L], true, &rn[L]);
      robot_mb[k] = std::make_unique<Moving_body>(narrow::prepare_body(r.bodies[k].body, link_data[L]));
    }
    return *robot_mb[k];
  };
  return solve_planned(body, plans, opt, -1, true);
}

}  // namespace pccd::scene
