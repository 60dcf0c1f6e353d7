// The event queue: one entry per disk (its earliest predicted event) in a blocked tournament tree.
//
// Each disk owns exactly one key (time, tag), tag = kind << 29 | disk. Keys sit in an array; disks are
// grouped in blocks of kBlock consecutive ids, and a tournament tree over the blocks keeps at every node
// the smaller of its two children, so the minimum is the root. Changing one disk's key costs a scan of its
// block (two cache lines) and a walk towards the root that stops as soon as a node does not change:
// O(log N) worst case, usually a few levels. The tree is kBlock times smaller than a tree over disks, so at
// N = 10^6 it stays in cache (4 MB instead of 32 MB): that is what makes large N fast.
// The order is total (time, then kind, then disk id), so ties are broken the same way whatever the history
// of the tree, and a run resumed from a rebuilt queue pops the same sequence.
// Rejected: a binary heap of pair events with lazy deletion (grows with stale events and needs a sweep),
// std::set (an allocation per update), and a plain tournament tree over disks (measured 25% slower at
// N = 10^6: its lower levels miss every cache).
// Layout: implicit complete binary tree, node k has children 2k+1 and 2k+2; leaves n-1 .. 2n-2 hold the
// block minima.
#pragma once

#include <cstdint>
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
  // learn, so the comparison compiles to flag arithmetic and the selections below to conditional moves.
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
  static constexpr std::uint32_t kBlock = 8;

  EventQueue() = default;
  // n disks, every key initially (+inf, kind Pair, disk).
  explicit EventQueue(std::uint32_t n) { reset(n); }

  void reset(std::uint32_t n) {
    blocks_ = n == 0 ? 1 : (n + kBlock - 1) / kBlock;
    const QueueKey<T> never{scalar_limits<T>::infinity(), ~0u};
    keys_.assign(std::size_t(blocks_) * kBlock, never);  // padding keys never win against real ones
    for (std::uint32_t i = 0; i < n; ++i) keys_[i].tag = make_tag(EventKind::Pair, i);
    nodes_.assign(2 * std::size_t(blocks_) - 1, never);
    for (std::uint32_t b = 0; b < blocks_; ++b) nodes_[leaf(b)] = block_min(b);
    for (std::size_t k = blocks_ - 1; k-- > 0;) nodes_[k] = min_of_children(k);
  }

  const QueueKey<T>& top() const { return nodes_[0]; }
  const QueueKey<T>& key_of(std::uint32_t disk) const { return keys_[disk]; }

  void set(std::uint32_t disk, T time, EventKind kind) {
    const QueueKey<T> key{time, make_tag(kind, disk)};
    const std::uint32_t b = disk / kBlock;
    std::size_t k = leaf(b);
    const bool was_block_min = tag_disk(nodes_[k].tag) == disk && nodes_[k].tag != ~0u;
    keys_[disk] = key;
    QueueKey<T> m;
    if (key < nodes_[k])
      m = key;  // the new key wins its block outright
    else if (was_block_min)
      m = block_min(b);  // the old minimum got later: rescan
    else
      return;  // neither was nor is the block's minimum: nothing above changes
    if (m == nodes_[k]) return;
    nodes_[k] = m;
    while (k > 0) {
      k = (k - 1) / 2;
      const QueueKey<T> winner = min_of_children(k);
      if (winner == nodes_[k]) return;  // nothing above can change
      nodes_[k] = winner;
    }
  }

  std::size_t memory_bytes() const {
    return (keys_.capacity() + nodes_.capacity()) * sizeof(QueueKey<T>);
  }

 private:
  std::size_t leaf(std::uint32_t block) const { return std::size_t(blocks_) - 1 + block; }
  QueueKey<T> block_min(std::uint32_t b) const {
    const QueueKey<T>* k = &keys_[std::size_t(b) * kBlock];
    std::uint32_t m = 0;
    for (std::uint32_t j = 1; j < kBlock; ++j) m = k[j] < k[m] ? j : m;
    return k[m];
  }
  QueueKey<T> min_of_children(std::size_t k) const {
    const std::size_t left = 2 * k + 1;
    return nodes_[left + (nodes_[left + 1] < nodes_[left])];
  }

  std::uint32_t blocks_ = 0;
  std::vector<QueueKey<T>> keys_;   // one per disk (plus padding to whole blocks)
  std::vector<QueueKey<T>> nodes_;  // tournament tree over block minima
};

}  // namespace ede
