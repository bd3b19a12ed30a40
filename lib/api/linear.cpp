// pccd_solve_linear_d and its batch twin pccd_solve_linear_batch_d: queries of points
// moving linearly, given as doubles. Both check the input and answer each query with
// pred::solve_linear (filter, certificate, staged solver: pred/solve_linear.h), so a
// batch entry is exactly the single call's answer.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "api/config.h"
#include "api/guard.h"
#include "api/handles.h"
#include "pred/solve_linear.h"
#include "util/thread_pool.h"

using pccd::api::guard;
using pccd::api::place;
using pccd::api::require;
using pccd::arith::Input_error;

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
}  // namespace pccd::api

extern "C" {

PCCD_API int pccd_solve_linear_d(pccd_kind kind, const double *p_t0, const double *p_t1,
                                 const pccd_config *cfg, pccd_result *res) {
  return guard(__func__, [&] {
    require(res, "res");
    res->solved = false;  // unreadable until solved (require_solved); solve_linear resets r
    require(p_t0, "p_t0");
    require(p_t1, "p_t1");
    const long k = pccd::api::raw_kind(kind);
    const size_t n = pccd::api::linear_points(k);
    const pccd::api::Call_config call = pccd::api::read_call(cfg);
    pccd::api::check_finite(p_t0, n, "p_t0", nullptr);
    pccd::api::check_finite(p_t1, n, "p_t1", nullptr);
    pccd::api::check_double_bits(call.limits, p_t0, n, "p_t0", nullptr);
    pccd::api::check_double_bits(call.limits, p_t1, n, "p_t1", nullptr);
    std::optional<pccd::api::Call_budget> budget;  // none without limits: no per-call cost
    if (call.limits.work.any()) budget.emplace(call.limits.work);
    pccd::pred::solve_linear(static_cast<int>(k), n, p_t0, p_t1, *call.solve, res->r);
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
    const pccd::api::Call_config call = pccd::api::read_batch_call(cfg, opt);
    const long k = pccd::api::raw_kind(kind);
    const size_t np = pccd::api::linear_points(k);
    const pccd::api::Call_limits &limits = call.limits;
    if (n == 0) return PCCD_OK;
    require(t0, "t0");
    require(t1, "t1");
    const size_t chunks = (n + pccd::api::kChunk - 1) / pccd::api::kChunk;
    pccd::util::Thread_pool pool(static_cast<unsigned>(std::min<size_t>(call.threads, chunks)));
    // Every coordinate checked before any query is solved, on the pool: checking alone
    // took 8% of a 200k-query batch on one thread, a part that did not scale (issue 35).
    // The first bad chunk is checked again on this thread, so the error names the
    // first bad coordinate whatever the thread count.
    auto check_chunk = [&](size_t c) {
      const size_t end = std::min(n, (c + 1) * pccd::api::kChunk);
      for (size_t q = c * pccd::api::kChunk; q < end; ++q) {
        pccd::api::check_finite(t0 + 3 * np * q, np, "t0", &q);
        pccd::api::check_finite(t1 + 3 * np * q, np, "t1", &q);
        pccd::api::check_double_bits(limits, t0 + 3 * np * q, np, "t0", &q);
        pccd::api::check_double_bits(limits, t1 + 3 * np * q, np, "t1", &q);
      }
    };
    std::vector<unsigned char> bad(chunks, 0);
    pool.parallel_for(chunks, [&](size_t c) {
      try {
        check_chunk(c);
      } catch (...) {  // thrown again below, by the first bad chunk
        bad[c] = 1;
      }
    });
    const auto first_bad = std::find(bad.begin(), bad.end(), 1);
    if (first_bad != bad.end()) check_chunk(static_cast<size_t>(first_bad - bad.begin()));
    const pccd::api::Call_budget budget(limits.work);
    pool.parallel_for(chunks, [&](size_t c) {
      pccd::pred::Contact_result r;
      const size_t end = std::min(n, (c + 1) * pccd::api::kChunk);
      for (size_t q = c * pccd::api::kChunk; q < end; ++q) {
        pccd::pred::solve_linear(static_cast<int>(k), np, t0 + 3 * np * q, t1 + 3 * np * q,
                                 *call.solve, r);
        pccd::api::write(*out, q, r);
      }
    });
    return PCCD_OK;
  });
}

}  // extern "C"
