// Statistics of an event log that need no replay: how many events of each kind it holds.
//
// Only the `kinds` column of each chunk is read (one byte per event), so a summary of a large log costs
// one decompression per chunk and no state at all. Rejected: counting through Replay, which would decode
// every velocity and apply every event to answer a question about bytes the log already stores as such.
#pragma once

#include <cstdint>
#include <vector>

#include "core/event.hpp"
#include "log/log_reader.hpp"
#include "ede/error.hpp"

namespace ede {

struct LogKindCounts {
  std::uint64_t by_kind[kEventKindCount] = {};
  std::uint64_t chunks_read = 0;

  std::uint64_t of(EventKind k) const { return by_kind[static_cast<int>(k)]; }
  std::uint64_t total() const {
    std::uint64_t n = 0;
    for (const std::uint64_t c : by_kind) n += c;
    return n;
  }
};

// The events of every chunk the reader lists, counted by kind. Fails (naming the file and the chunk's
// byte offset) if a chunk cannot be read, its kinds column does not hold one byte per event, or a byte
// is not a kind a log may hold (pair, wall, wrap, action).
Result<LogKindCounts> count_logged_kinds(const LogReader& log);

// For each target P in `pairs` (ascending), the number of events up to and including the log's P-th pair
// collision (0 for P = 0): the state after that many events is the state right after that collision.
// From the kinds columns alone, in one pass that stops at the last target. Fails if the log holds fewer
// pair collisions than a target.
Result<std::vector<std::uint64_t>> events_through_pairs(const LogReader& log, const std::vector<std::uint64_t>& pairs);

}  // namespace ede
