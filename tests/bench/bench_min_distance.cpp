// bench_min_distance: minimum-separation CCD of polyccd (pccd_config.min_distance) against
// Tight Inclusion's minimum_distance (`ms`), in one process, on the public query set.
//
// For each delta (--deltas, default 2^-20 and 2^-10: exact doubles, so both libraries get
// the same number), every public query is solved by
//   TI        ticcd::vertexFaceCCD / edgeEdgeCCD with ms = delta, err (-1, -1, -1),
//             tolerance 1e-6, t_max 1, max_itr 1e6, BREADTH_FIRST_SEARCH (as bench_linear)
//   polyccd   pccd_solve_linear_d with min_distance = delta, time_tolerance 1e-6
// and compared (the rules: TI must never report later than the exact first time;
// where TI reports a contact polyccd does not, polyccd's exact "no time within delta"
// shows TI conservative):
//   both          both report a contact; "TI later" counts TI's toi > polyccd's hi
//   TI only       TI reports a contact at delta, polyccd proves none
//   polyccd only  polyccd finds a time within delta and TI misses it (a TI false negative)
// plus the median / mean microseconds per call. A benchmark: it never asserts; exit 2 only
// for bad input or a failed library call.
//
// Usage: bench_min_distance [--deltas D1,D2,...] [--root DIR]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gmp.h>
#include <tight_inclusion/ccd.hpp>

#include "bench_linear_input.h"
#include "polyccd.h"

namespace {

using Clock = std::chrono::steady_clock;

double us_since(Clock::time_point a) {
  return std::chrono::duration<double, std::micro>(Clock::now() - a).count();
}

struct Stats {
  std::vector<double> us;
  double median() {
    std::sort(us.begin(), us.end());
    return us.empty() ? 0 : us[us.size() / 2];
  }
  double mean() const {
    double s = 0;
    for (double x : us) s += x;
    return us.empty() ? 0 : s / us.size();
  }
};

bool ti_call(const bench::Linear_query &q, double ms, double *toi) {
  ticcd::Vector3 p[8];
  for (int k = 0; k < 4; ++k) {
    p[k] = ticcd::Vector3(q.t0[3 * k], q.t0[3 * k + 1], q.t0[3 * k + 2]);
    p[4 + k] = ticcd::Vector3(q.t1[3 * k], q.t1[3 * k + 1], q.t1[3 * k + 2]);
  }
  const ticcd::Array3 err(-1, -1, -1);
  double out_tol = 0;
  if (q.kind == PCCD_VERTEX_FACE)
    return ticcd::vertexFaceCCD(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], err, ms, *toi, 1e-6,
                                1, 1000000, out_tol, false,
                                ticcd::CCDRootFindingMethod::BREADTH_FIRST_SEARCH);
  return ticcd::edgeEdgeCCD(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], err, ms, *toi, 1e-6, 1,
                            1000000, out_tol, false, ticcd::CCDRootFindingMethod::BREADTH_FIRST_SEARCH);
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<double> deltas{std::ldexp(1.0, -20), std::ldexp(1.0, -10)};
  const char *env = std::getenv("POLYCCD_QUERY_DIR");
  std::string root = env ? env : "../shared/data/ccd-queries";
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--root" && i + 1 < argc) {
      root = argv[++i];
    } else if (a == "--deltas" && i + 1 < argc) {
      deltas.clear();
      std::string list = argv[++i];
      for (std::size_t at = 0; at <= list.size();) {
        std::size_t comma = list.find(',', at);
        if (comma == std::string::npos) comma = list.size();
        deltas.push_back(std::strtod(list.substr(at, comma - at).c_str(), nullptr));
        at = comma + 1;
      }
    } else {
      std::fprintf(stderr, "usage: bench_min_distance [--deltas D1,D2,...] [--root DIR]\n");
      return 2;
    }
  }
  const std::vector<bench::Linear_query> qs = bench::read_query_csvs(root);
  std::printf("bench_min_distance: %zu public queries from %s\n", qs.size(), root.c_str());
  pccd_result *res = nullptr;
  if (pccd_result_new(&res) != PCCD_OK) return 2;
  for (double delta : deltas) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", delta);  // exact for the powers of two used
    pccd_config cfg;
    pccd_config_init(&cfg);
    cfg.min_distance = text;
    cfg.time_tolerance = "1e-6";
    Stats ti_us, pc_us;
    long both = 0, ti_later = 0, ti_only = 0, pc_only = 0, neither = 0;
    for (const bench::Linear_query &q : qs) {
      double toi = 0;
      Clock::time_point a = Clock::now();
      const bool ti = ti_call(q, delta, &toi);
      ti_us.us.push_back(us_since(a));
      a = Clock::now();
      int hit = 0;
      if (pccd_solve_linear_d(q.kind, q.t0, q.t1, &cfg, res) != PCCD_OK ||
          pccd_result_collides(res, &hit) != PCCD_OK) {
        std::fprintf(stderr, "%s: %s\n", q.label.c_str(), pccd_last_error());
        return 2;
      }
      pc_us.us.push_back(us_since(a));
      if (hit && ti) {
        ++both;
        std::size_t need = 0;
        pccd_result_time(res, 1, nullptr, 0, &need);
        std::string hi(need, '\0');
        if (pccd_result_time(res, 1, &hi[0], need, nullptr) == PCCD_OK) {
          // exactly: TI's toi (a double) above polyccd's hi is later than the first time
          mpq_t h, t;
          mpq_init(h);
          mpq_init(t);
          mpq_set_str(h, hi.c_str(), 10);
          mpq_canonicalize(h);
          mpq_set_d(t, toi);
          if (mpq_cmp(t, h) > 0) ++ti_later;
          mpq_clear(h);
          mpq_clear(t);
        }
      } else if (ti) {
        ++ti_only;
      } else if (hit) {
        ++pc_only;
      } else {
        ++neither;
      }
    }
    std::printf("\ndelta = %s\n", text);
    std::printf("  contacts: both %ld (TI later than polyccd: %ld), TI only %ld (TI conservative: "
                "polyccd proves no time within delta), polyccd only %ld (TI misses), neither %ld\n",
                both, ti_later, ti_only, pc_only, neither);
    std::printf("  us per query: TI median %.3f mean %.3f | polyccd median %.3f mean %.3f | "
                "mean ratio polyccd/TI %.3fx\n",
                ti_us.median(), ti_us.mean(), pc_us.median(), pc_us.mean(),
                pc_us.mean() / ti_us.mean());
  }
  pccd_result_free(res);
  return 0;
}
