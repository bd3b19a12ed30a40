// pccd_report_*: reading the answers of a scene solve.
#include <string>

#include "api/guard.h"
#include "api/scene_handle.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::api::require_solved;
using pccd::api::State_error;
using pccd::arith::Input_error;
using pccd::arith::Rational;

namespace {

struct Time_ref {
  bool any;  // there is a contact (so a time)
  const Rational *lo, *hi;
  bool exact;
};

const pccd::scene::Pair_report &pair_at(const pccd_report *rep, size_t p) {
  if (p >= rep->r.pairs.size())
    throw Input_error("pair: " + std::to_string(p) + " out of range (" +
                      std::to_string(rep->r.pairs.size()) + " pairs in contact)");
  return rep->r.pairs[p];
}

const pccd::scene::Contact_report &contact_at(const pccd_report *rep, size_t p, size_t c) {
  const auto &pr = pair_at(rep, p);
  if (c >= pr.contacts.size())
    throw Input_error("contact: " + std::to_string(c) + " out of range (" +
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

PCCD_API int pccd_report_new(pccd_report **out) { return pccd::api::new_handle(__func__, out); }

PCCD_API void pccd_report_free(pccd_report *rep) { delete rep; }

PCCD_API int pccd_report_collides(const pccd_report *rep, int *collides) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    require(collides, "collides");
    *collides = rep->r.collides ? 1 : 0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_time(const pccd_report *rep, size_t pair, size_t contact, int which,
                              char *buf, size_t cap, size_t *needed) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    if (which < 0 || which > 2)
      throw Input_error("which: " + std::to_string(which) +
                        " is not 0 (lo), 1 (hi) or 2 (exact)");
    Time_ref t = time_of(rep, pair, contact);
    if (!t.any) throw State_error("rep: there is no contact, so no contact time");
    if (which == 2 && !t.exact)
      throw State_error("rep: the contact time is not known exactly (irrational, or "
                        "want_exact was 0)");
    return pccd::api::write_text(pccd::arith::to_string(which == 1 ? *t.hi : *t.lo), buf, cap,
                                 needed);
  });
}

PCCD_API int pccd_report_time_info(const pccd_report *rep, size_t pair, size_t contact,
                                   int *exact, double *approx) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    Time_ref t = time_of(rep, pair, contact);
    if (!t.any) throw State_error("rep: there is no contact, so no contact time");
    if (exact) *exact = t.exact ? 1 : 0;
    if (approx) *approx = pccd::arith::nearest_double((*t.lo + *t.hi) / 2);
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_pair_count(const pccd_report *rep, size_t *count) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    require(count, "count");
    *count = rep->r.pairs.size();
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_pair(const pccd_report *rep, size_t pair, size_t *body_i, size_t *body_j,
                              int *is_first) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
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
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    require(count, "count");
    *count = pair_at(rep, pair).contacts.size();
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_contact(const pccd_report *rep, size_t pair, size_t contact, int *feature_i,
                                 size_t *index_i, int *feature_j, size_t *index_j) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    const auto &c = contact_at(rep, pair, contact);
    if (feature_i) *feature_i = c.a.type;
    if (index_i) *index_i = c.a.index;
    if (feature_j) *feature_j = c.b.type;
    if (index_j) *index_j = c.b.index;
    return PCCD_OK;
  });
}

PCCD_API int pccd_report_stats(const pccd_report *rep, pccd_scene_stats *stats) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    require(stats, "stats");
    const auto &s = rep->r.stats;
    *stats = {s.pieces, s.leaves, s.candidates, s.solved, s.static_tests, s.refined, {0, 0, 0, 0, 0}};
    for (int k = 0; k < 5; ++k) stats->by_stage[k] = s.by_stage[k];
    return PCCD_OK;
  });
}

}  // extern "C"

extern "C" {

PCCD_API int pccd_report_free_until(const pccd_report *rep, char *buf, size_t cap, size_t *needed,
                                    double *below) {
  return guard(__func__, [&]() -> int {
    require_solved(rep, "rep");
    const Rational &f = rep->r.free_until;
    if (below) {  // a double <= f: the nearest, stepped down when above
      double d = pccd::arith::nearest_double(f);
      Rational dq;
      mpq_set_d(dq.get_mpq_t(), d);
      if (dq > f) d = pccd::arith::round_down(d);
      *below = d;
    }
    const std::string text = pccd::arith::to_string(f);
    if (!buf && cap == 0) {  // only *below (or the size) wanted
      if (needed) *needed = text.size() + 1;
      return PCCD_OK;
    }
    return pccd::api::write_text(text, buf, cap, needed);
  });
}

}  // extern "C"
