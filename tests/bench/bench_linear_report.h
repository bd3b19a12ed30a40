// What bench_linear measured and how it prints it (text on stdout, --json FILE).
#ifndef PCCD_BENCH_LINEAR_REPORT_H
#define PCCD_BENCH_LINEAR_REPORT_H

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bench_linear_input.h"

namespace bench {

enum Method { TI = 0, DECIDE = 1, TIME = 2 };
constexpr int kMethods = 3;
const char *method_name(int m);  // "TI", "polyccd-decide", "polyccd-time"

// One method over one workload: per query its time (ns, minimum over rounds) and, from
// the first round, its answer (1 / 0, -1 for a failed call), the polyccd stage
// (pccd_stage; 0 for TI) and a contact time (TI's toi; polyccd-time's
// pccd_result_time_approx when it collides; else -1).
struct Method_run {
  std::vector<double> ns;
  std::vector<int> answer, stage;
  std::vector<double> toi;
  void resize(std::size_t n) { ns.assign(n, 0), answer.assign(n, 0), stage.assign(n, 0), toi.assign(n, -1); }
};

// A small JSON writer: nested objects and arrays of numbers and strings.
class Json_writer {
 public:
  Json_writer() : s_("{"), first_{true} {}
  void open(const char *key, char bracket);  // key == nullptr inside an array
  void close(char bracket);
  void num(const char *key, double v);
  void str(const char *key, const std::string &v);
  bool write(const std::string &path) const;

 private:
  void sep(const char *key);
  std::string s_;
  std::vector<bool> first_;
};

// The machine, compiler, versions, load average and timing setup (stdout and json).
void print_machine(Json_writer &json, int repeat, std::size_t warmup);
void print_load(const char *when);

// The tables of one workload: per kind (vertex-face, edge-edge, all) the times, the
// polyccd/TI ratios, the stages and the answer checks; `examples` disagreements shown.
void report_workload(const std::vector<Linear_query> &qs,
                     const std::array<Method_run, kMethods> &runs, std::size_t examples,
                     Json_writer &json);

// The batch workload (bench_linear_batch.cpp): times pccd_solve_linear_batch_d when
// polyccd.h declares it, else prints that it was skipped.
void run_batch(const std::vector<Linear_query> &qs, int repeat, Json_writer &json);

}  // namespace bench

#endif
