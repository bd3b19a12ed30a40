// Storage for one robot check's pose enclosures (piece_poses.h): per dyadic piece or
// instant and link base, one slot per link and per obstacle, found through an
// open-addressing table. Kept per thread and reused by the next check, so a check
// allocates nothing once a check as large has run on its thread; it stores what the
// caller computed and decides nothing.
#pragma once
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "motion/chain_path.h"
#include "scene/link_filter.h"

namespace pccd::scene {

// Arrays of T handed out in runs of n contiguous elements that never move (chunks of
// at least kChunk elements; a reset hands the same memory out again).
template <class T>
class Chunks {
 public:
  T *take(size_t n) {
    while (at_ < chunks_.size() && used_ + n > sizes_[at_]) {
      ++at_;
      used_ = 0;
    }
    if (at_ == chunks_.size()) {
      const size_t sz = n > kChunk ? n : kChunk;
      chunks_.emplace_back(new T[sz]);
      sizes_.push_back(sz);
      used_ = 0;
    }
    T *out = chunks_[at_].get() + used_;
    used_ += n;
    return out;
  }
  void reset() { at_ = used_ = 0; }

 private:
  static constexpr size_t kChunk = 256;
  std::vector<std::unique_ptr<T[]>> chunks_;
  std::vector<size_t> sizes_;
  size_t at_ = 0, used_ = 0;
};

class Pose_store {
 public:
  // A piece's or instant's slots: nl per link (the links relative to the key's base),
  // no per obstacle (base -1 only). A have_ flag is set once its entry is made; the
  // entries are stale until then.
  struct Slots {
    motion::Pose_bounds *bounds;
    motion::Path_derivs *derivs;
    enclose::Pose_piece *links;
    Side_piece *side;
    char *have_bounds, *have_derivs, *have_links, *have_side;
    enclose::Pose_piece *obstacles;
    Side_piece *obst_side;
    char *have_obst;
  };

  // A store for a check of nl links and no obstacles: the thread's last one given back,
  // or a new one (a store is not shared: a check that starts while another holds one on
  // the same thread gets its own).
  static std::unique_ptr<Pose_store> borrow(size_t nl, size_t no) {
    auto &spare = spares();
    std::unique_ptr<Pose_store> s;
    if (spare.empty()) {
      s.reset(new Pose_store);
    } else {
      s = std::move(spare.back());
      spare.pop_back();
    }
    s->start(nl, no);
    return s;
  }
  static void give_back(std::unique_ptr<Pose_store> s) {
    auto &spare = spares();
    if (s && spare.size() < 4) spare.push_back(std::move(s));
  }

  // The slots over the piece [i, i + 1] / 2^d, relative to link base (-1: the world).
  Slots &piece(long base, int d, long i) { return find(pieces_, last_piece_, {base, d, i}); }
  // The slots at the instant i / 2^d, kept under its lowest terms (the end of one piece is
  // the start of the next, and of pieces of other depths).
  Slots &instant(long base, int d, long i) {
    while (d > 0 && i % 2 == 0) {
      i /= 2;
      --d;
    }
    if (i == 0) d = 0;
    return find(instants_, last_instant_, {base, d, i});
  }

 private:
  struct Key {
    long base;
    int d;
    long i;
    bool operator==(const Key &o) const { return base == o.base && d == o.d && i == o.i; }
  };
  struct Entry {
    Key key;
    uint32_t gen;  // valid in the check of generation gen
    Slots *slots;
  };
  struct Table {
    std::vector<Entry> e;  // a power of two long
    size_t count = 0;
  };
  struct Memo {
    Key key{0, -1, 0};  // depth -1: no key yet
    Slots *slots = nullptr;
  };

  static std::vector<std::unique_ptr<Pose_store>> &spares() {
    thread_local std::vector<std::unique_ptr<Pose_store>> s;
    return s;
  }
  void start(size_t nl, size_t no) {
    nl_ = nl;
    no_ = no;
    slots_.reset();
    bounds_.reset();
    derivs_.reset();
    poses_.reset();
    sides_.reset();
    flags_.reset();
    pieces_.count = instants_.count = 0;
    last_piece_ = last_instant_ = Memo{};
    if (++gen_ == 0) {  // wrapped: every entry forgotten
      for (Table *t : {&pieces_, &instants_})
        for (Entry &x : t->e) x.gen = 0;
      gen_ = 1;
    }
  }
  static size_t hash(const Key &k) {
    uint64_t h = static_cast<uint64_t>(k.i) * 0x9E3779B97F4A7C15ull;  // Fibonacci hashing
    h ^= (static_cast<uint64_t>(k.base + 2) << 8 | static_cast<uint64_t>(k.d)) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<size_t>(h ^ (h >> 29));
  }
  Slots &find(Table &t, Memo &last, const Key &k) {
    if (last.slots && last.key == k) return *last.slots;
    if (2 * (t.count + 1) > t.e.size()) grow(t);
    const size_t mask = t.e.size() - 1;
    size_t at = hash(k) & mask;
    while (t.e[at].gen == gen_ && !(t.e[at].key == k)) at = (at + 1) & mask;
    Entry &x = t.e[at];
    if (x.gen != gen_) {
      x = {k, gen_, make()};
      ++t.count;
    }
    last = {k, x.slots};
    return *x.slots;
  }
  void grow(Table &t) {
    std::vector<Entry> old;
    old.swap(t.e);
    t.e.assign(old.empty() ? 256 : 2 * old.size(), Entry{{0, 0, 0}, 0, nullptr});
    const size_t mask = t.e.size() - 1;
    for (const Entry &x : old) {
      if (x.gen != gen_) continue;
      size_t at = hash(x.key) & mask;
      while (t.e[at].gen == gen_) at = (at + 1) & mask;
      t.e[at] = x;
    }
  }
  Slots *make() {
    Slots *s = slots_.take(1);
    s->bounds = bounds_.take(nl_);
    s->derivs = derivs_.take(nl_);
    s->links = poses_.take(nl_);
    s->side = sides_.take(nl_);
    s->obstacles = poses_.take(no_);
    s->obst_side = sides_.take(no_);
    char *f = flags_.take(4 * nl_ + no_);
    std::memset(f, 0, 4 * nl_ + no_);
    s->have_bounds = f;
    s->have_derivs = f + nl_;
    s->have_links = f + 2 * nl_;
    s->have_side = f + 3 * nl_;
    s->have_obst = f + 4 * nl_;
    return s;
  }

  size_t nl_ = 0, no_ = 0;
  uint32_t gen_ = 0;
  Table pieces_, instants_;
  Memo last_piece_, last_instant_;
  Chunks<Slots> slots_;
  Chunks<motion::Pose_bounds> bounds_;
  Chunks<motion::Path_derivs> derivs_;
  Chunks<enclose::Pose_piece> poses_;
  Chunks<Side_piece> sides_;
  Chunks<char> flags_;
};

}  // namespace pccd::scene
