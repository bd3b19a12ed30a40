// The on-line collision problem (paper section 3): one body on its motion is
// preprocessed once (its primitives as lifted points in range trees, range/range_index.h);
// then any number of query bodies on their own motions are answered against it, each
// as the two-body scene {stored, query} (body 0 is the stored body, body 1 the query):
// collides, first contact time, touching features, or all contacts.
//
// A single query primitive is a one-triangle mesh or a one-ball sphere set; its
// vertices, edges and triangle are then the query's features.
//
// query() only reads the index, so several threads may query one index at once.
// Answers equal those of solve_scene on the same two bodies with any broad phase;
// opt.broad_phase chooses how candidates are found; automatic is chosen per query by
// estimated cost (scene::choose, broad_phase.h; the rule: scene/auto_cost.h), and is
// bvh with a minimum separation delta > 0 (range has no delta).
#pragma once
#include "scene/scene.h"

namespace pccd::scene {

class Online_index {
 public:
  // Input_error "motion: ..." when the stored motion's quaternion vanishes on [0, 1].
  explicit Online_index(const Scene_body &stored);

  // Input_error "motion: ..." when the query motion's quaternion vanishes on [0, 1].
  Scene_report query(const Scene_body &q, const Scene_options &opt) const;

  // Every query of qs, into out[k] (resized). The queries are shared by opt.threads
  // workers, each query solved on one thread; answers equal those of query(). Input
  // errors are found before any query is solved ("bodies[k].motion: ...").
  void query_many(const std::vector<Scene_body> &qs, const Scene_options &opt,
                  std::vector<Scene_report> &out) const;

  const Moving_body &stored() const { return stored_; }

 private:
  Moving_body stored_;

};

}  // namespace pccd::scene
