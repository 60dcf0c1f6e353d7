// The tournament-tree queue against a simple reference (std::set of keys), on random operation sequences.
#include <catch2/catch.hpp>
#include <cstdint>
#include <set>
#include <vector>

#include "engine/event_queue.hpp"
#include "core/geometry.hpp"

using namespace ede;

namespace {
std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
}  // namespace

TEST_CASE("EventQueue: the top is always the reference's minimum, ties by (time, kind, disk)", "[queue]") {
  for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 1000u}) {
    EventQueue<double> q(n);
    std::vector<QueueKey<double>> current(n);
    std::set<std::pair<double, std::uint32_t>> ref;
    for (std::uint32_t i = 0; i < n; ++i) {
      current[i] = {kNever<double>, make_tag(EventKind::Pair, i)};
      ref.insert({current[i].time, current[i].tag});
    }
    std::uint64_t seed = n;
    for (int step = 0; step < 20000; ++step) {
      const std::uint32_t i = std::uint32_t(splitmix(seed) % n);
      // Few distinct times, so ties between disks and kinds are common.
      const double t = step % 10 == 0 ? kNever<double> : double(splitmix(seed) % 50) / 8;
      const EventKind kind = static_cast<EventKind>(splitmix(seed) % 4);
      ref.erase({current[i].time, current[i].tag});
      current[i] = {t, make_tag(kind, i)};
      ref.insert({t, current[i].tag});
      q.set(i, t, kind);
      REQUIRE(q.top().time == ref.begin()->first);
      REQUIRE(q.top().tag == ref.begin()->second);
      REQUIRE(q.key_of(i) == current[i]);
    }
  }
}

TEST_CASE("EventQueue: popping in order yields non-decreasing times", "[queue]") {
  const std::uint32_t n = 500;
  EventQueue<double> q(n);
  std::uint64_t seed = 99;
  for (std::uint32_t i = 0; i < n; ++i) q.set(i, double(splitmix(seed) % 1000), EventKind::Pair);
  double last = -1;
  for (std::uint32_t k = 0; k < n; ++k) {
    const QueueKey<double> top = q.top();
    REQUIRE(top.time >= last);
    last = top.time;
    q.set(tag_disk(top.tag), kNever<double>, EventKind::Pair);  // "pop"
  }
  CHECK(q.top().time == kNever<double>);
}
