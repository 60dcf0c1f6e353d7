// The growth loop's event queue: one pending event per disk, an indexed binary min-heap on (time, disk id).
//
// Each disk's slot holds its earliest predicted event; re-predicting a disk moves its slot up or down. The
// order is total (ties by id), so the loop is deterministic. Rejected: a heap of every predicted pair event
// with lazy deletion (larger, and stale entries pile up near jamming, where a disk re-predicts constantly).
#pragma once

#include <cstdint>
#include <vector>

namespace ede::setup_detail {

class GrowQueue {
 public:
  explicit GrowQueue(const std::vector<double>& times) : t_(&times) {}

  void build(std::uint32_t n) {
    heap_.resize(n);
    pos_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) heap_[i] = pos_[i] = i;
    for (std::uint32_t k = n / 2; k-- > 0;) down(k);
  }
  std::uint32_t top() const { return heap_[0]; }
  void update(std::uint32_t i) {  // disk i's time changed
    up(pos_[i]);
    down(pos_[i]);
  }

 private:
  bool less(std::uint32_t a, std::uint32_t b) const {
    const double ta = (*t_)[a], tb = (*t_)[b];
    return ta < tb || (ta == tb && a < b);
  }
  void place(std::uint32_t k, std::uint32_t i) {
    heap_[k] = i;
    pos_[i] = k;
  }
  void up(std::uint32_t k) {
    const std::uint32_t i = heap_[k];
    while (k > 0) {
      const std::uint32_t parent = (k - 1) / 2;
      if (!less(i, heap_[parent])) break;
      place(k, heap_[parent]);
      k = parent;
    }
    place(k, i);
  }
  void down(std::uint32_t k) {
    const std::uint32_t n = std::uint32_t(heap_.size());
    const std::uint32_t i = heap_[k];
    for (;;) {
      std::uint32_t child = 2 * k + 1;
      if (child >= n) break;
      if (child + 1 < n && less(heap_[child + 1], heap_[child])) ++child;
      if (!less(heap_[child], i)) break;
      place(k, heap_[child]);
      k = child;
    }
    place(k, i);
  }

  const std::vector<double>* t_;
  std::vector<std::uint32_t> heap_, pos_;
};

}  // namespace ede::setup_detail
