#include "step/step_set.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "arith/errors.h"
#include "arith/rational.h"
#include "motion/body.h"
#include "util/work_budget.h"

namespace pccd::step {
namespace {

using arith::Input_error;

std::string at(const char *name, size_t i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

// Input_error (rational_from_double's message) for the first non-finite coordinate.
void check_finite(const double *x, size_t nv, const char *name) {
  for (size_t i = 0; i < 3 * nv; ++i)
    if (!std::isfinite(x[i])) arith::rational_from_double(x[i], at(name, i / 3) + "[" + std::to_string(i % 3) + "]");
}

void check_index(unsigned v, size_t nv, const std::string &where) {
  if (v >= nv)
    throw Input_error(where + ": index " + std::to_string(v) + " out of range (" +
                      std::to_string(nv) + " vertices)");
}

void check_positions(const double *x0, const double *x1, size_t nv) {
  if (nv && (!x0 || !x1)) throw Input_error(!x0 ? "v_t0: is NULL" : "v_t1: is NULL");
  check_finite(x0, nv, "v_t0");
  check_finite(x1, nv, "v_t1");
}

}  // namespace

size_t add_mesh(Step_set &s, const double *x0, const double *x1, size_t nv,
                const unsigned *faces, size_t nf, const unsigned *edges, size_t ne,
                const unsigned *points, size_t np) {
  motion::check_body_size(nv, "nv");
  motion::check_body_size(nf, "nf");
  motion::check_body_size(ne, "ne");
  motion::check_body_size(np, "np");
  motion::check_body_size(s.x0.size() / 3 + nv, "vertices of the step");
  check_positions(x0, x1, nv);
  if (nf && !faces) throw Input_error("faces: is NULL");
  if (ne && !edges) throw Input_error("edges: is NULL");
  if (np && !points) throw Input_error("points: is NULL");
  // Everything is checked into locals first, so the set is unchanged on error. A work
  // step per 4,096 elements before each pass (pccd_step_add_mesh_cfg_d's limits).
  const uint64_t pass = 1 + (nv + nf + ne + np) / 4096;
  util::work_step(pass);
  std::vector<std::array<uint32_t, 3>> f(nf);
  for (size_t i = 0; i < nf; ++i) {
    for (size_t k = 0; k < 3; ++k) check_index(faces[3 * i + k], nv, at("faces", i) + "[" + std::to_string(k) + "]");
    const unsigned a = faces[3 * i], b = faces[3 * i + 1], c = faces[3 * i + 2];
    if (a == b || b == c || a == c)
      throw Input_error(at("faces", i) + ": repeats vertex " + std::to_string(a == b || a == c ? a : b) +
                        " (a degenerate face)");
    f[i] = {a, b, c};
  }
  std::vector<std::array<uint32_t, 2>> e;
  if (edges) {
    e.resize(ne);
    for (size_t i = 0; i < ne; ++i) {
      for (size_t k = 0; k < 2; ++k) check_index(edges[2 * i + k], nv, at("edges", i) + "[" + std::to_string(k) + "]");
      const unsigned a = edges[2 * i], b = edges[2 * i + 1];
      if (a == b) throw Input_error(at("edges", i) + ": repeats vertex " + std::to_string(a) + " (a degenerate edge)");
      e[i] = {std::min(a, b), std::max(a, b)};
    }
  } else {
    e.reserve(3 * nf);
    for (const auto &t : f)
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = t[k], b = t[(k + 1) % 3];
        e.push_back({std::min(a, b), std::max(a, b)});
      }
  }
  util::work_step(pass);
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  util::work_step(pass);
  std::vector<uint32_t> p(np);
  for (size_t i = 0; i < np; ++i) {
    check_index(points[i], nv, at("points", i));
    p[i] = points[i];
  }
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  std::vector<uint8_t> use(nv, 0);
  for (const auto &t : f) use[t[0]] = use[t[1]] = use[t[2]] = 1;
  for (const auto &d : e) use[d[0]] = use[d[1]] = 1;
  for (uint32_t v : p) use[v] = 1;

  // Commit: nothing below throws but bad_alloc.
  const size_t m = s.meshes.size();
  Mesh_range r;
  r.v0 = static_cast<uint32_t>(s.x0.size() / 3);
  r.nv = static_cast<uint32_t>(nv);
  r.f0 = static_cast<uint32_t>(s.faces.size());
  r.nf = static_cast<uint32_t>(f.size());
  r.e0 = static_cast<uint32_t>(s.edges.size());
  r.ne = static_cast<uint32_t>(e.size());
  r.p0 = static_cast<uint32_t>(s.points.size());
  r.np = static_cast<uint32_t>(p.size());
  s.x0.insert(s.x0.end(), x0, x0 + 3 * nv);
  s.x1.insert(s.x1.end(), x1, x1 + 3 * nv);
  s.vmesh.insert(s.vmesh.end(), nv, static_cast<uint32_t>(m));
  for (const auto &t : f) s.faces.push_back({t[0] + r.v0, t[1] + r.v0, t[2] + r.v0});
  for (const auto &d : e) s.edges.push_back({d[0] + r.v0, d[1] + r.v0});
  for (uint32_t v : p) s.points.push_back(v + r.v0);
  s.fmesh.insert(s.fmesh.end(), f.size(), static_cast<uint32_t>(m));
  s.emesh.insert(s.emesh.end(), e.size(), static_cast<uint32_t>(m));
  s.pmesh.insert(s.pmesh.end(), p.size(), static_cast<uint32_t>(m));
  for (uint32_t v = 0; v < nv; ++v)
    if (use[v]) s.used.push_back(v + r.v0);
  s.meshes.push_back(r);
  s.ncoef.push_back(0);
  s.coef.emplace_back();
  // Grow the pair matrix: the new mesh is checked against every mesh and itself.
  const size_t n = m + 1;
  std::vector<uint8_t> skip(n * n, 0);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) skip[i * n + j] = s.skip[i * m + j];
  s.skip.swap(skip);
  return m;
}

namespace {

// Mesh m of the set, with nv its vertex count (Input_error otherwise).
const Mesh_range &mesh_of(const Step_set &s, size_t m, size_t nv) {
  if (m >= s.meshes.size())
    throw Input_error("mesh: " + std::to_string(m) + " out of range (" + std::to_string(s.meshes.size()) +
                      " meshes)");
  const Mesh_range &r = s.meshes[m];
  if (nv != r.nv)
    throw Input_error("nv: " + std::to_string(nv) + " vertices given, mesh " + std::to_string(m) + " has " +
                      std::to_string(r.nv));
  return r;
}

}  // namespace

void set_positions(Step_set &s, size_t m, const double *x0, const double *x1, size_t nv) {
  const Mesh_range &r = mesh_of(s, m, nv);
  check_positions(x0, x1, nv);
  std::copy(x0, x0 + 3 * nv, s.x0.begin() + 3 * size_t(r.v0));
  std::copy(x1, x1 + 3 * nv, s.x1.begin() + 3 * size_t(r.v0));
  s.ncoef[m] = 0;
  s.coef[m].clear();
}

void set_paths(Step_set &s, size_t m, const double *coef, size_t ncoef, size_t nv) {
  const Mesh_range &r = mesh_of(s, m, nv);
  if (ncoef < 1 || ncoef > kMax_path_coefficients)
    throw Input_error("ncoeffs: " + std::to_string(ncoef) + " is outside 1.." +
                      std::to_string(kMax_path_coefficients) + " (degree 0 to " +
                      std::to_string(kMax_path_coefficients - 1) + ")");
  if (nv && !coef) throw Input_error("coeffs: is NULL");
  for (size_t i = 0; i < 3 * nv * ncoef; ++i)
    if (!std::isfinite(coef[i]))
      arith::rational_from_double(coef[i], at("coeffs", i / (3 * nv)) + "[" + std::to_string(i / 3 % nv) + "][" +
                                               std::to_string(i % 3) + "]");
  for (size_t i = 0; i < nv; ++i)
    for (size_t a = 0; a < 3; ++a) {
      double end = 0;  // x(1), rounded: the broad phase's frame velocity only
      for (size_t k = 0; k < ncoef; ++k) end += coef[(k * nv + i) * 3 + a];
      s.x0[3 * (r.v0 + i) + a] = coef[i * 3 + a];
      s.x1[3 * (r.v0 + i) + a] = std::isfinite(end) ? end : coef[i * 3 + a];
    }
  s.coef[m].assign(coef, coef + 3 * nv * ncoef);
  s.ncoef[m] = static_cast<uint32_t>(ncoef);
}

void set_pair_check(Step_set &s, size_t i, size_t j, bool check) {
  const size_t n = s.meshes.size();
  for (size_t k : {i, j})
    if (k >= n)
      throw Input_error(std::string(k == i ? "i" : "j") + ": " + std::to_string(k) + " out of range (" +
                        std::to_string(n) + " meshes)");
  s.skip[i * n + j] = s.skip[j * n + i] = check ? 0 : 1;
}

}  // namespace pccd::step
