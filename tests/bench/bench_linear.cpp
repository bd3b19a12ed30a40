// bench_linear: polyccd's C API against Tight Inclusion's C++ (issue 11, "the benchmark
// that keeps us honest"), in ONE process, on the same prepared inputs.
//
// Methods (each query is one call; the kind is dispatched before the clock starts):
//   TI              ticcd::vertexFaceCCD / edgeEdgeCCD as ipctk calls them: err =
//                   (-1, -1, -1), ms = 0, tolerance 1e-6, t_max 1, max_itr 1e6,
//                   no_zero_toi = false, BREADTH_FIRST_SEARCH (Tight Inclusion 1.0.4
//                   from ../shared/peers/tight-inclusion, built -O3 -march=native -DNDEBUG)
//   polyccd-decide  pccd_solve_linear_d with pccd_config_init + want_time = 0, then
//                   pccd_result_collides
//   polyccd-time    the same with want_time = 1, time_tolerance = "1e-6" (default exactness)
// polyccd is called only through polyccd.h and the shared library, with one pccd_result
// reused. Rounds (--repeat, default 3) run every method over all queries, the method
// order rotated each round, after an untimed warm-up (--warmup queries per method);
// each call is timed alone with std::chrono::steady_clock and a query's time is its
// minimum over the rounds. Answers and stages are those of the first round.
//
// Workloads (--workloads, default sim,public,batch):
//   sim     the seeded simulation-like generator of bench_linear_input.cpp (--seed,
//           --n, default 200,000: half vertex-face, half edge-edge, about 4 % colliding)
//   public  every CSV under $POLYCCD_QUERY_DIR (default ../shared/data/ccd-queries),
//           read exactly, with its truth column
//   batch   pccd_solve_linear_batch_d with 1 and 2 threads against single calls, on the
//           sim queries; compiled only when the header declares it (bench_linear_batch.h)
//
// Output per workload and kind (vertex-face, edge-edge, all): median / mean / p99 in
// microseconds per method, the polyccd/TI ratios, the stages that decided the queries,
// answer checks (decide vs time must agree; TI against polyccd's exact answer; every
// method against the truth column when there is one) and the first disagreements with
// their exact coordinates. --json FILE writes the numbers. A benchmark: it never asserts
// on speed or on answers; exit status 2 only for bad input or a failed library call setup.
//
// Usage: bench_linear [--workloads LIST] [--seed S] [--n N] [--repeat R] [--warmup W]
//                     [--json FILE] [--examples K] [--ti 0|1]
// --ti 0 skips Tight Inclusion (its rows read 0): the polyccd-only runs of the tail
// comparisons (docs/benchmarks-tail.md), where TI's seconds-long queries only add noise.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <tight_inclusion/ccd.hpp>

#include "bench_linear_input.h"
#include "bench_linear_report.h"
#include "bench_linear_tail.h"
#include "polyccd.h"

namespace bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> workloads{"sim", "public", "batch"};
  std::uint64_t seed = 1;
  std::size_t n = 200000;
  int repeat = 3;
  std::size_t warmup = 1000;
  std::size_t examples = 3;
  bool ti = true;  // --ti 0: skip Tight Inclusion (its rows then read 0; for polyccd-only runs)
  std::string json;
};

[[noreturn]] void usage(const char *msg) {
  std::fprintf(stderr,
               "bench_linear: %s\nusage: bench_linear [--workloads sim,public,batch] [--seed S] "
               "[--n N] [--repeat R] [--warmup W] [--examples K] [--json FILE] [--ti 0|1]\n",
               msg);
  std::exit(2);
}

Options parse_options(int argc, char **argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (i + 1 >= argc) usage(("missing value after " + a).c_str());
    std::string v = argv[++i];
    char *end = nullptr;
    unsigned long long num = std::strtoull(v.c_str(), &end, 10);
    bool is_num = !v.empty() && *end == '\0';
    if (a == "--workloads") {
      o.workloads.clear();
      for (std::size_t p = 0, q; p <= v.size(); p = q + 1) {
        q = v.find(',', p);
        if (q == std::string::npos) q = v.size();
        std::string w = v.substr(p, q - p);
        if (w != "sim" && w != "public" && w != "batch") usage(("unknown workload " + w).c_str());
        o.workloads.push_back(w);
      }
    } else if (a == "--json") {
      o.json = v;
    } else if (!is_num) {
      usage((a + " needs a non-negative integer, got " + v).c_str());
    } else if (a == "--seed") {
      o.seed = num;
    } else if (a == "--n") {
      o.n = num;
    } else if (a == "--repeat") {
      o.repeat = static_cast<int>(std::max(1ULL, num));
    } else if (a == "--warmup") {
      o.warmup = num;
    } else if (a == "--ti") {
      o.ti = num != 0;
    } else if (a == "--examples") {
      o.examples = num;
    } else {
      usage(("unknown option " + a).c_str());
    }
  }
  return o;
}

bool wants(const Options &o, const char *w) {
  return std::find(o.workloads.begin(), o.workloads.end(), w) != o.workloads.end();
}

// The prepared input of Tight Inclusion: its 8 points as Eigen vectors (t0 rows, t1 rows).
using Ti_points = std::array<ticcd::Vector3, 8>;

std::vector<Ti_points> ti_points(const std::vector<Linear_query> &qs) {
  std::vector<Ti_points> out(qs.size());
  for (std::size_t i = 0; i < qs.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      out[i][k] = ticcd::Vector3(qs[i].t0[3 * k], qs[i].t0[3 * k + 1], qs[i].t0[3 * k + 2]);
      out[i][4 + k] = ticcd::Vector3(qs[i].t1[3 * k], qs[i].t1[3 * k + 1], qs[i].t1[3 * k + 2]);
    }
  return out;
}

double elapsed_ns(Clock::time_point a, Clock::time_point b) {
  return static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(b - a).count());
}

// One timed call of Tight Inclusion; *toi receives its time of impact.
bool ti_call(const Linear_query &q, const Ti_points &p, double *ns, double *toi) {
  const ticcd::Array3 err(-1, -1, -1);
  const double ms = 0, tolerance = 1e-6, t_max = 1;
  const long max_itr = 1000000;
  double out_tol = 0;
  bool hit;
  if (q.kind == PCCD_VERTEX_FACE) {
    Clock::time_point a = Clock::now();
    hit = ticcd::vertexFaceCCD(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], err, ms, *toi,
                               tolerance, t_max, max_itr, out_tol, false,
                               ticcd::CCDRootFindingMethod::BREADTH_FIRST_SEARCH);
    *ns = elapsed_ns(a, Clock::now());
  } else {
    Clock::time_point a = Clock::now();
    hit = ticcd::edgeEdgeCCD(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], err, ms, *toi,
                             tolerance, t_max, max_itr, out_tol, false,
                             ticcd::CCDRootFindingMethod::BREADTH_FIRST_SEARCH);
    *ns = elapsed_ns(a, Clock::now());
  }
  return hit;
}

// One timed polyccd call (solve + collides); returns 1 / 0, or -1 after a failed call.
int pccd_call(const Linear_query &q, const pccd_config &cfg, pccd_result *res, double *ns) {
  int hit = 0;
  Clock::time_point a = Clock::now();
  int rc = pccd_solve_linear_d(q.kind, q.t0, q.t1, &cfg, res);
  if (rc == PCCD_OK) rc = pccd_result_collides(res, &hit);
  *ns = elapsed_ns(a, Clock::now());
  return rc == PCCD_OK ? hit : -1;
}

struct Runner {
  const std::vector<Linear_query> &qs;
  std::vector<Ti_points> ti;
  pccd_config decide{}, time{};
  pccd_result *res = nullptr;
  std::vector<std::string> first_errors;

  explicit Runner(const std::vector<Linear_query> &queries) : qs(queries), ti(ti_points(queries)) {
    if (pccd_config_init(&decide) != PCCD_OK || pccd_config_init(&time) != PCCD_OK ||
        pccd_result_new(&res) != PCCD_OK) {
      std::fprintf(stderr, "bench_linear: %s\n", pccd_last_error());
      std::exit(2);
    }
    decide.want_time = 0;
    time.want_time = 1;
    time.time_tolerance = "1e-6";
  }
  ~Runner() { pccd_result_free(res); }
  Runner(const Runner &) = delete;
  Runner &operator=(const Runner &) = delete;

  // Runs method m over queries [0, count); fills r (times as minima) when r != nullptr.
  void round(int m, std::size_t count, Method_run *r, bool first) {
    for (std::size_t i = 0; i < count; ++i) {
      double ns = 0;
      int answer, stage = 0;
      double t = -1;
      if (m == TI) {
        answer = ti_call(qs[i], ti[i], &ns, &t) ? 1 : 0;
      } else {
        answer = pccd_call(qs[i], m == DECIDE ? decide : time, res, &ns);
        if (answer < 0 && first_errors.size() < 5)
          first_errors.push_back(std::string(method_name(m)) + " " + qs[i].label + ": " + pccd_last_error());
        if (answer >= 0) pccd_result_stage(res, &stage);
        if (answer == 1 && m == TIME) pccd_result_time_approx(res, &t);
      }
      if (r == nullptr) continue;
      if (first) {
        r->ns[i] = ns, r->answer[i] = answer, r->stage[i] = stage, r->toi[i] = t;
      } else {
        r->ns[i] = std::min(r->ns[i], ns);
      }
    }
  }

  std::array<Method_run, kMethods> run(const Options &o) {
    std::array<Method_run, kMethods> runs;
    for (Method_run &r : runs) r.resize(qs.size());
    for (int m = 0; m < kMethods; ++m)
      if (m != TI || o.ti) round(m, std::min(o.warmup, qs.size()), nullptr, false);
    for (int rd = 0; rd < o.repeat; ++rd)
      for (int j = 0; j < kMethods; ++j) {
        int m = (j + rd) % kMethods;  // rotate the order of the methods every round
        if (m == TI && !o.ti) continue;
        round(m, qs.size(), &runs[m], rd == 0);
      }
    return runs;
  }
};

void run_workload(const Options &o, const char *name, const std::vector<Linear_query> &qs,
                  const std::string &note, Json_writer &json) {
  std::printf("== workload %s: %zu queries%s\n", name, qs.size(), note.c_str());
  Runner runner(qs);
  Clock::time_point a = Clock::now();
  std::array<Method_run, kMethods> runs = runner.run(o);
  double secs = elapsed_ns(a, Clock::now()) * 1e-9;
  std::printf("   (%d round(s) of 3 methods in %.1f s)\n", o.repeat, secs);
  report_workload(qs, runs, o.examples, json);
  report_tail(qs, runs, json);
  for (const std::string &e : runner.first_errors) std::printf("   error: %s\n", e.c_str());
  std::printf("\n");
}

}  // namespace
}  // namespace bench

int main(int argc, char **argv) {
  using namespace bench;
  Options o = parse_options(argc, argv);
  Json_writer json;
  print_machine(json, o.repeat, o.warmup);
  std::vector<Linear_query> sim;
  if (wants(o, "sim") || wants(o, "batch")) sim = make_sim_queries(o.seed, o.n);
  json.open("workloads", '[');
  if (wants(o, "sim")) {
    char note[96];
    std::snprintf(note, sizeof note, " (generator seed %llu, --n %zu)",
                  static_cast<unsigned long long>(o.seed), o.n);
    json.open(nullptr, '{');
    json.str("name", "sim");
    json.num("seed", static_cast<double>(o.seed));
    run_workload(o, "sim", sim, note, json);
    json.close('}');
  }
  if (wants(o, "public")) {
    const char *env = std::getenv("POLYCCD_QUERY_DIR");
    std::string root = env && *env ? env : "../shared/data/ccd-queries";
    std::vector<Linear_query> pub = read_query_csvs(root);
    json.open(nullptr, '{');
    json.str("name", "public");
    json.str("root", root);
    run_workload(o, "public", pub, " from " + root + " (every coordinate an exact double)", json);
    json.close('}');
  }
  json.close(']');
  if (wants(o, "batch")) run_batch(sim, o.repeat, json);
  print_load("end");
  if (!o.json.empty() && !json.write(o.json)) {
    std::fprintf(stderr, "bench_linear: cannot write %s\n", o.json.c_str());
    return 2;
  }
  return 0;
}
