// A body pair's point trajectories made once per pair (Pair_ctx::traj_q, traj_i and the
// own trajectories): the feature pairs a pair solves share their points, and each was
// made anew per query. With a minimum distance, the feature pairs of one vertex-vertex
// approach all touch first together (every triangle and edge at both vertices: 35-47
// on the UR5's wrist / end-effector pairs), and building their exact points, the
// rotated polynomials of degree up to 16, was the largest single cost of their solves
// (perf, issue 33).
#pragma once
#include <cstdint>
#include <mutex>
#include <unordered_map>

namespace pccd::narrow {

// The value of a key, made by `make` on its first request and copied out. Safe from
// several threads (a pair's feature pairs are solved in parallel); make runs unlocked,
// so two threads may both make a value, and the first one stored is kept (the same).
template <class T>
class Point_memo {
 public:
  template <class Make>
  T get(uint64_t key, const Make &make) {
    {
      std::lock_guard<std::mutex> lock(m_);
      auto it = map_.find(key);
      if (it != map_.end()) return it->second;
    }
    T v = make();
    std::lock_guard<std::mutex> lock(m_);
    map_.emplace(key, v);
    return v;
  }

 private:
  std::mutex m_;
  std::unordered_map<uint64_t, T> map_;
};

// The key of point k of side s.
inline uint64_t point_key(int s, uint32_t k) { return (uint64_t(s) << 32) | k; }

}  // namespace pccd::narrow
