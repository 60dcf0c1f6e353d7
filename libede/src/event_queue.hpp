// The event queue: one entry per disk (its earliest predicted event) in a tournament tree.
//
// Each disk owns exactly one key (time, tag), tag = kind << 29 | disk; the tree keeps at every internal node
// the smaller of its two children, so the minimum is the root and changing one disk's key costs one walk to
// the root that stops as soon as a node does not change: O(log N) worst case, usually a few levels.
// The order is total (time, then kind, then disk id), so ties are broken the same way whatever the history
// of the tree, and a run resumed from a rebuilt queue pops the same sequence.
// Rejected: a binary heap of pair events with lazy deletion (grows with stale events and needs a
// sweep), and std::set (a node allocation per update). One event per disk also bounds memory at 2N keys.
// Layout: implicit complete binary tree, node k has children 2k+1 and 2k+2, leaves n-1 .. 2n-2 hold the
// disks' own keys. Keys are (time, tag) pairs stored inline so a level costs one cache line.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "ede/event.hpp"

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

  friend bool operator<(const QueueKey& a, const QueueKey& b) {
    return a.time < b.time || (a.time == b.time && a.tag < b.tag);
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
    n_ = n == 0 ? 1 : n;  // a tree needs a leaf; a lone padding leaf never wins against real keys
    nodes_.assign(2 * std::size_t(n_) - 1, QueueKey<T>{std::numeric_limits<T>::infinity(), ~0u});
    for (std::uint32_t i = 0; i < n; ++i) nodes_[leaf(i)].tag = make_tag(EventKind::Pair, i);
    for (std::size_t k = n_ - 1; k-- > 0;) nodes_[k] = min_of_children(k);
  }

  const QueueKey<T>& top() const { return nodes_[0]; }
  const QueueKey<T>& key_of(std::uint32_t disk) const { return nodes_[leaf(disk)]; }

  void set(std::uint32_t disk, T time, EventKind kind) {
    std::size_t k = leaf(disk);
    nodes_[k] = QueueKey<T>{time, make_tag(kind, disk)};
    while (k > 0) {
      k = (k - 1) / 2;
      const QueueKey<T> winner = min_of_children(k);
      if (winner == nodes_[k]) return;  // nothing above can change
      nodes_[k] = winner;
    }
  }

  std::size_t memory_bytes() const { return nodes_.capacity() * sizeof(QueueKey<T>); }

 private:
  std::size_t leaf(std::uint32_t disk) const { return std::size_t(n_) - 1 + disk; }
  QueueKey<T> min_of_children(std::size_t k) const {
    const QueueKey<T>& a = nodes_[2 * k + 1];
    const QueueKey<T>& b = nodes_[2 * k + 2];
    return b < a ? b : a;
  }

  std::uint32_t n_ = 0;
  std::vector<QueueKey<T>> nodes_;
};

}  // namespace ede
