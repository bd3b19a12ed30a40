// The `batch` workload of bench_linear: pccd_solve_linear_batch_d (1 and 2 threads)
// against single pccd_solve_linear_d calls on the same sim queries, decide only.
//
// Compiled when tests/bench/bench.mk finds pccd_solve_linear_batch_d in polyccd.h
// (PCCD_HAVE_LINEAR_BATCH); otherwise the workload prints that it was skipped.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "bench_linear_report.h"
#include "polyccd.h"

namespace bench {

#ifdef PCCD_HAVE_LINEAR_BATCH
namespace {

using Clock = std::chrono::steady_clock;

int batch_call(pccd_kind kind, const std::vector<double> &t0, const std::vector<double> &t1,
               const pccd_config &cfg, unsigned threads, std::vector<int> &collides) {
  pccd_batch_options opt;
  pccd_batch_options_init(&opt);
  opt.threads = threads;
  std::vector<unsigned char> hit(collides.size());
  pccd_batch_out out{};
  out.struct_size = sizeof out;
  out.collides = hit.data();
  const int rc = pccd_solve_linear_batch_d(kind, collides.size(), t0.data(), t1.data(), &cfg, &opt, &out);
  for (std::size_t i = 0; i < hit.size(); ++i) collides[i] = rc == PCCD_OK ? hit[i] : -1;
  return rc;
}

double seconds_since(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

}  // namespace

void run_batch(const std::vector<Linear_query> &qs, int repeat, Json_writer &json) {
  std::printf("== workload batch: pccd_solve_linear_batch_d on the %zu sim queries, decide only "
              "(want_time = 0), whole-call wall time, min over %d round(s)\n",
              qs.size(), repeat);
  pccd_config cfg;
  pccd_result *res = nullptr;
  if (pccd_config_init(&cfg) != PCCD_OK || pccd_result_new(&res) != PCCD_OK) {
    std::printf("   setup failed: %s\n", pccd_last_error());
    return;
  }
  cfg.want_time = 0;
  json.open("batch", '{');
  json.num("available", 1);
  for (pccd_kind kind : {PCCD_VERTEX_FACE, PCCD_EDGE_EDGE}) {
    const char *kname = kind == PCCD_VERTEX_FACE ? "vertex-face" : "edge-edge";
    std::vector<double> t0, t1;
    for (const Linear_query &q : qs)
      if (q.kind == kind) t0.insert(t0.end(), q.t0, q.t0 + 12), t1.insert(t1.end(), q.t1, q.t1 + 12);
    std::size_t n = t0.size() / 12;
    if (n == 0) continue;
    std::vector<int> single(n), batch(n);
    double best_single = 1e300, best[3] = {1e300, 1e300, 1e300};
    int rc[3] = {PCCD_OK, PCCD_OK, PCCD_OK};
    std::size_t differ[3] = {};
    for (int r = 0; r < repeat; ++r) {
      Clock::time_point a = Clock::now();
      for (std::size_t i = 0; i < n; ++i) {
        int hit = -1;
        if (pccd_solve_linear_d(kind, &t0[12 * i], &t1[12 * i], &cfg, res) == PCCD_OK)
          pccd_result_collides(res, &hit);
        single[i] = hit;
      }
      best_single = std::min(best_single, seconds_since(a));
      for (unsigned threads : {1u, 2u}) {
        a = Clock::now();
        rc[threads] = batch_call(kind, t0, t1, cfg, threads, batch);
        best[threads] = std::min(best[threads], seconds_since(a));
        differ[threads] = 0;
        for (std::size_t i = 0; i < n; ++i) differ[threads] += batch[i] != single[i];
      }
    }
    double us = 1e6 / static_cast<double>(n);
    std::printf("   %s, %zu queries: single calls %.3f us/query", kname, n, best_single * us);
    json.open(kname, '{');
    json.num("single_us_per_query", best_single * us);
    for (unsigned threads : {1u, 2u}) {
      std::printf(", batch %u thread(s) %.3f us/query (%.2fx), rc %d, %zu answers differ", threads,
                  best[threads] * us, best_single / best[threads], rc[threads], differ[threads]);
      json.num(threads == 1 ? "batch1_us_per_query" : "batch2_us_per_query", best[threads] * us);
      json.num(threads == 1 ? "batch1_answers_differ" : "batch2_answers_differ", static_cast<double>(differ[threads]));
    }
    std::printf("\n");
    json.close('}');
  }
  json.close('}');
  pccd_result_free(res);
  std::printf("\n");
}

#else

void run_batch(const std::vector<Linear_query> &qs, int repeat, Json_writer &json) {
  (void)qs, (void)repeat;
  std::printf("== workload batch: skipped: polyccd.h does not declare pccd_solve_linear_batch_d "
              "(tests/bench/bench_linear_batch.cpp is the hook)\n\n");
  json.open("batch", '{');
  json.num("available", 0);
  json.close('}');
}

#endif

}  // namespace bench
