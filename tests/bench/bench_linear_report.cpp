// Reporting of bench_linear: statistics, stage counts, answer checks, machine info, JSON.
#include "bench_linear_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

#include <tight_inclusion/config.hpp>

#include "polyccd.h"

namespace bench {

const char *method_name(int m) {
  static const char *const names[kMethods] = {"TI", "polyccd-decide", "polyccd-time"};
  return names[m];
}

// ---- JSON ----

void Json_writer::sep(const char *key) {
  if (!first_.back()) s_ += ",";
  first_.back() = false;
  if (key != nullptr) {
    s_ += "\n\"";
    s_ += key;
    s_ += "\": ";
  }
}

void Json_writer::open(const char *key, char bracket) {
  sep(key);
  s_ += bracket;
  first_.push_back(true);
}

void Json_writer::close(char bracket) {
  s_ += bracket;
  first_.pop_back();
}

void Json_writer::num(const char *key, double v) {
  sep(key);
  char buf[32];
  if (std::isfinite(v))
    std::snprintf(buf, sizeof buf, "%.6g", v);
  else
    std::snprintf(buf, sizeof buf, "null");
  s_ += buf;
}

void Json_writer::str(const char *key, const std::string &v) {
  sep(key);
  s_ += '"';
  for (char c : v) {
    if (c == '"' || c == '\\') s_ += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) s_ += c;
  }
  s_ += '"';
}

bool Json_writer::write(const std::string &path) const {
  std::ofstream f(path);
  f << s_ << "}\n";
  return static_cast<bool>(f);
}

// ---- machine ----

namespace {

std::string first_line_with(const char *file, const char *prefix) {
  std::ifstream f(file);
  for (std::string line; std::getline(f, line);)
    if (line.rfind(prefix, 0) == 0) {
      std::size_t c = line.find(':');
      return c == std::string::npos ? line : line.substr(line.find_first_not_of(" \t", c + 1));
    }
  return "unknown";
}

std::string loadavg() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a + " " + b + " " + c;
}

}  // namespace

void print_load(const char *when) {
  std::printf("load average (%s): %s (1, 5, 15 min)\n", when, loadavg().c_str());
}

void print_machine(Json_writer &json, int repeat, std::size_t warmup) {
  char date[32];
  std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  std::string cpu = first_line_with("/proc/cpuinfo", "model name");
  unsigned cores = std::thread::hardware_concurrency();
  std::printf("bench_linear  %s\n", date);
  std::printf("cpu       %s, %u hardware threads\n", cpu.c_str(), cores);
  std::printf("compiler  g++ %s (this program and Tight Inclusion: -O3 -march=native -DNDEBUG)\n", __VERSION__);
  std::printf("polyccd   %s (C API, shared library)\n", pccd_version());
  std::printf("TI        Tight Inclusion %s (tolerance 1e-6, err -1, ms 0, max_itr 1e6, BFS)\n",
              TIGHT_INCLUSION_VER);
  std::printf("timing    steady_clock around each call; min over %d round(s), method order "
              "rotated per round; untimed warm-up of %zu queries per method\n",
              repeat, warmup);
  print_load("start");
  std::printf("\n");
  json.open("machine", '{');
  json.str("date", date);
  json.str("cpu", cpu);
  json.num("hardware_threads", cores);
  json.str("compiler", std::string("g++ ") + __VERSION__);
  json.str("polyccd", pccd_version());
  json.str("tight_inclusion", TIGHT_INCLUSION_VER);
  json.str("loadavg_start", loadavg());
  json.num("repeat", repeat);
  json.num("warmup", static_cast<double>(warmup));
  json.close('}');
}

// ---- one workload ----

namespace {

struct Stats {
  double median = NAN, mean = NAN, p99 = NAN, max = NAN;  // microseconds
};

Stats stats_of(const std::vector<double> &ns, const std::vector<std::size_t> &idx) {
  Stats s;
  if (idx.empty()) return s;
  std::vector<double> v;
  v.reserve(idx.size());
  for (std::size_t i : idx) v.push_back(ns[i] * 1e-3);
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  double sum = 0;
  for (double x : v) sum += x;
  s.mean = sum / static_cast<double>(n);
  s.p99 = v[std::min(n - 1, static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(n))) - 1)];
  s.max = v.back();
  return s;
}

const char *const kStageNames[5] = {"none", "bounds", "bernstein", "interval", "exact"};

void print_query(const Linear_query &q) {
  const char *pts = q.kind == PCCD_VERTEX_FACE ? "v f0 f1 f2" : "a0 a1 b0 b1";
  std::printf("        %s (%s; %s)\n", q.label.c_str(), q.kind == PCCD_VERTEX_FACE ? "vertex-face" : "edge-edge", pts);
  for (int t = 0; t < 2; ++t) {
    const double *p = t == 0 ? q.t0 : q.t1;
    std::printf("        t%d:", t);
    for (int k = 0; k < 4; ++k) std::printf(" (%.17g, %.17g, %.17g)", p[3 * k], p[3 * k + 1], p[3 * k + 2]);
    std::printf("\n");
  }
}

// Counts of one answer comparison over idx: "a says yes, b says no" and the reverse.
struct Mismatch {
  std::size_t yes_no = 0, no_yes = 0, errors = 0;
  std::vector<std::size_t> first;
};

Mismatch compare(const std::vector<int> &a, const std::vector<int> &b, const std::vector<std::size_t> &idx,
                 std::size_t keep) {
  Mismatch m;
  for (std::size_t i : idx) {
    if (a[i] < 0 || b[i] < 0) {
      ++m.errors;
      continue;
    }
    if (a[i] == b[i]) continue;
    (a[i] == 1 ? m.yes_no : m.no_yes) += 1;
    if (m.first.size() < keep) m.first.push_back(i);
  }
  return m;
}

void report_kind(const char *kind, const std::vector<std::size_t> &idx, const std::vector<Linear_query> &qs,
                 const std::array<Method_run, kMethods> &runs, std::size_t examples, Json_writer &json) {
  const std::vector<int> &exact = runs[DECIDE].answer;
  std::size_t colliding = 0, truth_known = 0, truth_yes = 0;
  for (std::size_t i : idx) {
    colliding += exact[i] == 1;
    truth_known += qs[i].truth >= 0;
    truth_yes += qs[i].truth == 1;
  }
  std::printf("   -- %s: %zu queries, %zu colliding by polyccd (%.2f %%)", kind, idx.size(), colliding,
              idx.empty() ? 0.0 : 100.0 * static_cast<double>(colliding) / static_cast<double>(idx.size()));
  if (truth_known) std::printf(", %zu by the truth column", truth_yes);
  std::printf("\n      %-15s %10s %10s %10s %10s\n", "method", "median us", "mean us", "p99 us", "max us");
  json.open(nullptr, '{');
  json.str("kind", kind);
  json.num("queries", static_cast<double>(idx.size()));
  json.num("colliding_polyccd", static_cast<double>(colliding));
  if (truth_known) json.num("colliding_truth", static_cast<double>(truth_yes));
  std::array<Stats, kMethods> st;
  json.open("times_us", '{');
  for (int m = 0; m < kMethods; ++m) {
    st[m] = stats_of(runs[m].ns, idx);
    std::printf("      %-15s %10.3f %10.3f %10.3f %10.1f\n", method_name(m), st[m].median, st[m].mean, st[m].p99,
                st[m].max);
    json.open(method_name(m), '{');
    json.num("median", st[m].median), json.num("mean", st[m].mean), json.num("p99", st[m].p99);
    json.num("max", st[m].max);
    json.close('}');
  }
  json.close('}');
  // TI skipped (bench_linear --ti 0): its times are all 0; no ratios, no TI answers.
  const bool have_ti = st[TI].max > 0;
  json.open("ratio_to_ti", '{');
  for (int m : {DECIDE, TIME}) {
    if (!have_ti) break;
    double rmed = st[m].median / st[TI].median, rmean = st[m].mean / st[TI].mean;
    std::printf("      %s/TI: median %.3gx, mean %.3gx\n", method_name(m), rmed, rmean);
    json.open(method_name(m), '{');
    json.num("median", rmed), json.num("mean", rmean);
    json.close('}');
  }
  json.close('}');
  json.open("stages", '{');
  for (int m : {DECIDE, TIME}) {
    std::size_t count[5] = {};
    double ns[5] = {};
    for (std::size_t i : idx) {
      int s = std::min(4, std::max(0, runs[m].stage[i]));
      ++count[s], ns[s] += runs[m].ns[i];
    }
    std::printf("      stages %-14s", method_name(m));
    json.open(method_name(m), '{');
    for (int s = 1; s <= 4; ++s) {
      std::printf(" %s %zu", kStageNames[s], count[s]);
      if (count[s]) std::printf(" (mean %.2f us)", ns[s] * 1e-3 / static_cast<double>(count[s]));
      if (s < 4) std::printf(",");
      json.num(kStageNames[s], static_cast<double>(count[s]));
    }
    if (count[0]) std::printf(", no stage (failed call) %zu", count[0]);
    std::printf("\n");
    json.close('}');
  }
  json.close('}');

  // answers
  Mismatch dt = compare(runs[DECIDE].answer, runs[TIME].answer, idx, examples);
  Mismatch ti = compare(runs[TI].answer, exact, idx, have_ti ? examples : 0);
  std::printf("      answers: polyccd-decide vs polyccd-time: %zu disagreements (%zu failed calls)\n",
              dt.yes_no + dt.no_yes, dt.errors);
  if (have_ti)
    std::printf("      answers: TI vs polyccd (exact): %zu false positives, %zu false negatives\n", ti.yes_no,
                ti.no_yes);
  json.open("answers", '{');
  json.num("decide_vs_time_disagreements", static_cast<double>(dt.yes_no + dt.no_yes));
  json.num("failed_calls", static_cast<double>(dt.errors));
  json.num("ti_false_positives", static_cast<double>(ti.yes_no));
  json.num("ti_false_negatives", static_cast<double>(ti.no_yes));
  std::vector<int> truth(qs.size(), -1);
  for (std::size_t i : idx) truth[i] = qs[i].truth;
  if (truth_known) {
    std::printf("      answers vs the truth column (false pos / false neg):");
    json.open("vs_truth", '{');
    for (int m = have_ti ? 0 : 1; m < kMethods; ++m) {
      Mismatch t = compare(runs[m].answer, truth, idx, 0);
      std::printf(" %s %zu / %zu%s", method_name(m), t.yes_no, t.no_yes, m + 1 < kMethods ? "," : "\n");
      json.open(method_name(m), '{');
      json.num("false_positives", static_cast<double>(t.yes_no));
      json.num("false_negatives", static_cast<double>(t.no_yes));
      json.close('}');
    }
    json.close('}');
  }
  // contact times where both collide: TI's toi is meant to be a lower bound of t*
  double lo = INFINITY, hi = -INFINITY;
  std::size_t both = 0;
  for (std::size_t i : idx)
    if (runs[TI].answer[i] == 1 && runs[TIME].answer[i] == 1) {
      double d = runs[TI].toi[i] - runs[TIME].toi[i];
      lo = std::min(lo, d), hi = std::max(hi, d), ++both;
    }
  if (both)
    std::printf("      contact time, TI toi - polyccd t (enclosure midpoint) over %zu common hits: min %.3g, max %.3g\n",
                both, lo, hi);
  json.num("toi_diff_min", both ? lo : NAN);
  json.num("toi_diff_max", both ? hi : NAN);
  json.close('}');
  json.close('}');
  for (std::size_t i : dt.first) {
    std::printf("      decide %d, time %d:\n", runs[DECIDE].answer[i], runs[TIME].answer[i]);
    print_query(qs[i]);
  }
  for (std::size_t i : ti.first) {
    std::printf("      TI %d, polyccd %d (stage %s), TI toi %.17g:\n", runs[TI].answer[i], exact[i],
                kStageNames[std::min(4, std::max(0, runs[DECIDE].stage[i]))], runs[TI].toi[i]);
    print_query(qs[i]);
  }
}

}  // namespace

void report_workload(const std::vector<Linear_query> &qs,
                     const std::array<Method_run, kMethods> &runs, std::size_t examples, Json_writer &json) {
  std::vector<std::size_t> vf, ee, all;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    (qs[i].kind == PCCD_VERTEX_FACE ? vf : ee).push_back(i);
    all.push_back(i);
  }
  // generated queries: how many of each generator case collide (label "sim #i (case)")
  std::vector<std::pair<std::string, std::array<std::size_t, 2>>> cases;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    std::size_t a = qs[i].label.find('('), b = qs[i].label.rfind(')');
    if (qs[i].truth >= 0 || a == std::string::npos || b == std::string::npos || b < a) continue;
    std::string c = qs[i].label.substr(a + 1, b - a - 1);
    auto it = std::find_if(cases.begin(), cases.end(), [&](const auto &e) { return e.first == c; });
    if (it == cases.end()) it = cases.insert(cases.end(), {c, {0, 0}});
    ++it->second[0], it->second[1] += runs[DECIDE].answer[i] == 1;
  }
  if (!cases.empty()) {
    std::printf("   generator cases (colliding by polyccd / queries):");
    json.open("generator_cases", '{');
    for (const auto &e : cases) {
      std::printf(" %s %zu / %zu;", e.first.c_str(), e.second[1], e.second[0]);
      json.open(e.first.c_str(), '{');
      json.num("queries", static_cast<double>(e.second[0]));
      json.num("colliding", static_cast<double>(e.second[1]));
      json.close('}');
    }
    std::printf("\n");
    json.close('}');
  }
  json.open("kinds", '[');
  report_kind("vertex-face", vf, qs, runs, examples, json);
  report_kind("edge-edge", ee, qs, runs, examples, json);
  report_kind("all", all, qs, runs, 0, json);
  json.close(']');
}

}  // namespace bench
