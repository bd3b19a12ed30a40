// The tail report of bench_linear (bench_linear_tail.h).
//
// Stage histogram: per kind (vertex-face, edge-edge) and polyccd mode (decide, time),
// for each pccd_stage that decided a query: count, mean / median / p90 / p99 / max of the
// per-query time (us, minimum over the rounds) and the stage's share of the mode's total.
//
// Families: flags computed exactly from the input doubles (GMP rationals; no rounding):
//   coplanar-always  the coplanarity cubic f (VF: det(f1 - f0, f2 - f0, v - f0), EE:
//                    det(a1 - a0, b0 - a0, b1 - a0)) is identically 0 (zero at t = 0,
//                    1/3, 2/3, 1: a cubic with 4 roots is the zero polynomial)
//   coplanar-t0/t1   f(0) = 0 / f(1) = 0
//   parallel         EE: (a1 - a0) x (b1 - b0) = 0 at t = 0 or at t = 1
//   degenerate       a zero-length edge or zero-area triangle at t = 0 or at t = 1
//   touch-t0/t1      the primitives touch at t = 0 / t = 1: polyccd's exact answer for
//                    the static query (the positions of that time at both ends)
//   vertices-meet    a point of one primitive and a point of the other coincide at some
//                    t in [0, 1] (their relative motion is linear: the minimum of the
//                    squared distance over [0, 1] is a rational, computed exactly)
// and three "near" families, labels only (exact comparisons against thresholds; s is
// taken in doubles, a label's scale; they decide nothing):
//   near-vertices    not vertices-meet, but two such points pass within 2^-40 s of each
//                    other, s the largest coordinate difference of the query's points
//   near-coplanar    not coplanar-always, but |f| <= 2^-40 s^3 at t = 0, 1/3, 2/3, 1
//   near-parallel    EE, not parallel, but |(a1 - a0) x (b1 - b0)|^2 <= 2^-80 |a1 - a0|^2
//                    |b1 - b0|^2 at t = 0 or at t = 1 (the sine of the angle <= 2^-40)
//   general          none of these
// Input width: the bits of the integers the query's 24 coordinates become on one common
// scale (highest set bit of any minus lowest set bit of any, plus 1; exact, from the
// doubles' binary forms): what a fixed-size integer exact stage would have to hold
// (issue 34, item 2), shown for all queries and for those decided by the exact stage.
// A query can be in several families. The "slowest 1 %" column counts each family in
// the 1 % slowest queries of polyccd-decide.
#include "bench_linear_tail.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <string>

#include <gmpxx.h>

#include "polyccd.h"

namespace bench {
namespace {

const char *const kStage[5] = {"none", "bounds", "bernstein", "interval", "exact"};

enum Family { COPLANAR_ALWAYS, COPLANAR_T0, COPLANAR_T1, PARALLEL, DEGENERATE, TOUCH_T0, TOUCH_T1,
              VERTICES_MEET, NEAR_VERTICES, NEAR_COPLANAR, NEAR_PARALLEL, GENERAL, kFamilies };
const char *const kFamily[kFamilies] = {"coplanar-always", "coplanar-t0", "coplanar-t1", "parallel",
                                        "degenerate", "touch-t0", "touch-t1", "vertices-meet",
                                        "near-vertices", "near-coplanar", "near-parallel", "general"};

using V3 = std::array<mpq_class, 3>;

V3 sub(const V3 &a, const V3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(const V3 &a, const V3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
mpq_class dot(const V3 &a, const V3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool zero(const V3 &a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// Point k of q at time t (exact: x0 + (x1 - x0) t).
V3 at(const Linear_query &q, int k, const mpq_class &t) {
  V3 p;
  for (int a = 0; a < 3; ++a) {
    mpq_class x0(q.t0[3 * k + a]), x1(q.t1[3 * k + a]);
    p[a] = x0 + (x1 - x0) * t;
  }
  return p;
}

mpq_class cubic_at(const Linear_query &q, const mpq_class &t) {
  V3 p[4] = {at(q, 0, t), at(q, 1, t), at(q, 2, t), at(q, 3, t)};
  if (q.kind == PCCD_VERTEX_FACE) return dot(cross(sub(p[2], p[1]), sub(p[3], p[1])), sub(p[0], p[1]));
  return dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), sub(p[3], p[0]));
}

bool degenerate_at(const Linear_query &q, const mpq_class &t) {
  V3 p[4] = {at(q, 0, t), at(q, 1, t), at(q, 2, t), at(q, 3, t)};
  if (q.kind == PCCD_VERTEX_FACE) return zero(cross(sub(p[2], p[1]), sub(p[3], p[1])));
  return zero(sub(p[1], p[0])) || zero(sub(p[3], p[2]));
}

bool parallel_at(const Linear_query &q, const mpq_class &t) {
  if (q.kind != PCCD_EDGE_EDGE) return false;
  V3 p[4] = {at(q, 0, t), at(q, 1, t), at(q, 2, t), at(q, 3, t)};
  return zero(cross(sub(p[1], p[0]), sub(p[3], p[2])));
}

// polyccd's exact answer for the query frozen at its t = 0 (end 0) or t = 1 positions.
bool touches_at(const Linear_query &q, int end, pccd_result *res) {
  const double *p = end == 0 ? q.t0 : q.t1;
  pccd_config cfg;
  int hit = 0;
  if (pccd_config_init(&cfg) != PCCD_OK) return false;
  cfg.want_time = 0;
  if (pccd_solve_linear_d(q.kind, p, p, &cfg, res) != PCCD_OK) return false;
  return pccd_result_collides(res, &hit) == PCCD_OK && hit;
}

// The smallest squared distance over t in [0, 1] between point i and point j of q.
mpq_class min_dist2(const Linear_query &q, int i, int j) {
  const V3 d0 = sub(at(q, i, 0), at(q, j, 0)), e = sub(sub(at(q, i, 1), at(q, j, 1)), d0);
  const mpq_class ee = dot(e, e);
  mpq_class t = ee == 0 ? mpq_class(0) : mpq_class(-dot(d0, e) / ee);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  const V3 d = {d0[0] + e[0] * t, d0[1] + e[1] * t, d0[2] + e[2] * t};
  return dot(d, d);
}

// The smallest squared distance between a point of the first primitive (VF: the vertex;
// EE: a0, a1) and a point of the second, over [0, 1].
mpq_class min_vertex_dist2(const Linear_query &q) {
  const int split = q.kind == PCCD_VERTEX_FACE ? 1 : 2;
  mpq_class best = -1;
  for (int i = 0; i < split; ++i)
    for (int j = split; j < 4; ++j) {
      mpq_class d = min_dist2(q, i, j);
      if (best < 0 || d < best) best = d;
    }
  return best;
}

bool near_parallel_at(const Linear_query &q, const mpq_class &t) {
  if (q.kind != PCCD_EDGE_EDGE) return false;
  V3 p[4] = {at(q, 0, t), at(q, 1, t), at(q, 2, t), at(q, 3, t)};
  const V3 a = sub(p[1], p[0]), b = sub(p[3], p[2]), c = cross(a, b);
  return dot(c, c) * (mpq_class(1) << 80) <= dot(a, a) * dot(b, b);
}

std::array<bool, kFamilies> families_of(const Linear_query &q, pccd_result *res) {
  std::array<bool, kFamilies> f{};
  const mpq_class t0(0), t1(1), a(1, 3), b(2, 3);
  f[COPLANAR_T0] = cubic_at(q, t0) == 0;
  f[COPLANAR_T1] = cubic_at(q, t1) == 0;
  f[COPLANAR_ALWAYS] = f[COPLANAR_T0] && f[COPLANAR_T1] && cubic_at(q, a) == 0 && cubic_at(q, b) == 0;
  f[PARALLEL] = parallel_at(q, t0) || parallel_at(q, t1);
  f[DEGENERATE] = degenerate_at(q, t0) || degenerate_at(q, t1);
  f[TOUCH_T0] = touches_at(q, 0, res);
  f[TOUCH_T1] = touches_at(q, 1, res);
  double s = 0;
  for (int i = 3; i < 12; ++i)
    s = std::max({s, std::fabs(q.t0[i] - q.t0[i % 3]), std::fabs(q.t1[i] - q.t1[i % 3])});
  const mpq_class s2 = mpq_class(s) * mpq_class(s), eps(1, mpz_class(1) << 40);
  const mpq_class d2 = min_vertex_dist2(q);
  f[VERTICES_MEET] = d2 == 0;
  f[NEAR_VERTICES] = !f[VERTICES_MEET] && d2 <= s2 * eps * eps;
  bool near_coplanar = !f[COPLANAR_ALWAYS];
  for (int k = 0; k < 4 && near_coplanar; ++k) near_coplanar = abs(cubic_at(q, mpq_class(k, 3))) <= s2 * s * eps;
  f[NEAR_COPLANAR] = near_coplanar;
  f[NEAR_PARALLEL] = !f[PARALLEL] && (near_parallel_at(q, t0) || near_parallel_at(q, t1));
  f[GENERAL] = std::none_of(f.begin(), f.end() - 1, [](bool x) { return x; });
  return f;
}

// The input width of q (above); 0 when every coordinate is 0.
int input_width(const Linear_query &q) {
  int hi = INT32_MIN, lo = INT32_MAX;
  for (int k = 0; k < 24; ++k) {
    const double x = k < 12 ? q.t0[k] : q.t1[k - 12];
    if (x == 0) continue;
    int e = 0;
    const double m = std::frexp(std::fabs(x), &e);  // |x| = m 2^e, m in [1/2, 1)
    const auto bits = static_cast<unsigned long long>(std::ldexp(m, 53));  // exact: 53 bits
    hi = std::max(hi, e - 1);
    lo = std::min(lo, e - 53 + __builtin_ctzll(bits));
  }
  return hi == INT32_MIN ? 0 : hi - lo + 1;
}

struct Dist {
  std::size_t n = 0;
  double mean = NAN, median = NAN, p90 = NAN, p99 = NAN, max = NAN, sum = 0;  // us
};

double quantile(const std::vector<double> &v, double q) {
  std::size_t k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, k == 0 ? 0 : k - 1)];
}

Dist dist_of(std::vector<double> v) {
  Dist d;
  d.n = v.size();
  if (v.empty()) return d;
  std::sort(v.begin(), v.end());
  for (double x : v) d.sum += x;
  d.mean = d.sum / static_cast<double>(d.n);
  d.median = d.n % 2 ? v[d.n / 2] : 0.5 * (v[d.n / 2 - 1] + v[d.n / 2]);
  d.p90 = quantile(v, 0.90), d.p99 = quantile(v, 0.99), d.max = v.back();
  return d;
}

void stage_table(const char *kind, const std::vector<std::size_t> &idx, const Method_run &r, int m,
                 Json_writer &json) {
  double total = 0;
  std::vector<double> by[5];
  for (std::size_t i : idx) {
    int s = std::min(4, std::max(0, r.stage[i]));
    by[s].push_back(r.ns[i] * 1e-3);
    total += r.ns[i] * 1e-3;
  }
  std::printf("      %s, %s (total %.1f us):\n", kind, method_name(m), total);
  std::printf("        %-10s %6s %9s %9s %9s %9s %9s %7s\n", "stage", "count", "mean", "median", "p90", "p99",
              "max", "share");
  json.open(method_name(m), '{');
  for (int s = 0; s <= 4; ++s) {
    if (by[s].empty()) continue;
    Dist d = dist_of(by[s]);
    std::printf("        %-10s %6zu %9.3f %9.3f %9.3f %9.3f %9.1f %6.1f%%\n", kStage[s], d.n, d.mean, d.median,
                d.p90, d.p99, d.max, total > 0 ? 100 * d.sum / total : 0.0);
    json.open(kStage[s], '{');
    json.num("count", static_cast<double>(d.n)), json.num("mean", d.mean), json.num("median", d.median);
    json.num("p90", d.p90), json.num("p99", d.p99), json.num("max", d.max);
    json.num("share", total > 0 ? d.sum / total : NAN);
    json.close('}');
  }
  json.close('}');
}

void family_table(const char *kind, const std::vector<std::size_t> &idx,
                  const std::vector<std::array<bool, kFamilies>> &fam,
                  const std::array<Method_run, kMethods> &runs, Json_writer &json) {
  if (idx.empty()) return;
  std::vector<double> d;
  for (std::size_t i : idx) d.push_back(runs[DECIDE].ns[i]);
  std::sort(d.begin(), d.end());
  const std::size_t slow_n = std::max<std::size_t>(1, idx.size() / 100);
  const double slow_cut = d[d.size() - slow_n];
  double tot[kMethods] = {};
  for (std::size_t i : idx) tot[DECIDE] += runs[DECIDE].ns[i], tot[TIME] += runs[TIME].ns[i];
  std::printf("      %s families (slowest 1 %% = the %zu decide queries >= %.2f us):\n", kind, slow_n,
              slow_cut * 1e-3);
  std::printf("        %-16s %6s %7s %8s %10s %7s %10s %7s\n", "family", "count", "exact", "slow1%", "decide us",
              "share", "time us", "share");
  json.open(kind, '{');
  for (int f = 0; f < kFamilies; ++f) {
    std::size_t n = 0, exact = 0, slow = 0;
    double sd = 0, st = 0;
    for (std::size_t i : idx) {
      if (!fam[i][f]) continue;
      ++n, exact += runs[DECIDE].stage[i] == PCCD_STAGE_EXACT, slow += runs[DECIDE].ns[i] >= slow_cut;
      sd += runs[DECIDE].ns[i], st += runs[TIME].ns[i];
    }
    if (n == 0) continue;
    const double dn = static_cast<double>(n);
    std::printf("        %-16s %6zu %7zu %8zu %10.3f %6.1f%% %10.3f %6.1f%%\n", kFamily[f], n, exact, slow,
                sd * 1e-3 / dn, 100 * sd / tot[DECIDE], st * 1e-3 / dn, 100 * st / tot[TIME]);
    json.open(kFamily[f], '{');
    json.num("count", dn), json.num("exact_stage", static_cast<double>(exact));
    json.num("in_slowest_1pct", static_cast<double>(slow));
    json.num("decide_mean_us", sd * 1e-3 / dn), json.num("decide_share", sd / tot[DECIDE]);
    json.num("time_mean_us", st * 1e-3 / dn), json.num("time_share", st / tot[TIME]);
    json.close('}');
  }
  json.close('}');
}

}  // namespace

void report_tail(const std::vector<Linear_query> &qs, const std::array<Method_run, kMethods> &runs,
                 Json_writer &json) {
  std::vector<std::size_t> vf, ee;
  for (std::size_t i = 0; i < qs.size(); ++i) (qs[i].kind == PCCD_VERTEX_FACE ? vf : ee).push_back(i);
  std::printf("   -- the tail (issue 34): cost by the stage that decided, us per query\n");
  json.open("tail", '{');
  json.open("stages", '{');
  for (int k = 0; k < 2; ++k) {
    const char *kind = k == 0 ? "vertex-face" : "edge-edge";
    json.open(kind, '{');
    for (int m : {DECIDE, TIME}) stage_table(kind, k == 0 ? vf : ee, runs[m], m, json);
    json.close('}');
  }
  json.close('}');
  json.open("input_width_bits", '{');
  for (int k = 0; k < 2; ++k) {
    const char *kind = k == 0 ? "vertex-face" : "edge-edge";
    std::vector<double> all, exact;
    for (std::size_t i : k == 0 ? vf : ee) {
      all.push_back(input_width(qs[i]));
      if (runs[DECIDE].stage[i] == PCCD_STAGE_EXACT) exact.push_back(all.back());
    }
    json.open(kind, '{');
    for (int e = 0; e < 2; ++e) {
      Dist d = dist_of(e == 0 ? all : exact);
      std::printf("      %s input width in bits, %s (%zu): median %.0f, p90 %.0f, p99 %.0f, max %.0f\n", kind,
                  e == 0 ? "all" : "decided by exact", d.n, d.median, d.p90, d.p99, d.max);
      json.open(e == 0 ? "all" : "exact_stage", '{');
      json.num("count", static_cast<double>(d.n)), json.num("median", d.median), json.num("p90", d.p90);
      json.num("p99", d.p99), json.num("max", d.max);
      json.close('}');
    }
    json.close('}');
  }
  json.close('}');
  pccd_result *res = nullptr;
  if (pccd_result_new(&res) != PCCD_OK) {
    json.close('}');
    return;
  }
  std::vector<std::array<bool, kFamilies>> fam(qs.size());
  for (std::size_t i = 0; i < qs.size(); ++i) fam[i] = families_of(qs[i], res);
  pccd_result_free(res);
  json.open("families", '{');
  family_table("vertex-face", vf, fam, runs, json);
  family_table("edge-edge", ee, fam, runs, json);
  json.close('}');
  json.close('}');
}

}  // namespace bench
