// Fuzz target: the event queue against a simple reference model.
//
// Bytes drive a sequence of set(disk, time, kind) operations, some of them "pops" (the top's key moved to
// a later time, as the engine does after processing it). After every operation the queue's top must be
// the reference's minimum under the total order (time, kind, disk), and pops must come in non-decreasing
// time. Times are drawn from a small set so that ties are frequent.
// The harness returns false on a violated check; the fuzz target traps on it, the test suite fails.
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

#include "engine/event_queue.hpp"
#include "core/geometry.hpp"

namespace ede::fuzz {

inline bool fuzz_queue(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return true;
  const std::uint32_t n = 1 + data[0] % 200;
  ede::EventQueue<double> queue(n);
  std::vector<ede::QueueKey<double>> current(n);
  std::set<std::pair<double, std::uint32_t>> reference;
  for (std::uint32_t i = 0; i < n; ++i) {
    current[i] = {ede::kNever<double>, ede::make_tag(ede::EventKind::Pair, i)};
    reference.insert({current[i].time, current[i].tag});
  }
  double last_pop = -1;
  const auto set = [&](std::uint32_t i, double t, ede::EventKind kind) {
    reference.erase({current[i].time, current[i].tag});
    current[i] = {t, ede::make_tag(kind, i)};
    reference.insert({t, current[i].tag});
    queue.set(i, t, kind);
  };
  for (std::size_t k = 1; k + 2 < size; k += 3) {
    const std::uint8_t op = data[k], a = data[k + 1], b = data[k + 2];
    if (op % 4 == 0) {  // pop: the earliest disk's next event comes later
      const ede::QueueKey<double> top = queue.top();
      if (top.time == ede::kNever<double>) continue;
      if (top.time < last_pop) return false;
      last_pop = top.time;
      set(ede::tag_disk(top.tag), top.time + 1 + b % 8, static_cast<ede::EventKind>(a % 4));
    } else {
      const double t = b == 255 ? ede::kNever<double> : std::max(last_pop, 0.0) + double(b % 16) / 4;
      set(a % n, t, static_cast<ede::EventKind>(op % 4));
    }
    const ede::QueueKey<double> top = queue.top();
    if (top.time != reference.begin()->first || top.tag != reference.begin()->second) return false;
  }
  return true;
}

}  // namespace ede::fuzz
