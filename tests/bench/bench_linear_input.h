// The workloads of bench_linear (tests/bench/bench_linear.cpp): linear vertex-face and
// edge-edge queries as exact doubles, from a seeded simulation-like generator or from the
// public query CSVs. Nothing here is timed. See bench_linear_input.cpp for the generator.
#ifndef PCCD_BENCH_LINEAR_INPUT_H
#define PCCD_BENCH_LINEAR_INPUT_H

#include <cstdint>
#include <string>
#include <vector>

#include "polyccd.h"

namespace bench {

// One linear query: 4 points (pccd point order of `kind`) at t = 0 and at t = 1.
struct Linear_query {
  pccd_kind kind = PCCD_VERTEX_FACE;
  double t0[12] = {};
  double t1[12] = {};
  int truth = -1;     // the CSV truth column (0 / 1); -1 for generated queries
  std::string label;  // where it comes from: "sim #17 (miss: beside)", "scene/kind/file.csv #3"
};

// The simulation-like workload: n queries from std::mt19937_64(seed), alternating
// vertex-face (even index) and edge-edge (odd index). Deterministic for (seed, n).
std::vector<Linear_query> make_sim_queries(std::uint64_t seed, std::size_t n);

// Every *.csv under root (sorted by path), the folder holding each file named
// vertex-face or edge-edge. Every coordinate num/den must be exactly a double (den a
// power of two): the reader exits with a message naming file, row and column otherwise.
std::vector<Linear_query> read_query_csvs(const std::string &root);

}  // namespace bench

#endif
