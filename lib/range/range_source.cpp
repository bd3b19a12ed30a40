#include "range/range_source.h"

#include "range/range_index.h"

namespace pccd::range {

namespace {

size_t n_elements(const Moving_body &b) {
  return b.is_mesh() ? b.mesh->triangles().size() : b.spheres->centers().size();
}

class Range_source final : public narrow::Candidate_source {
 public:
  Range_source(const Pair_ctx &ctx, int stored) : index_(ctx, stored) {}

  // The triangle pairs whose boxes meet at t = 0 (a search of the stored triangles' tree).
  std::vector<Prim_pair> static_candidates(Thread_pool &pool) override {
    return index_.static_candidates(pool);
  }

  void run(narrow::Candidate_sink &sink, narrow::Search_stats &stats, Thread_pool &pool) override {
    const int n = index_.pieces();
    for (int k = 0; k < n; ++k) {
      const double a = double(k) / n, b = double(k + 1) / n;  // exact: n is a power of 2
      if (sink.pruned(a)) break;
      ++stats.pieces;
      std::vector<Prim_pair> cand = index_.candidates(a, b, pool);
      if (cand.empty()) continue;
      ++stats.leaves;
      stats.candidates += cand.size();
      sink.piece(a, b, std::move(cand));
    }
  }

 private:
  Range_index index_;
};

}  // namespace

std::unique_ptr<narrow::Candidate_source> range_source(const Pair_ctx &ctx, int stored) {
  if (stored < 0) stored = n_elements(ctx.side(0)) >= n_elements(ctx.side(1)) ? 0 : 1;
  return std::make_unique<Range_source>(ctx, stored);
}

}  // namespace pccd::range
