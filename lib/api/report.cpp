// pccd_report_*: reading the answers of a scene solve.
#include <string>

#include "api/guard.h"
#include "api/scene_handle.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Rational;

namespace {

struct Time_ref {
  bool any;  // there is a contact (so a time)
  const Rational *lo, *hi;
  bool exact;
};

// False (with the error set) when nothing was solved into rep: PCCD_ESTATE.
bool solved(const pccd_report *rep, const char *fn) {
  require(rep, "report");
  if (!rep->solved) pccd::api::set_error(fn, "no scene has been solved into this report");
  return rep->solved;
}

const pccd::scene::Pair_report &pair_at(const pccd_report *rep, size_t p) {
  if (p >= rep->r.pairs.size())
    throw Input_error("pair index " + std::to_string(p) + " out of range (" +
                      std::to_string(rep->r.pairs.size()) + " pairs in contact)");
  return rep->r.pairs[p];
}

const pccd::scene::Contact_report &contact_at(const pccd_report *rep, size_t p, size_t c) {
  const auto &pr = pair_at(rep, p);
  if (c >= pr.contacts.size())
    throw Input_error("contact index " + std::to_string(c) + " out of range (" +
                      std::to_string(pr.contacts.size()) + " contacts)");
  return pr.contacts[c];
}

Time_ref time_of(const pccd_report *rep, size_t pair, size_t contact) {
  if (pair == PCCD_WHOLE) return {rep->r.collides, &rep->r.lo, &rep->r.hi, rep->r.exact};
  if (contact == PCCD_WHOLE) {
    const auto &p = pair_at(rep, pair);
    return {true, &p.lo, &p.hi, p.exact};
  }
  const auto &c = contact_at(rep, pair, contact);
  return {true, &c.lo, &c.hi, c.exact};
}

}  // namespace

extern "C" {

PCCD_API int pccd_report_new(pccd_report **out) { return pccd::api::new_handle("pccd_report_new", out); }

PCCD_API void pccd_report_free(pccd_report *rep) { delete rep; }

PCCD_API int pccd_report_collides(const pccd_report *rep, int *collides) {
  return guard("pccd_report_collides", [&]() -> int {
    if (!solved(rep, "pccd_report_collides")) return PCCD_ESTATE;
    require(collides, "collides");
    *collides = rep->r.collides ? 1 : 0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_time(const pccd_report *rep, size_t pair, size_t contact, int which,
                              char *buf, size_t cap, size_t *needed) {
  return guard("pccd_report_time", [&]() -> int {
    if (!solved(rep, "pccd_report_time")) return PCCD_ESTATE;
    if (which < 0 || which > 2)
      throw Input_error("which is " + std::to_string(which) + "; expected 0 (lo), 1 (hi) or 2 (exact)");
    Time_ref t = time_of(rep, pair, contact);
    if (!t.any) {
      pccd::api::set_error("pccd_report_time", "there is no contact, so no contact time");
      return PCCD_ESTATE;
    }
    if (which == 2 && !t.exact) {
      pccd::api::set_error("pccd_report_time", "the contact time is not known exactly "
                                               "(irrational, or want_exact was 0)");
      return PCCD_ESTATE;
    }
    return pccd::api::write_text("pccd_report_time",
                                 pccd::arith::to_string(which == 1 ? *t.hi : *t.lo), buf, cap,
                                 needed);
  });
}

PCCD_API int pccd_report_time_info(const pccd_report *rep, size_t pair, size_t contact,
                                   int *exact, double *approx) {
  return guard("pccd_report_time_info", [&]() -> int {
    if (!solved(rep, "pccd_report_time_info")) return PCCD_ESTATE;
    Time_ref t = time_of(rep, pair, contact);
    if (!t.any) {
      pccd::api::set_error("pccd_report_time_info", "there is no contact, so no contact time");
      return PCCD_ESTATE;
    }
    if (exact) *exact = t.exact ? 1 : 0;
    if (approx) *approx = pccd::arith::nearest_double((*t.lo + *t.hi) / 2);
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_pair_count(const pccd_report *rep, size_t *count) {
  return guard("pccd_report_pair_count", [&]() -> int {
    if (!solved(rep, "pccd_report_pair_count")) return PCCD_ESTATE;
    require(count, "count");
    *count = rep->r.pairs.size();
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_pair(const pccd_report *rep, size_t pair, size_t *body_i, size_t *body_j,
                              int *is_first) {
  return guard("pccd_report_pair", [&]() -> int {
    if (!solved(rep, "pccd_report_pair")) return PCCD_ESTATE;
    const auto &p = pair_at(rep, pair);
    if (body_i) *body_i = p.i;
    if (body_j) *body_j = p.j;
    if (is_first) {
      *is_first = 0;
      for (size_t f : rep->r.first_pairs)
        if (f == pair) *is_first = 1;
    }
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_contact_count(const pccd_report *rep, size_t pair, size_t *count) {
  return guard("pccd_report_contact_count", [&]() -> int {
    if (!solved(rep, "pccd_report_contact_count")) return PCCD_ESTATE;
    require(count, "count");
    *count = pair_at(rep, pair).contacts.size();
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_contact(const pccd_report *rep, size_t pair, size_t contact, int *feature_i,
                                 size_t *index_i, int *feature_j, size_t *index_j) {
  return guard("pccd_report_contact", [&]() -> int {
    if (!solved(rep, "pccd_report_contact")) return PCCD_ESTATE;
    const auto &c = contact_at(rep, pair, contact);
    if (feature_i) *feature_i = c.a.type;
    if (index_i) *index_i = c.a.index;
    if (feature_j) *feature_j = c.b.type;
    if (index_j) *index_j = c.b.index;
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_stats(const pccd_report *rep, pccd_scene_stats *stats) {
  return guard("pccd_report_stats", [&]() -> int {
    if (!solved(rep, "pccd_report_stats")) return PCCD_ESTATE;
    require(stats, "stats");
    const auto &s = rep->r.stats;
    *stats = {s.pieces, s.leaves, s.candidates, s.solved, s.static_tests, s.refined, {0, 0, 0, 0, 0}};
    for (int k = 0; k < 5; ++k) stats->by_stage[k] = s.by_stage[k];
    return PCCD_OK;
  });
}

}  // extern "C"
