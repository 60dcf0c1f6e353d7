// The event-log benchmark (ede-bench log): what the event log costs. Bytes per event for scenes and where
// they go (per column), the zstd level, the logging overhead (log off vs on: wall time, main-thread cycles,
// CPU time of both threads), and seeking (state at arbitrary times from fresh Replays) for several
// keyframe intervals, with replay throughput against the simulation's. ede-bench prints the tables.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "study/log_measure.hpp"

namespace ede::study {

struct LogBenchPlan {
  std::vector<std::string> scenes;       // bytes per event and overhead for each
  std::string reference;                 // the scene of the level, overhead and seek measurements
  int repeat = 3;
  std::vector<std::string> overrides;    // --set key=value, applied to every scene
  std::uint64_t seek_events = 10000000;  // engine events (stop.events) of the logs built for seeking
  bool skip_seek = false;
  std::vector<int> levels = {1, 3, 6, 9, 19};
  std::string tmp_dir = "/tmp/ede-bench-log";  // where the logs go (deleted as soon as read)
  std::uint32_t format_version = 2;      // of every log written (1: the version 1 columns, for comparison)
};

// The default scenes and reference (relative to the repository root, where the docs run the benchmark).
std::vector<std::string> default_log_bench_scenes();
std::string default_log_bench_reference();

// The results of one configuration over the repeats, and the shape of its log.
struct Series {
  RunConfig config;
  std::vector<RunResult> runs;
  LogShape shape;
  std::string failure;
  bool sizes_differ = false;  // the log's size differed between repeats (it must not)

  bool ok() const { return failure.empty() && !runs.empty(); }
  const RunResult& first() const { return runs.front(); }
  double median_of(double (*f)(const RunResult&)) const;
  double wall() const;
  double cycles() const;
  double cpu_process() const;
  double cpu_main() const;
  double cpu_worker() const;
};

double wall_of(const RunResult& r);
double cpu_of(const RunResult& r);
// The median over repeats of (this run / the baseline's run of the same repeat).
double paired_ratio(const Series& s, const Series& base, double (*f)(const RunResult&));

struct LogBenchResults {
  std::vector<Series> scenes;   // per scene: log off, log on (default settings)
  std::vector<Series> ref;      // the reference scene: log off, each level (the default among them), keyframes 2^14
  std::vector<Series> sim;      // the seek logs' run without a log
  std::vector<SeekRow> seeks;   // keyframe every 2^16 ... 2^22 logged events, then the defaults
  bool ok() const;
};

// Runs every configuration, each run in its own child; the logs are read and deleted as it goes.
Result<LogBenchResults> run_log_bench(const LogBenchPlan& plan);

}  // namespace ede::study
