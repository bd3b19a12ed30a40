// The brute-force candidate source: every feature pair, no filter (PCCD_BROAD_BRUTE, the
// reference the other sources are tested against).
#include "narrow/candidate_source.h"

#include <cmath>

namespace pccd::narrow {

void Search_stats::add(const Search_stats &o) {
  pieces += o.pieces;
  leaves += o.leaves;
  candidates += o.candidates;
  solved += o.solved;
  static_tests += o.static_tests;
  refined += o.refined;
  for (int k = 0; k < 5; ++k) by_stage[k] += o.by_stage[k];
}

namespace {

class Brute_source final : public Candidate_source {
 public:
  explicit Brute_source(const Pair_ctx &ctx) : A_(ctx.side(0)), B_(ctx.side(1)) {}

  std::vector<Prim_pair> static_candidates(util::Thread_pool &) override {
    std::vector<Prim_pair> cand;
    all(cand, TT, A_.mesh->triangles().size(), B_.mesh->triangles().size(), nullptr, nullptr);
    return cand;
  }

  void run(Candidate_sink &sink, Search_stats &, util::Thread_pool &) override {
    std::vector<Prim_pair> cand;
    if (A_.is_mesh() && B_.is_mesh()) {
      all(cand, VF, 0, B_.mesh->triangles().size(), &A_.data->surface_vertices, nullptr);
      all(cand, FV, A_.mesh->triangles().size(), 0, nullptr, &B_.data->surface_vertices);
      all(cand, EE, A_.mesh->edges().size(), B_.mesh->edges().size(), nullptr, nullptr);
    } else if (!A_.is_mesh() && !B_.is_mesh()) {
      all(cand, SS, A_.n_points(), B_.n_points(), nullptr, nullptr);
    } else if (!A_.is_mesh()) {
      all(cand, ST, A_.n_points(), B_.mesh->triangles().size(), nullptr, nullptr);
    } else {
      all(cand, TS, A_.mesh->triangles().size(), B_.n_points(), nullptr, nullptr);
    }
    sink.whole(std::move(cand));
  }

 private:
  const Moving_body &A_, &B_;

  // Every (a, b): a over va (or 0..na-1 when va is null), b likewise.
  static void all(std::vector<Prim_pair> &cand, uint8_t type, size_t na, size_t nb,
                  const std::vector<uint32_t> *va, const std::vector<uint32_t> *vb) {
    for (size_t i = 0; i < (va ? va->size() : na); ++i)
      for (size_t j = 0; j < (vb ? vb->size() : nb); ++j)
        cand.push_back({type, va ? (*va)[i] : uint32_t(i), vb ? (*vb)[j] : uint32_t(j)});
  }
};

}  // namespace

std::unique_ptr<Candidate_source> brute_source(const Pair_ctx &ctx) {
  return std::make_unique<Brute_source>(ctx);
}

bool has_infinite_bounds(const Pair_ctx &ctx) {
  for (int s = 0; s < 2; ++s)
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(ctx.side(s).data->box_h[a])) return true;
  return false;
}

}  // namespace pccd::narrow
