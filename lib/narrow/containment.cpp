// Containment at t = 0 (narrow/containment.h).
#include "narrow/containment.h"

#include <array>
#include <memory>
#include <vector>

#include "motion/solid.h"

namespace pccd::narrow {

namespace {

using motion::Point3_q;

// The points of a body tested against the other's solid: a vertex of each surface
// component of a mesh, every ball centre. Kept with the body.
struct Test_points final : Body_attachment {
  std::vector<uint32_t> ids;
};

// The exact body-frame box of a solid mesh's vertices: a point outside is outside.
struct Solid_box final : Body_attachment {
  Point3_q lo, hi;
};

const std::vector<uint32_t> &test_points(const Body_data &d) {
  return d.attached<Test_points>([&] {
           auto t = std::make_unique<Test_points>();
           if (d.mesh) t->ids = motion::component_vertices(*d.mesh);
           else
             for (uint32_t k = 0; k < d.spheres->centers().size(); ++k) t->ids.push_back(k);
           return t;
         }).ids;
}

const Solid_box &solid_box(const Body_data &d) {
  return d.attached<Solid_box>([&] {
    auto b = std::make_unique<Solid_box>();
    const auto &V = d.mesh->vertices();
    b->lo = b->hi = V[0];
    for (const Point3_q &v : V)
      for (int k = 0; k < 3; ++k) {
        if (v[k] < b->lo[k]) b->lo[k] = v[k];
        if (b->hi[k] < v[k]) b->hi[k] = v[k];
      }
    return b;
  });
}

bool is_solid(const Moving_body &b) { return b.mesh && b.mesh->solid(); }

// The first point of side q strictly inside the solid of side s at t = 0.
std::optional<uint32_t> first_inside(const Moving_body &S, const Moving_body &Q) {
  // Q's points in S's frame at t = 0: y = (M p + u) / w (narrow::relative_pose) with
  // every polynomial taken at t = 0, exactly.
  const Rational zero(0);
  std::array<std::array<Rational, 3>, 3> RS, RQ;
  std::array<Rational, 3> OS, OQ;
  for (int i = 0; i < 3; ++i) {
    OS[i] = S.mo->O[i].eval(zero);
    OQ[i] = Q.mo->O[i].eval(zero);
    for (int j = 0; j < 3; ++j) {
      RS[i][j] = S.mo->Rn[i][j].eval(zero);
      RQ[i][j] = Q.mo->Rn[i][j].eval(zero);
    }
  }
  const Relative_pose<Rational> rel =
      relative_pose(RS, OS, S.mo->W.eval(zero), RQ, OQ, Q.mo->W.eval(zero));
  const Solid_box &box = solid_box(*S.data);
  for (uint32_t k : test_points(*Q.data)) {
    const Point3_q &p = Q.point(k);
    Point3_q y;
    bool in_box = true;
    for (int i = 0; i < 3 && in_box; ++i) {
      y[i] = (rel.M[i][0] * p[0] + rel.M[i][1] * p[1] + rel.M[i][2] * p[2] + rel.u[i]) / rel.w;
      in_box = box.lo[i] < y[i] && y[i] < box.hi[i];  // strictly inside needs this
    }
    if (in_box && motion::winding_number(*S.mesh, y) != 0) return k;
  }
  return std::nullopt;
}

}  // namespace

bool has_solid(const Pair_ctx &ctx) { return is_solid(ctx.side(0)) || is_solid(ctx.side(1)); }

std::optional<Prim_pair> contained_at_zero(const Pair_ctx &ctx) {
  const Moving_body &A = ctx.side(0), &B = ctx.side(1);
  // Balls against a non-solid mesh, or a non-solid mesh against balls: no test (a ball
  // holding a surface point meets a closed triangle: containment.h).
  if (is_solid(A))
    if (auto k = first_inside(A, B)) return Prim_pair{IN_A, 0, *k};
  if (is_solid(B))
    if (auto k = first_inside(B, A)) return Prim_pair{IN_B, *k, 0};
  return std::nullopt;
}

}  // namespace pccd::narrow
