#include "narrow/moving_body.h"

#include <algorithm>
#include <cmath>

namespace pccd::narrow {

namespace {

// nearest double and an upper bound of its distance to x.
double approx(const Rational &x, double &err) {
  const double d = arith::nearest_double(x);
  const Interval e = arith::enclose(x);
  // Beyond the double range d is infinite and so is the error (inf - inf would be NaN).
  err = std::isfinite(d) ? std::max(err, std::max(d - e.lo, e.hi - d)) : INFINITY;
  return d;
}

int64_t edge_index(const motion::Mesh_body &m, uint32_t a, uint32_t b) {
  if (a == b) return -1;
  const motion::Edge key{std::min(a, b), std::max(a, b)};
  const auto &E = m.edges();
  auto it = std::lower_bound(E.begin(), E.end(), key);
  if (it == E.end() || *it != key) throw arith::Internal_error("triangle side missing from the edge list");
  return it - E.begin();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

std::shared_ptr<const Motion_data> prepare_motion(const motion::Rigid_motion &m, bool known_valid,
                                                  const motion::Mat3_poly *Rn) {
  if (!known_valid) m.validate();
  auto d = std::make_shared<Motion_data>();
  d->motion = m;
  d->Rn = Rn ? *Rn : motion::rotation_numerator(m.r);
  d->O = m.offset_numerator();
  d->W = m.denominator();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d->Rn_i[i][j] = poly::convert<Interval>(d->Rn[i][j]);
    d->O_i[i] = poly::convert<Interval>(d->O[i]);
  }
  d->W_i = poly::convert<Interval>(d->W);
  return d;
}

const std::shared_ptr<const Motion_data> &identity_motion() {
  static const std::shared_ptr<const Motion_data> id = prepare_motion(motion::Rigid_motion());
  return id;
}

Moving_body prepare_body(std::shared_ptr<const Body_data> data, std::shared_ptr<const Motion_data> mo) {
  if (!mo) throw arith::Internal_error("prepare_body: no motion data");
  Moving_body b;
  b.data = std::move(data);
  b.mesh = b.data->mesh;
  b.spheres = b.data->spheres;
  b.mo = std::move(mo);
  b.derived = std::make_shared<const Attachments>();
  return b;
}

Moving_body prepare_body(std::shared_ptr<const Body_data> data, const motion::Rigid_motion &m) {
  return prepare_body(std::move(data), prepare_motion(m));
}

std::shared_ptr<const Body_data> same_geometry(const Body_data &d, std::shared_ptr<const motion::Mesh_body> mesh) {
  if (!d.mesh || !mesh || mesh->vertices().size() != d.mesh->vertices().size() ||
      mesh->triangles() != d.mesh->triangles())
    throw arith::Internal_error("same_geometry: not the same mesh");
  auto out = std::make_shared<Body_data>(d);
  out->mesh = std::move(mesh);
  return out;
}

std::shared_ptr<const Body_data> make_body_data(std::shared_ptr<const motion::Mesh_body> mesh,
                                                std::shared_ptr<const motion::Sphere_body> spheres) {
  auto data = std::make_shared<Body_data>();
  Body_data &b = *data;
  b.mesh = std::move(mesh);
  b.spheres = std::move(spheres);
  const auto &P = b.mesh ? b.mesh->vertices() : b.spheres->centers();
  b.pts.resize(P.size());
  double err = 0;
  for (size_t k = 0; k < P.size(); ++k)
    for (int a = 0; a < 3; ++a) b.pts[k][a] = approx(P[k][a], err);
  b.pt_err = err;
  double r_max = 0;
  std::vector<double> sizes;
  if (b.spheres) {
    for (const Rational &r : b.spheres->radii()) {
      b.radius_up.push_back(arith::enclose(r).hi);
      r_max = std::max(r_max, b.radius_up.back());
    }
    for (double r : b.radius_up) sizes.push_back(2 * r);
  } else {
    const auto &T = b.mesh->triangles();
    b.tri_edges.resize(T.size());
    std::vector<char> used(P.size(), 0);
    for (size_t t = 0; t < T.size(); ++t)
      for (int s = 0; s < 3; ++s) {
        b.tri_edges[t][s] = edge_index(*b.mesh, T[t][s], T[t][(s + 1) % 3]);
        used[T[t][s]] = 1;
      }
    for (size_t k = 0; k < P.size(); ++k)
      if (used[k]) b.surface_vertices.push_back(static_cast<uint32_t>(k));
    const size_t step = std::max<size_t>(1, T.size() / 2000);  // a sample is enough
    for (size_t t = 0; t < T.size(); t += step) {
      double d2 = 0;
      for (int a = 0; a < 3; ++a) {
        double lo = b.pts[T[t][0]][a], hi = lo;
        for (int s = 1; s < 3; ++s) {
          lo = std::min(lo, b.pts[T[t][s]][a]);
          hi = std::max(hi, b.pts[T[t][s]][a]);
        }
        d2 += (hi - lo) * (hi - lo);
      }
      sizes.push_back(std::sqrt(d2));
    }
  }
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = b.pts.empty() ? 0 : b.pts[0][a];
  double reach = 0;
  for (const auto &p : b.pts)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
      reach = std::max(reach, std::fabs(p[a]));
    }
  // Upper bounds (each a few roundings above the true value; the boxes built from them
  // widen again by the slack of boxes.h).
  const double pad = (r_max + err) * (1 + 1e-12);
  for (int a = 0; a < 3; ++a) {
    b.box_c[a] = 0.5 * (lo[a] + hi[a]);
    b.box_h[a] = (0.5 * (hi[a] - lo[a]) + pad + 1e-15 * std::fabs(b.box_c[a])) * (1 + 1e-12) + 1e-300;
  }
  b.reach = (reach + pad) * (1 + 1e-12);
  for (int a = 0; a < 3; ++a)  // a body beyond the double range: an infinite box about 0
    if (!std::isfinite(b.box_c[a]) || !std::isfinite(b.box_h[a])) {
      b.box_c[a] = 0;
      b.box_h[a] = INFINITY;
    }
  b.feature = median(sizes);
  if (!(b.feature > 0) || !std::isfinite(b.feature)) b.feature = b.reach > 0 && std::isfinite(b.reach) ? b.reach : 1.0;
  // No NaN reaches a filter or a broad phase (issue 23): the doubles above are upper
  // bounds, +infinity at worst (numbers beyond the double range), never NaN.
  bool nan = std::isnan(b.reach) || std::isnan(b.feature) || std::isnan(b.pt_err);
  for (int a = 0; a < 3; ++a) nan = nan || std::isnan(b.box_c[a]) || std::isnan(b.box_h[a]);
  if (nan) throw arith::Internal_error("make_body_data: a NaN bound");
  return data;
}

}  // namespace pccd::narrow
