// The event queue: one entry per disk (its earliest predicted event) in a calendar (bucket) queue.
//
// Each disk owns exactly one key (time, tag), tag = kind << 29 | disk. The order is total (time, then kind,
// then disk id), so ties are broken the same way whatever the history of the queue, and a run resumed from
// a rebuilt queue pops the same sequence: the queue changes how fast the minimum is found, never which.
// Time is cut into a "year" of B buckets of width w starting at base: bucket(t) = floor((t - base) / w),
// monotone in t. Keys in buckets up to the current one sit in a small binary heap (the exact (time, tag)
// order); keys in later buckets of the year sit unsorted in that bucket's doubly linked list; keys past the
// year in one overflow list; keys that never happen (infinite time: a disk at rest) in one more list, whose
// minimum is only looked for when nothing else is left. Because bucket() is monotone, the heap's minimum is
// the global one; when the heap empties the next non-empty bucket moves into it, and when the year runs
// out a new year starts at the earliest overflow key, with w chosen from the overflow keys (B buckets over
// twice their mean distance from that earliest key: a few keys per bucket). set() is O(1) (unlink, link)
// for a key that lands in a later bucket, which is nearly every key: an event's new predictions lie ahead.
// Links live in two int32 arrays beside the keys; a list head's backward link encodes its list, a heap
// member's forward link is its heap position. A key is stored as its time (time_) and its kind (kind_, one
// byte): the disk part of the tag is the key's index, so 9 bytes a key in double (16 as a struct, 12
// packed; docs/performance.md, "Memory cuts"). Only equal times read the kinds.
// Measured against the blocked tournament tree it replaces (docs/performance.md): the tree's walk to the
// root for every popped disk cost ~440 instructions per update, 22 % of the run at N = 10^4.
// Rejected: the blocked tournament tree (O(log N) per update, kept in git history), a binary heap of pair
// events with lazy deletion (grows with stale events and needs a sweep), std::set (an allocation per
// update), and a bucket width fixed at construction (a cooling or heating gas changes its event rate by
// orders of magnitude; the width follows it at each year).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/event.hpp"
#include "core/scalar_math.hpp"

namespace ede {

constexpr std::uint32_t kTagDiskBits = 29;
constexpr std::uint32_t kTagDiskMask = (1u << kTagDiskBits) - 1;
constexpr std::uint32_t kMaxQueueDisks = 1u << kTagDiskBits;

inline std::uint32_t make_tag(EventKind kind, std::uint32_t disk) {
  return (static_cast<std::uint32_t>(kind) << kTagDiskBits) | disk;
}
inline std::uint32_t tag_disk(std::uint32_t tag) { return tag & kTagDiskMask; }
inline EventKind tag_kind(std::uint32_t tag) { return static_cast<EventKind>(tag >> kTagDiskBits); }

template <class T>
struct QueueKey {
  T time;
  std::uint32_t tag;

  // Written with non-short-circuit operators: which key wins is a coin flip the branch predictor cannot
  // learn, so the comparison compiles to flag arithmetic.
  friend bool operator<(const QueueKey& a, const QueueKey& b) {
    return (a.time < b.time) | ((a.time == b.time) & (a.tag < b.tag));
  }
  friend bool operator==(const QueueKey& a, const QueueKey& b) {
    return a.time == b.time && a.tag == b.tag;
  }
};

template <class T>
class EventQueue {
 public:
  EventQueue() = default;
  // n disks, every key initially (+inf, kind Pair, disk).
  explicit EventQueue(std::uint32_t n) { reset(n); }

  void reset(std::uint32_t n) {
    buckets_ = std::max<std::uint32_t>(16, n);  // one bucket per key: 4 B/disk of heads at every N
    head_.assign(std::size_t(buckets_) + 2, kNil);
    time_.resize(n);
    kind_.resize(n);
    next_.resize(n);
    prev_.resize(n);
    heap_.clear();
    heap_.reserve(64);
    cur_ = buckets_;  // no year yet: every finite key goes to the overflow list (base = -inf)
    ahead_ = 0;
    base_ = -scalar_limits<T>::infinity();
    inv_width_ = 1;
    never_min_ = kNil;
    for (std::uint32_t i = n; i-- > 0;) {
      time_[i] = scalar_limits<T>::infinity();
      kind_[i] = EventKind::Pair;
      link(std::int32_t(i), never_list());
    }
    never_min_ = n ? 0 : kNil;
  }

  // The earliest key (the heap's root, after moving the next bucket in if the heap is empty); a key of
  // infinite time when nothing is due.
  QueueKey<T> top() {
    if (heap_.empty()) refill();
    if (!heap_.empty()) return key(heap_[0]);
    return never_top();
  }
  QueueKey<T> key_of(std::uint32_t disk) const { return key(std::int32_t(disk)); }

  // Calls f(disk) once for every disk keyed in the buckets up to `ahead` past the current one that it has
  // not visited yet: with about one key per bucket and new keys spread over the whole year, these are very
  // likely the next events (the engine prefetches their records, run_until).
  template <class F>
  void visit_ahead(std::uint32_t ahead, F&& f) {
    if (ahead_ < cur_) ahead_ = cur_;
    const std::uint32_t last = std::min(cur_ + ahead, buckets_ - 1);
    while (ahead_ < last) {
      ++ahead_;
      for (std::int32_t d = head_[ahead_]; d != kNil; d = next_[d]) f(d);
    }
  }

  void set(std::uint32_t disk, T time, EventKind kind) {
    const std::int32_t d = std::int32_t(disk);
    if (prev_[d] == kInHeap) {
      const std::int32_t s = slot_for(time);
      if (s < 0) {  // stays in the heap: move it within
        const std::uint32_t pos = std::uint32_t(next_[d]);
        const bool earlier = QueueKey<T>{time, make_tag(kind, disk)} < key(d);
        time_[d] = time;
        kind_[d] = kind;
        if (earlier)
          sift_up(pos);
        else
          sift_down(pos);
        return;
      }
      heap_remove(std::uint32_t(next_[d]));
      time_[d] = time;
      kind_[d] = kind;
      link(d, s);
      return;
    }
    unlink(d);
    time_[d] = time;
    kind_[d] = kind;
    const std::int32_t s = slot_for(time);
    if (s < 0)
      heap_push(d);
    else
      link(d, s);
  }

  std::size_t memory_bytes() const {
    return time_.capacity() * sizeof(T) + kind_.capacity() * sizeof(EventKind) +
           (next_.capacity() + prev_.capacity() + head_.capacity() + heap_.capacity()) * sizeof(std::int32_t);
  }

 private:
  static constexpr std::int32_t kNil = -1;
  static constexpr std::int32_t kInHeap = -2;  // prev_ of a heap member (next_ holds its heap position)
  // prev_ of a list's first member: -3 - list
  static std::int32_t head_mark(std::int32_t list) { return -3 - list; }

  std::int32_t overflow_list() const { return std::int32_t(buckets_); }
  std::int32_t never_list() const { return std::int32_t(buckets_) + 1; }

  // Where a key of this time goes now: -1 for the heap (its bucket is the current one or earlier), a
  // bucket of the year, the overflow list, or the never list (infinite or NaN time).
  std::int32_t slot_for(T time) const {
    if (!(time < scalar_limits<T>::infinity())) return never_list();
    const double x = double(time - base_) * inv_width_;
    if (x < double(cur_) + 1) return -1;  // also a key earlier than base (never produced by the engine)
    if (x < double(buckets_)) return std::int32_t(x);
    return overflow_list();
  }

  void link(std::int32_t d, std::int32_t list) {
    const std::int32_t h = head_[std::size_t(list)];
    next_[d] = h;
    prev_[d] = head_mark(list);
    if (h != kNil) prev_[h] = d;
    head_[std::size_t(list)] = d;
    if (list == never_list() && never_min_ != kNil && less(d, never_min_)) never_min_ = d;
  }

  void unlink(std::int32_t d) {
    const std::int32_t p = prev_[d], n = next_[d];
    if (p >= 0) {
      next_[p] = n;
    } else {
      head_[std::size_t(-3 - p)] = n;
    }
    if (d == never_min_) never_min_ = kNil;
    if (n != kNil) prev_[n] = p;
  }

  // The heap is empty: move the next non-empty bucket of the year into it, or start a new year.
  void refill() {
    while (heap_.empty()) {
      while (cur_ + 1 < buckets_)
        if (head_[++cur_] != kNil) return drain(cur_);
      cur_ = buckets_;
      if (head_[std::size_t(overflow_list())] == kNil) return;  // nothing finite is due
      new_year();
    }
  }

  // Moves every key of one bucket (the current) into the heap.
  void drain(std::uint32_t bucket) {
    std::int32_t d = head_[bucket];
    head_[bucket] = kNil;
    while (d != kNil) {
      const std::int32_t n = next_[d];
      heap_push(d);
      d = n;
    }
  }

  // Starts a year at the earliest overflow key, buckets spread over twice the keys' mean distance from it,
  // and sorts the overflow keys into the heap, the year's buckets, or back to overflow.
  void new_year() {
    const std::size_t of = std::size_t(overflow_list());
    T t_min = scalar_limits<T>::infinity();
    std::size_t count = 0;
    for (std::int32_t d = head_[of]; d != kNil; d = next_[d]) {
      t_min = time_[d] < t_min ? time_[d] : t_min;
      ++count;
    }
    double sum = 0;
    for (std::int32_t d = head_[of]; d != kNil; d = next_[d]) sum += double(time_[d] - t_min);
    const double span = 2 * sum / double(count);
    const double floor_span = std::max(std::abs(double(t_min)) * 1e-12, 1e-300);
    base_ = t_min;
    inv_width_ = double(buckets_) / std::max(span, floor_span);
    cur_ = 0;
    ahead_ = 0;
    std::int32_t d = head_[of];
    head_[of] = kNil;
    while (d != kNil) {
      const std::int32_t n = next_[d];
      const std::int32_t s = slot_for(time_[d]);
      if (s < 0)
        heap_push(d);
      else
        link(d, s);
      d = n;
    }
  }

  QueueKey<T> never_top() {
    const std::int32_t h = head_[std::size_t(never_list())];
    if (h == kNil) return {scalar_limits<T>::infinity(), ~0u};
    if (never_min_ == kNil) {
      never_min_ = h;
      for (std::int32_t d = next_[h]; d != kNil; d = next_[d])
        if (less(d, never_min_)) never_min_ = d;
    }
    return key(never_min_);
  }

  QueueKey<T> key(std::int32_t d) const { return {time_[d], make_tag(kind_[d], std::uint32_t(d))}; }
  // key(a) < key(b). Times differ nearly always; which is earlier is a coin flip the branch predictor
  // cannot learn, so that comparison is a value, and only the rare tie branches to the kinds.
  bool less(std::int32_t a, std::int32_t b) const {
    const T ta = time_[a], tb = time_[b];
    if (__builtin_expect(ta == tb, 0)) return make_tag(kind_[a], std::uint32_t(a)) < make_tag(kind_[b], std::uint32_t(b));
    return ta < tb;
  }

  // --- the binary min-heap of the current bucket (positions in next_) ---
  void place(std::uint32_t pos, std::int32_t d) {
    heap_[pos] = d;
    next_[d] = std::int32_t(pos);
  }
  void heap_push(std::int32_t d) {
    prev_[d] = kInHeap;
    heap_.push_back(d);
    sift_up(std::uint32_t(heap_.size() - 1));
  }
  void heap_remove(std::uint32_t pos) {
    const std::int32_t last = heap_.back();
    heap_.pop_back();
    if (pos == heap_.size()) return;
    const bool earlier = less(last, heap_[pos]);
    place(pos, last);
    if (earlier)
      sift_up(pos);
    else
      sift_down(pos);
  }
  void sift_up(std::uint32_t pos) {
    const std::int32_t d = heap_[pos];
    while (pos > 0) {
      const std::uint32_t parent = (pos - 1) / 2;
      if (!less(d, heap_[parent])) break;
      place(pos, heap_[parent]);
      pos = parent;
    }
    place(pos, d);
  }
  void sift_down(std::uint32_t pos) {
    const std::int32_t d = heap_[pos];
    const std::uint32_t n = std::uint32_t(heap_.size());
    while (true) {
      std::uint32_t child = 2 * pos + 1;
      if (child >= n) break;
      if (child + 1 < n && less(heap_[child + 1], heap_[child])) ++child;
      if (!less(heap_[child], d)) break;
      place(pos, heap_[child]);
      pos = child;
    }
    place(pos, d);
  }

  std::uint32_t buckets_ = 16;  // per year: max(16, N) (a power of two >= N cost up to 8 B/disk)
  std::uint32_t cur_ = 16;      // the current bucket: keys in buckets <= cur_ are in the heap
  std::uint32_t ahead_ = 0;     // visit_ahead has visited the buckets up to here
  T base_ = T(0);               // the year's start time
  double inv_width_ = 1;        // buckets per unit time
  std::vector<T> time_;               // each disk's key: its time
  std::vector<EventKind> kind_;       // and its kind (the tag is kind << 29 | disk)
  std::vector<std::int32_t> next_;    // list: next member or kNil; heap: position
  std::vector<std::int32_t> prev_;    // list: previous member, or head_mark(list) for the first; heap: kInHeap
  std::vector<std::int32_t> head_;    // first member of each bucket, then the overflow and never lists
  std::vector<std::int32_t> heap_;    // the current bucket's keys (disks), a binary min-heap
  std::int32_t never_min_ = kNil;     // the never list's minimum key, kNil when unknown
};

}  // namespace ede
