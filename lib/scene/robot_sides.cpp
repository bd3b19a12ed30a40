#include "scene/robot_sides.h"

namespace pccd::scene {

namespace {

// The pose of a body that stands still in its pair's frame, on every piece and instant.
const Side_piece &identity_side() {
  static const Side_piece side = [] {
    static enclose::Pose_piece p;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        p.Rm[i][j] = i == j ? 1 : 0;
        p.Rr[i][j] = 0;
      }
    Side_piece x;
    x.ball = &p;
    x.identity = true;
    return x;
  }();
  return side;
}

}  // namespace

Filter_side Robot_sides::operator()(size_t k, long base) {
  const size_t nr = r_.bodies.size();
  Filter_side s;
  s.src = &poses_;
  s.base = base;
  if (k < nr) {
    const size_t link = r_.bodies[k].link;
    s.data = r_.bodies[k].body.get();
    s.k = link;
    s.share = share_;
    if (static_cast<long>(link) == base) {
      s.piece_of = [](void *, long, size_t, int, long) -> const Side_piece & { return identity_side(); };
      s.instant_of = [](void *, long, size_t, int, long) -> const enclose::Pose_piece & {
        return *identity_side().ball;
      };
    } else {
      s.piece_of = [](void *src, long b, size_t l, int d, long i) -> const Side_piece & {
        return static_cast<Piece_poses *>(src)->link(b, l, d, i);
      };
      s.instant_of = [](void *src, long b, size_t l, int d, long i) -> const enclose::Pose_piece & {
        return static_cast<Piece_poses *>(src)->link_at(b, l, d, i);
      };
    }
  } else {
    s.data = obst_[k - nr].data.get();
    s.k = k - nr;
    s.piece_of = [](void *src, long, size_t o, int d, long i) -> const Side_piece & {
      return static_cast<Piece_poses *>(src)->obstacle(o, d, i);
    };
    s.instant_of = [](void *src, long, size_t o, int d, long i) -> const enclose::Pose_piece & {
      return static_cast<Piece_poses *>(src)->obstacle_at(o, d, i);
    };
  }
  if (!trees_[k]) trees_[k] = &bvh::hierarchy(*s.data);
  s.tree = trees_[k];
  return s;
}

}  // namespace pccd::scene
