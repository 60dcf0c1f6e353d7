// The library's replay against the reference reader (reference_reader.hpp, written from FORMAT.md alone):
// after every chunk, every disk's position, velocity, time and (rotating logs) spin must be the same bits.
// Shared by the reader, segment and rough log tests, which each write logs of their own kind.
#pragma once

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "ede/log.hpp"
#include "log_test_support.hpp"
#include "reference_reader.hpp"

namespace ede::test {

// a and b are the same bits (the width the log stores: long double's padding does not count).
template <class T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, reference::kWidth<T>) == 0;
}

// Compares after every chunk; returns the events compared up to (the log's total when all went well).
template <class T>
std::uint64_t compare_with_reference(const std::string& path) {
  auto log = open_log(path);
  auto fast = replay_of<T>(path);
  reference::Reader<T> ref(*log);
  const bool spins = log->header().rotation();
  std::uint64_t checked = 0;
  ref.run([&](std::uint64_t events, const std::vector<reference::Record<T>>& records) {
    REQUIRE(fast->seek_event(events));
    const Particles<T>& p = fast->particles();
    for (std::size_t i = 0; i < records.size(); ++i) {
      const Disk<T>& d = p.disk[i];
      const reference::Record<T>& r = records[i];
      INFO("event " << events << ", disk " << i);
      REQUIRE((same_bits(d.x, r.x) && same_bits(d.y, r.y) && same_bits(d.vx, r.vx) && same_bits(d.vy, r.vy) &&
               same_bits(d.t, r.t) && (!spins || same_bits(p.omega[i], r.w))));
    }
    checked = events;
  });
  return checked;
}

// A run's log, in the scalar type its scene names ("float", "double", "long double"), decodes to the same
// bits with the library and the reference reader to its last event, and a re-run verifies it (at least
// two resumable keyframes checked on the way).
inline void check_exact_and_verified(const std::string& path, const std::string& scalar) {
  const std::uint64_t total = open_log(path)->total_events();
  if (scalar == "double") CHECK(compare_with_reference<double>(path) == total);
  if (scalar == "float") CHECK(compare_with_reference<float>(path) == total);
  if (scalar == "long double") CHECK(compare_with_reference<long double>(path) == total);
  const auto verified = Log::open(path).value().verify();
  REQUIRE(verified.ok());
  INFO(verified.value().text);
  CHECK(verified.value().identical);
  CHECK(verified.value().resumable_checked >= 2);
}

}  // namespace ede::test
