// pccd_step_*: whole steps of deforming meshes (lib/step), each candidate pair solved by
// the linear path of pccd_solve_linear_d (pred/solve_linear.h).
#include <cmath>
#include <string>

#include "api/config.h"
#include "api/guard.h"
#include "api/handles.h"
#include "api/limits.h"
#include "arith/convert.h"
#include "step/step.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::api::require_solved;
using pccd::api::State_error;
using pccd::arith::Input_error;

struct pccd_step {
  pccd::step::Step_set set;
};

struct pccd_step_report {
  bool solved = false;
  int mode = 0;
  pccd::step::Step_report r;
  std::vector<size_t> index;  // 4 per contact: mesh and local index of a, of b
};

namespace pccd::api {
namespace {

// The mesh and local index of a contact's side: vertices, faces or edges per kind.
void locate(const step::Step_set &s, int kind, bool side_b, uint32_t g, size_t *out) {
  const bool vertex = kind == pred::VERTEX_VERTEX || (!side_b && kind != pred::EDGE_EDGE);
  const bool face = side_b && kind == pred::VERTEX_FACE;
  const uint32_t m = vertex ? s.vmesh[g] : face ? s.fmesh[g] : s.emesh[g];
  const step::Mesh_range &r = s.meshes[m];
  out[0] = m;
  out[1] = g - (vertex ? r.v0 : face ? r.f0 : r.e0);
}

// The input limit on number sizes (pccd_config.max_number_bits) over every coordinate;
// only a limit below 1,127 bits (the largest double) can be exceeded.
void check_bits(const step::Step_set &s, const Call_limits &l) {
  if (l.max_number_bits == 0 || l.max_number_bits >= 1127) return;
  for (size_t m = 0; m < s.meshes.size(); ++m) {
    const step::Mesh_range &r = s.meshes[m];
    for (int t = 0; t < 2; ++t)
      for (size_t i = 0; i < 3 * size_t(r.nv); ++i) {
        Biggest_number b;
        b.bits = number_bits((t ? s.x1 : s.x0)[3 * size_t(r.v0) + i]);
        b.place = "meshes[" + std::to_string(m) + "]." + (t ? "v_t1" : "v_t0") + place("", {i / 3, i % 3});
        l.check(b);
      }
  }
}

const step::Mesh_range &mesh_at(const pccd_step *s, size_t mesh) {
  require(s, "s");
  if (mesh >= s->set.meshes.size())
    throw Input_error("mesh: " + std::to_string(mesh) + " out of range (" +
                      std::to_string(s->set.meshes.size()) + " meshes)");
  return s->set.meshes[mesh];
}

void require_time(const pccd_step_report *rep) {
  require_solved(rep, "rep");
  if (rep->mode == PCCD_STEP_DECIDE) throw State_error("rep: a step solved in mode DECIDE has no time");
  if (!rep->r.collides) throw State_error("rep: there is no contact, so no contact time");
}

}  // namespace
}  // namespace pccd::api

extern "C" {

PCCD_API int pccd_step_new(pccd_step **out) { return pccd::api::new_handle(__func__, out); }
PCCD_API void pccd_step_free(pccd_step *s) { delete s; }

PCCD_API int pccd_step_add_mesh_d(pccd_step *s, const double *v_t0, const double *v_t1, size_t nv,
                                  const unsigned int *faces, size_t nf, const unsigned int *edges,
                                  size_t ne, const unsigned int *points, size_t np, size_t *index) {
  return guard(__func__, [&] {
    require(s, "s");
    const size_t m = pccd::step::add_mesh(s->set, v_t0, v_t1, nv, faces, nf, edges, edges ? ne : 0,
                                          points, np);
    if (index) *index = m;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_add_mesh_cfg_d(pccd_step *s, const double *v_t0, const double *v_t1,
                                      size_t nv, const unsigned int *faces, size_t nf,
                                      const unsigned int *edges, size_t ne,
                                      const unsigned int *points, size_t np, size_t *index,
                                      const pccd_config *cfg) {
  return guard(__func__, [&] {
    require(s, "s");
    // the config's rules (struct_size, ...) as for any call; only its work limits are used
    const pccd::api::Call_limits limits = pccd::api::read_call(cfg).limits;
    const pccd::api::Call_budget budget(limits.work);
    const size_t m = pccd::step::add_mesh(s->set, v_t0, v_t1, nv, faces, nf, edges, edges ? ne : 0,
                                          points, np);
    if (index) *index = m;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_set_positions_d(pccd_step *s, size_t mesh, const double *v_t0,
                                       const double *v_t1, size_t nv) {
  return guard(__func__, [&] {
    require(s, "s");
    pccd::step::set_positions(s->set, mesh, v_t0, v_t1, nv);
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_set_paths_d(pccd_step *s, size_t mesh, const double *coeffs, size_t ncoeffs,
                                   size_t nv) {
  return guard(__func__, [&] {
    require(s, "s");
    pccd::step::set_paths(s->set, mesh, coeffs, ncoeffs, nv);
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_set_pair_check(pccd_step *s, size_t i, size_t j, int check) {
  return guard(__func__, [&] {
    require(s, "s");
    if (check != 0 && check != 1) throw Input_error("check: " + std::to_string(check) + " is not 0 or 1");
    pccd::step::set_pair_check(s->set, i, j, check == 1);
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_options_init(pccd_step_options *opt) {
  return guard(__func__, [&] {
    require(opt, "opt");
    opt->struct_size = sizeof *opt;
    opt->threads = 1;
    opt->mode = PCCD_STEP_FIRST;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_solve(const pccd_step *s, const pccd_config *cfg,
                             const pccd_step_options *opt, pccd_step_report *rep) {
  return guard(__func__, [&] {
    require(rep, "rep");
    rep->solved = false;
    rep->r = pccd::step::Step_report();
    rep->index.clear();
    require(s, "s");
    pccd::step::Step_options so;
    if (opt) {
      if (opt->struct_size != sizeof(pccd_step_options))
        throw Input_error("opt.struct_size: " + std::to_string(opt->struct_size) + " is not " +
                          std::to_string(sizeof(pccd_step_options)) +
                          " (initialise with pccd_step_options_init)");
      so.threads = pccd::api::checked_threads(opt->threads, "opt.threads");
      if (opt->mode < 0 || opt->mode > 2)
        throw Input_error("opt.mode: " + std::to_string(opt->mode) +
                          " is not 0 (FIRST), 1 (DECIDE) or 2 (ALL)");
      so.mode = static_cast<pccd::step::Mode>(opt->mode);
    }
    const pccd::api::Call_config call = pccd::api::read_call(cfg);
    so.solve = *call.solve;
    pccd::api::check_bits(s->set, call.limits);
    const pccd::api::Call_budget budget(call.limits.work);
    rep->r = pccd::step::solve_step(s->set, so);
    rep->mode = so.mode;
    rep->index.resize(4 * rep->r.contacts.size());
    for (size_t k = 0; k < rep->r.contacts.size(); ++k) {
      const auto &c = rep->r.contacts[k];
      pccd::api::locate(s->set, c.kind, false, c.a, &rep->index[4 * k]);
      pccd::api::locate(s->set, c.kind, true, c.b, &rep->index[4 * k + 2]);
    }
    rep->solved = true;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_report_new(pccd_step_report **out) { return pccd::api::new_handle(__func__, out); }
PCCD_API void pccd_step_report_free(pccd_step_report *rep) { delete rep; }

PCCD_API int pccd_step_report_collides(const pccd_step_report *rep, int *collides) {
  return guard(__func__, [&] {
    require_solved(rep, "rep");
    require(collides, "collides");
    *collides = rep->r.collides ? 1 : 0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_report_time(const pccd_step_report *rep, int which, char *buf, size_t cap,
                                   size_t *needed) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    if (which < 0 || which > 2)
      throw Input_error("which: " + std::to_string(which) + " is not 0 (lo), 1 (hi) or 2 (exact)");
    pccd::api::require_time(rep);
    if (which == 2 && !rep->r.exact)
      throw State_error("rep: the contact time is not known exactly (irrational, or want_exact was 0)");
    return pccd::api::write_text(pccd::arith::to_string(which == 1 ? rep->r.hi : rep->r.lo), buf, cap,
                                 needed);
  });
}

PCCD_API int pccd_step_report_time_info(const pccd_step_report *rep, int *exact, double *lo,
                                        double *hi) {
  return guard(__func__, [&] {
    pccd::api::require_time(rep);
    if (exact) *exact = rep->r.exact ? 1 : 0;
    if (lo) *lo = pccd::arith::enclose(rep->r.lo).lo;
    if (hi) *hi = pccd::arith::enclose(rep->r.hi).hi;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_report_stepsize(const pccd_step_report *rep, double *stepsize) {
  return guard(__func__, [&] {
    require_solved(rep, "rep");
    require(stepsize, "stepsize");
    if (rep->mode == PCCD_STEP_DECIDE) throw State_error("rep: a step solved in mode DECIDE has no step size");
    *stepsize = rep->r.stepsize;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_report_contact_count(const pccd_step_report *rep, size_t *count) {
  return guard(__func__, [&] {
    require_solved(rep, "rep");
    require(count, "count");
    *count = rep->r.contacts.size();
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_report_contacts(const pccd_step_report *rep, size_t first, size_t n,
                                       int *kind, size_t *index, double *lo, double *hi,
                                       unsigned char *exact) {
  return guard(__func__, [&] {
    require_solved(rep, "rep");
    const size_t count = rep->r.contacts.size();
    if (first > count || n > count - first)
      throw Input_error("n: contacts " + std::to_string(first) + " .. " + std::to_string(first + n) +
                        " are beyond the " + std::to_string(count) + " contacts");
    const bool timed = rep->mode != PCCD_STEP_DECIDE;
    for (size_t k = first; k < first + n; ++k) {
      const auto &c = rep->r.contacts[k];
      const size_t o = k - first;
      if (kind) kind[o] = c.kind;
      if (index)
        for (int i = 0; i < 4; ++i) index[4 * o + i] = rep->index[4 * k + i];
      if (lo) lo[o] = timed ? pccd::arith::enclose(c.r.lo).lo : NAN;
      if (hi) hi[o] = timed ? pccd::arith::enclose(c.r.hi).hi : NAN;
      if (exact) exact[o] = timed && c.r.exact ? 1 : 0;
    }
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_edges(const pccd_step *s, size_t mesh, size_t first, size_t n, size_t *v) {
  return guard(__func__, [&] {
    const pccd::step::Mesh_range &r = pccd::api::mesh_at(s, mesh);
    if (first > r.ne || n > r.ne - first)
      throw Input_error("n: edges " + std::to_string(first) + " .. " + std::to_string(first + n) +
                        " are beyond the " + std::to_string(r.ne) + " edges");
    if (n) require(v, "v");
    for (size_t i = 0; i < n; ++i)
      for (int k = 0; k < 2; ++k) v[2 * i + k] = s->set.edges[r.e0 + first + i][k] - r.v0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_mesh_counts(const pccd_step *s, size_t mesh, size_t *nv, size_t *nf,
                                   size_t *ne, size_t *np) {
  return guard(__func__, [&] {
    const pccd::step::Mesh_range &r = pccd::api::mesh_at(s, mesh);
    if (nv) *nv = r.nv;
    if (nf) *nf = r.nf;
    if (ne) *ne = r.ne;
    if (np) *np = r.np;
    return PCCD_OK;
  });
}

PCCD_API int pccd_step_report_stats(const pccd_step_report *rep, pccd_step_stats *stats) {
  return guard(__func__, [&] {
    require_solved(rep, "rep");
    require(stats, "stats");
    const auto &st = rep->r.stats;
    stats->queries = st.queries;
    stats->candidates = st.candidates;
    stats->refined = st.refined;
    for (int k = 0; k < 5; ++k) stats->by_stage[k] = st.by_stage[k];
    return PCCD_OK;
  });
}

}  // extern "C"
