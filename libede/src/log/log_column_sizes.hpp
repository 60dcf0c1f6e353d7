// Where the bytes of an event log go: each chunk column's size, decompressed and compressed on its own.
//
// A chunk is compressed as one zstd frame, so the file itself cannot say how much each column costs.
// This decompresses the chunks and compresses every column alone at the level given (normally the one
// the log was written with): the per-column figures are an estimate of each column's share whose sum
// lands near the real payload (joint compression shares a little context between columns). For
// benchmarks and format work (ede-bench log); reading a log never needs it.
// Rejected: instrumenting the writer (it would cost every run something to answer a benchmark's question).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "log/log_reader.hpp"
#include "ede/error.hpp"

namespace ede {

struct LogColumnSize {
  std::string name;              // as in schema/ede_log.capnp: times, kinds, disks, partners, ...
  std::uint64_t bytes = 0;       // decompressed, summed over the chunks
  std::uint64_t compressed = 0;  // each chunk's column compressed alone, summed
};

struct LogColumnSizes {
  std::uint64_t chunks = 0, events = 0;  // chunks examined and the events they hold
  std::uint64_t payload = 0;             // their zstd frames as stored in the file
  std::uint64_t message = 0;             // their decompressed Cap'n Proto messages (columns + framing)
  std::vector<LogColumnSize> columns;    // the Chunk message's Data fields, in schema order
};

// Examines every chunk of `log`, or, with max_chunks > 0, that many spread evenly over the log.
Result<LogColumnSizes> log_column_sizes(const LogReader& log, int zstd_level, std::size_t max_chunks = 0);

}  // namespace ede
