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

TEST_CASE("EventQueue::visit_ahead names the next events, each once, before they are due", "[queue]") {
  // A steady queue like the engine's: each popped disk gets a new time a random distance ahead (mean 1 per
  // disk). visit_ahead(3) is called before every pop, as the engine does: the disk popped must nearly
  // always have been named by an earlier call (the prefetch is useful), a visited disk must be due at or
  // after the current top (it is ahead, not behind), and no disk is named twice for one key.
  const std::uint32_t n = 100000;
  EventQueue<double> q(n);
  std::uint64_t seed = 7;
  const auto ahead = [&]() { return double(splitmix(seed) >> 11) * 0x1.0p-53 * 2.0; };
  for (std::uint32_t i = 0; i < n; ++i) q.set(i, ahead(), EventKind::Pair);
  std::vector<std::uint8_t> named(n, 0);
  std::uint64_t pops = 0, named_before = 0, named_twice = 0, named_behind = 0;
  for (int step = 0; step < 400000; ++step) {
    const QueueKey<double> top = q.top();
    q.visit_ahead(3, [&](std::int32_t d) {
      named_twice += named[std::size_t(d)];
      named[std::size_t(d)] = 1;
      named_behind += q.key_of(std::uint32_t(d)).time < top.time;
    });
    const std::uint32_t d = tag_disk(top.tag);
    if (step >= 200000) {  // after the first years: the steady state
      ++pops;
      named_before += named[d];
    }
    named[d] = 0;  // a new key: it may be named again
    q.set(d, top.time + ahead(), EventKind::Pair);
  }
  INFO("named before their pop: " << named_before << " of " << pops);
  CHECK(double(named_before) > 0.9 * double(pops));
  CHECK(named_twice == 0);
  CHECK(named_behind == 0);
}
