// ede-bench log: what the event log costs. Bytes per event for scenes and where they go (per column),
// the zstd level, the logging overhead (log off vs on in one invocation: wall time, main-thread cycles,
// CPU time of both threads), and seeking (state at arbitrary times from fresh Replays) for several
// keyframe intervals, with replay throughput against the simulation's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ede::bench {

struct LogBenchOptions {
  std::vector<std::string> scenes;        // bytes per event and overhead for each
  std::string reference;                  // the scene of the level, overhead and seek measurements
  int repeat = 3;
  std::uint64_t events = 0;               // 0: each scene's own stop.events
  std::uint64_t seek_events = 10000000;   // engine events (stop.events) of the logs built for seeking
  bool skip_seek = false;
  std::vector<int> levels = {1, 3, 6, 9, 19};
  std::string csv_prefix;                 // PREFIX-scenes.csv, -columns.csv, -levels.csv, -seek.csv
  std::string out_dir = "/tmp/ede-bench-log";
};

// The default scenes and reference (relative to the repository root, where the docs run the benchmark).
std::vector<std::string> default_log_bench_scenes();
std::string default_log_bench_reference();

int run_log_bench(const LogBenchOptions& options);

}  // namespace ede::bench
