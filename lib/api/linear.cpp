// pccd_solve_linear_d and its batch twin pccd_solve_linear_batch_d: queries of points
// moving linearly, given as doubles. Both run the static filter (pred/linear_filter.h),
// then the hit certificate (pred/linear_crossing.h), and the staged solver only when
// neither decides, so a batch entry is exactly the single call's answer.
#include <algorithm>
#include <cmath>
#include <string>

#include "api/guard.h"
#include "api/limits.h"
#include "api/handles.h"
#include "pred/linear_crossing.h"
#include "pred/linear_filter.h"
#include "util/thread_pool.h"

using pccd::api::guard;
using pccd::api::place;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Interval;
using pccd::arith::Rational;

namespace pccd::api {
namespace {

// The number of points of a linear kind (every kind but SPHERE_SPHERE).
size_t linear_points(long kind) {
  if (kind == PCCD_SPHERE_SPHERE)
    throw Input_error("kind: sphere-sphere queries need radii: use pccd_query_new");
  return kind_points(kind);
}

// Input_error naming the first non-finite coordinate a of point i: name[i][a], or
// name[k][i][a] for query k of a batch (k != nullptr).
void check_finite(const double *p, size_t n, const char *name, const size_t *k) {
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a) {
      const double x = p[3 * i + a];
      if (!std::isfinite(x))
        arith::rational_from_double(x, k ? place(name, {*k, i, a}) : place(name, {i, a}));
    }
}

// The static filter's answer into out (reset); false when it cannot decide.
bool filtered(long kind, const double *p0, const double *p1, pred::Contact_result &out) {
  switch (pred::linear_filter(static_cast<int>(kind), p0, p1)) {
    case pred::Linear_verdict::boxes_apart: out.stage = pred::STAGE_BOUNDS; return true;
    case pred::Linear_verdict::no_root: out.stage = pred::STAGE_BERNSTEIN; return true;
    case pred::Linear_verdict::misses: out.stage = pred::STAGE_INTERVAL; return true;
    case pred::Linear_verdict::unknown: break;
  }
  return false;
}

// The hit certificate (pred/linear_crossing.h): the staged solver's answer of a single
// transversal crossing, its time by the same midpoint bisection.
bool certified_hit(long kind, const double *p0, const double *p1, const pred::Solve_options &opt,
                   pred::Contact_result &out) {
  return pred::crossing_hit(static_cast<int>(kind), p0, p1, opt, out);
}

// The staged solver on n points with finite coordinates.
pred::Contact_result solve_staged(long kind, size_t n, const double *p0, const double *p1,
                                  const pred::Solve_options &opt) {
  const arith::Nearest_scope nearest;  // before any interval arithmetic
  // The interval stages see the doubles as exact points; the exact trajectories are
  // built only if those stages cannot decide.
  pred::Query_data<Interval> iq;
  iq.kind = static_cast<int>(kind);
  iq.p.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const double x0 = p0[3 * i + a], x1 = p1[3 * i + a];
      // x(t) = x0 + (x1 - x0) t: the slope is enclosed, not rounded.
      iq.p[i][a] = poly::Poly<Interval>(std::vector<Interval>{Interval(x0), Interval(x1) - Interval(x0)});
    }
  auto exact = [&] {
    pred::Query_data<Rational> eq;
    eq.kind = static_cast<int>(kind);
    eq.p.resize(n);
    for (size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) {
        Rational x0 = arith::rational_from_double(p0[3 * i + a], "p_t0");
        Rational x1 = arith::rational_from_double(p1[3 * i + a], "p_t1");
        eq.p[i][a] = poly::Poly<Rational>(std::vector<Rational>{x0, x1 - x0});
      }
    return eq;
  };
  return pred::solve(iq, exact, opt);
}

// Writes answer k of a batch.
void write(const pccd_batch_out &out, size_t k, const pred::Contact_result &r) {
  if (out.collides) out.collides[k] = r.collides ? 1 : 0;
  if (out.stage) out.stage[k] = r.stage;
  if (out.exact) out.exact[k] = r.collides && r.exact ? 1 : 0;
  if (out.lo) out.lo[k] = r.collides ? arith::enclose(r.lo).lo : NAN;
  if (out.hi) out.hi[k] = r.collides ? arith::enclose(r.hi).hi : NAN;
}

constexpr size_t kChunk = 256;  // queries per parallel task

// The input limit for the doubles of a linear query: only a limit below the size of
// the largest double (1,127 bits) can be exceeded, so the default costs nothing.
void check_double_bits(const Call_limits &l, const double *p, size_t n, const char *name,
                       const size_t *query) {
  if (l.max_number_bits == 0 || l.max_number_bits >= 1127) return;
  for (size_t i = 0; i < 3 * n; ++i) {
    Biggest_number b;
    b.bits = number_bits(p[i]);
    b.place = query ? place(name, {*query, i / 3, i % 3}) : place(name, {i / 3, i % 3});
    l.check(b);
  }
}

}  // namespace

void solve_linear_one(int kind, const double *p0, const double *p1, const pred::Solve_options &opt,
                      pred::Contact_result &r) {
  reset(r);
  if (sgn(opt.delta) > 0 || (!filtered(kind, p0, p1, r) && !certified_hit(kind, p0, p1, opt, r)))
    r = solve_staged(kind, linear_points(kind), p0, p1, opt);
}

}  // namespace pccd::api

extern "C" {

PCCD_API int pccd_solve_linear_d(pccd_kind kind, const double *p_t0, const double *p_t1,
                                 const pccd_config *cfg, pccd_result *res) {
  return guard(__func__, [&] {
    require(res, "res");
    res->solved = false;
    pccd::api::reset(res->r);
    require(p_t0, "p_t0");
    require(p_t1, "p_t1");
    const long k = pccd::api::raw_kind(kind);
    const size_t n = pccd::api::linear_points(k);
    pccd::api::checked_config(cfg);
    pccd::api::check_finite(p_t0, n, "p_t0", nullptr);
    pccd::api::check_finite(p_t1, n, "p_t1", nullptr);
    const pccd::api::Call_limits limits = pccd::api::read_limits(cfg);
    pccd::api::check_double_bits(limits, p_t0, n, "p_t0", nullptr);
    pccd::api::check_double_bits(limits, p_t1, n, "p_t1", nullptr);
    const bool delta = pccd::api::has_min_distance(cfg);  // the fast paths assume delta = 0
    if (delta || !pccd::api::filtered(k, p_t0, p_t1, res->r)) {
      const pccd::pred::Solve_options opt = pccd::api::read_config(cfg);
      if (delta || !pccd::api::certified_hit(k, p_t0, p_t1, opt, res->r)) {
        const pccd::api::Call_budget budget(limits.work);
        res->r = pccd::api::solve_staged(k, n, p_t0, p_t1, opt);
      }
    }
    res->solved = true;
    return PCCD_OK;
  });
}

PCCD_API int pccd_batch_options_init(pccd_batch_options *opt) {
  return guard(__func__, [&] {
    require(opt, "opt");
    opt->struct_size = sizeof *opt;
    opt->threads = 1;
    return PCCD_OK;
  });
}

PCCD_API int pccd_solve_linear_batch_d(pccd_kind kind, size_t n, const double *t0,
                                       const double *t1, const pccd_config *cfg,
                                       const pccd_batch_options *opt, pccd_batch_out *out) {
  return guard(__func__, [&] {
    require(out, "out");
    if (out->struct_size != sizeof(pccd_batch_out))
      throw Input_error("out.struct_size: " + std::to_string(out->struct_size) + " is not " +
                        std::to_string(sizeof(pccd_batch_out)));
    unsigned threads = 1;
    if (opt) {
      if (opt->struct_size != sizeof(pccd_batch_options))
        throw Input_error("opt.struct_size: " + std::to_string(opt->struct_size) + " is not " +
                          std::to_string(sizeof(pccd_batch_options)) +
                          " (initialise with pccd_batch_options_init)");
      if (opt->threads < 1 || opt->threads > 1024)
        throw Input_error("opt.threads: " + std::to_string(opt->threads) + " is outside 1..1024");
      threads = opt->threads;
    }
    const long k = pccd::api::raw_kind(kind);
    const size_t np = pccd::api::linear_points(k);
    const pccd::pred::Solve_options so = pccd::api::read_config(cfg);
    const pccd::api::Call_limits limits = pccd::api::read_limits(cfg);
    if (n == 0) return PCCD_OK;
    require(t0, "t0");
    require(t1, "t1");
    for (size_t q = 0; q < n; ++q) {
      pccd::api::check_finite(t0 + 3 * np * q, np, "t0", &q);
      pccd::api::check_finite(t1 + 3 * np * q, np, "t1", &q);
      pccd::api::check_double_bits(limits, t0 + 3 * np * q, np, "t0", &q);
      pccd::api::check_double_bits(limits, t1 + 3 * np * q, np, "t1", &q);
    }
    const pccd::api::Call_budget budget(limits.work);
    const size_t chunks = (n + pccd::api::kChunk - 1) / pccd::api::kChunk;
    pccd::util::Thread_pool pool(static_cast<unsigned>(std::min<size_t>(threads, chunks)));
    pool.parallel_for(chunks, [&](size_t c) {
      pccd::pred::Contact_result r;
      const size_t end = std::min(n, (c + 1) * pccd::api::kChunk);
      for (size_t q = c * pccd::api::kChunk; q < end; ++q) {
        const double *p0 = t0 + 3 * np * q, *p1 = t1 + 3 * np * q;
        pccd::api::solve_linear_one(static_cast<int>(k), p0, p1, so, r);
        pccd::api::write(*out, q, r);
      }
    });
    return PCCD_OK;
  });
}

}  // extern "C"
