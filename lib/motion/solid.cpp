// Solid validation and the exact winding number (motion/solid.h).
#include "motion/solid.h"

#include <numeric>
#include <string>

#include "arith/errors.h"

namespace pccd::motion {

namespace {

using arith::Rational;

std::string edge_name(const Edge &e) {
  return "triangles: edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ")";
}

// Whether triangle t lists a then b (cyclically): a -> b is one of its sides.
bool has_side(const Triangle &t, uint32_t a, uint32_t b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == a && t[(k + 1) % 3] == b) return true;
  return false;
}

// The sign of the 2D orientation of (u, v, q') with q' = (qy + e, qz + e^2), e > 0
// infinitesimal (solid.h): (v - u) x (q' - u) = D0 - dz e + dy e^2.
int orient_perturbed(const Rational &uy, const Rational &uz, const Rational &vy, const Rational &vz,
                     const Rational &qy, const Rational &qz) {
  const Rational dy = vy - uy, dz = vz - uz;
  const int s0 = sgn(dy * (qz - uz) - dz * (qy - uy));
  if (s0) return s0;
  if (sgn(dz)) return -sgn(dz);
  return sgn(dy);
}

}  // namespace

void check_solid(const Mesh_body &mesh) {
  const auto &tris = mesh.triangles();
  for (size_t t = 0; t < tris.size(); ++t)
    if (tris[t][0] == tris[t][1] || tris[t][1] == tris[t][2] || tris[t][0] == tris[t][2])
      throw arith::Input_error("triangles[" + std::to_string(t) + "]: (" + std::to_string(tris[t][0]) + ", " +
                               std::to_string(tris[t][1]) + ", " + std::to_string(tris[t][2]) +
                               ") repeats a vertex index; a solid needs a closed, consistently oriented mesh");
  const auto &edges = mesh.edges();
  for (size_t e = 0; e < edges.size(); ++e) {
    size_t n = 0;
    const uint32_t *et = mesh.edge_triangles(e, &n);
    const uint32_t a = edges[e][0], b = edges[e][1];
    const std::string tail = "; a solid needs a closed, consistently oriented mesh (every edge a side of "
                             "exactly two triangles, in opposite directions)";
    if (n == 1)
      throw arith::Input_error(edge_name(edges[e]) + " of triangle " + std::to_string(et[0]) +
                               " is open: no other triangle has it" + tail);
    if (n > 2)
      throw arith::Input_error(edge_name(edges[e]) + " of triangle " + std::to_string(et[0]) + " is a side of " +
                               std::to_string(n) + " triangles" + tail);
    const bool ab0 = has_side(tris[et[0]], a, b), ab1 = has_side(tris[et[1]], a, b);
    if (ab0 == ab1)
      throw arith::Input_error(edge_name(edges[e]) + " of triangle " + std::to_string(et[0]) +
                               " runs the same way (" + std::to_string(ab0 ? a : b) + " -> " +
                               std::to_string(ab0 ? b : a) + ") in triangles " + std::to_string(et[0]) + " and " +
                               std::to_string(et[1]) + ": one of them is flipped" + tail);
  }
}

long winding_number(const Mesh_body &mesh, const Point3_q &p, bool *on_surface) {
  std::vector<uint32_t> all(mesh.triangles().size());
  std::iota(all.begin(), all.end(), 0u);
  return winding_number(mesh, p, all.data(), all.size(), on_surface);
}

long winding_number(const Mesh_body &mesh, const Point3_q &p, const uint32_t *tris, size_t n,
                    bool *on_surface) {
  if (on_surface) *on_surface = false;
  const auto &V = mesh.vertices();
  long w = 0;
  for (size_t i = 0; i < n; ++i) {
    const Triangle &t = mesh.triangles()[tris[i]];
    const Point3_q &a = V[t[0]], &b = V[t[1]], &c = V[t[2]];
    // Quick rejection: p' = (y + e, z + e^2) lies in [min, max) of the projected
    // coordinates only if min <= p <= ... < max on both axes.
    bool below_y = false, above_y = false, below_z = false, above_z = false;
    for (const Point3_q *v : {&a, &b, &c}) {
      below_y = below_y || (*v)[1] <= p[1];
      above_y = above_y || (*v)[1] > p[1];
      below_z = below_z || (*v)[2] <= p[2];
      above_z = above_z || (*v)[2] > p[2];
    }
    if (!(below_y && above_y && below_z && above_z)) continue;
    // The normal's x component: twice the projected (y, z) area, signed.
    const Rational nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
    const int s = sgn(nx);
    if (s == 0) continue;
    const int o1 = orient_perturbed(a[1], a[2], b[1], b[2], p[1], p[2]);
    const int o2 = orient_perturbed(b[1], b[2], c[1], c[2], p[1], p[2]);
    const int o3 = orient_perturbed(c[1], c[2], a[1], a[2], p[1], p[2]);
    if (o1 != s || o2 != s || o3 != s) continue;
    // Where the ray meets the plane: x_hit - p_x has the sign of n . (a - p) / n_x.
    const Rational ny = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
    const Rational nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    const int side = sgn(nx * (a[0] - p[0]) + ny * (a[1] - p[1]) + nz * (a[2] - p[2])) * s;
    if (side == 0) {  // p' projects into the triangle and p is in its plane: on it
      if (on_surface) *on_surface = true;
      return 0;
    }
    if (side > 0) w += s;
  }
  return w;
}

std::vector<uint32_t> component_vertices(const Mesh_body &mesh) {
  std::vector<uint32_t> parent(mesh.vertices().size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<bool> used(parent.size(), false);
  for (const Triangle &t : mesh.triangles())
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      uint32_t x = find(t[k]), y = find(t[(k + 1) % 3]);
      if (x != y) parent[std::max(x, y)] = std::min(x, y);  // the root stays the least index
    }
  std::vector<uint32_t> out;
  for (uint32_t v = 0; v < parent.size(); ++v)
    if (used[v] && find(v) == v) out.push_back(v);
  return out;
}

}  // namespace pccd::motion
