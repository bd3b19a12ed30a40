#include "step/separate.h"

#include <cmath>
#include <initializer_list>

namespace pccd::step {
namespace {

constexpr double kU = 1.0 / 9007199254740992.0;  // 2^-53
constexpr double kTiny = 1e-300;                // > 2^-1070 and every underflow loss

struct V3 {
  double x, y, z;
};
V3 at(const double *p, int i) { return {p[3 * i], p[3 * i + 1], p[3 * i + 2]}; }
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Whether d . (a - b) > margin certainly for every a of points A and b of points B
// (indices into p0, p1) at both t = 0 and t = 1; sign flips d.
bool apart(V3 d, const double *p0, const double *p1, const int *A, int na, const int *B, int nb,
           double reach) {
  if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z))) return false;
  const double ad[3] = {std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
  if (ad[0] + ad[1] + ad[2] == 0) return false;
  // |d| rounded up: sqrt of a sum rounded three times, then one more relative step.
  const double norm = reach > 0 ? std::sqrt(ad[0] * ad[0] + ad[1] * ad[1] + ad[2] * ad[2]) * (1 + 8 * kU) : 0;
  const double need = reach * norm * (1 + 4 * kU);
  for (const double *p : {p0, p1})
    for (int i = 0; i < na; ++i)
      for (int j = 0; j < nb; ++j) {
        const V3 a = at(p, A[i]), b = at(p, B[j]);
        const double g = d.x * (a.x - b.x) + d.y * (a.y - b.y) + d.z * (a.z - b.z);
        const double mag = ad[0] * (std::fabs(a.x) + std::fabs(b.x)) + ad[1] * (std::fabs(a.y) + std::fabs(b.y)) +
                           ad[2] * (std::fabs(a.z) + std::fabs(b.z));
        if (!(g > need + 8 * kU * mag * (1 + 8 * kU) + kTiny)) return false;
      }
  return true;
}

bool either_way(V3 d, const double *p0, const double *p1, const int *A, int na, const int *B, int nb,
                double reach) {
  return apart(d, p0, p1, A, na, B, nb, reach) || apart(d, p0, p1, B, nb, A, na, reach);
}

}  // namespace

bool separated(int kind, const double *p0, const double *p1, double reach) {
  if (kind == 0) {  // VERTEX_FACE: v, f0, f1, f2
    static const int V[1] = {0}, F[3] = {1, 2, 3};
    for (const double *p : {p0, p1}) {
      const V3 f0 = at(p, 1), f1 = at(p, 2), f2 = at(p, 3);
      const V3 n = cross(sub(f1, f0), sub(f2, f0));
      if (either_way(n, p0, p1, V, 1, F, 3, reach)) return true;
      const V3 e[3] = {sub(f1, f0), sub(f2, f1), sub(f0, f2)};
      for (const V3 &k : e)
        if (either_way(cross(n, k), p0, p1, V, 1, F, 3, reach)) return true;
    }
    return false;
  }
  if (kind == 1) {  // EDGE_EDGE: a0, a1, b0, b1
    static const int A[2] = {0, 1}, B[2] = {2, 3};
    for (const double *p : {p0, p1}) {
      const V3 ea = sub(at(p, 1), at(p, 0)), eb = sub(at(p, 3), at(p, 2));
      const V3 n = cross(ea, eb);
      if (either_way(n, p0, p1, A, 2, B, 2, reach)) return true;
      // Nearly parallel edges: the plane through edge a and b's start.
      const V3 m = cross(ea, sub(at(p, 2), at(p, 0)));
      for (const V3 &plane : {n, m}) {
        if (either_way(cross(plane, ea), p0, p1, A, 2, B, 2, reach)) return true;
        if (either_way(cross(plane, eb), p0, p1, A, 2, B, 2, reach)) return true;
      }
    }
    return false;
  }
  return false;
}

}  // namespace pccd::step
