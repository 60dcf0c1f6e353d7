// What the log benchmark (log_bench) and the accuracy study (accuracy_log, accuracy_engine) both measure
// about the event log: one run with or without a log, timed in a child process; what a written log is
// made of (sizes, keyframes); and seeking in it (state at arbitrary times from fresh Replays).
// Only the event loop is timed, never setup; the writer's final flush is inside the loop's last call, so
// draining its queue counts. Rejected: timing `ede-sim -o` from outside (progress, summary and setup get
// mixed in, and the compressing thread's CPU time is not separable from the event loop's).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "ede/internal/log.hpp"
#include "study/study_engine.hpp"

namespace ede::study {

constexpr int kSeekTimes = 20;
// engine.rebuild_interval = 2^40: only the rebuild at start, so that keyframe_interval alone places keyframes.
constexpr const char* kNoRebuilds = "engine.rebuild_interval=1099511627776";

// "2^20", or the number when v is not a power of two; "auto" for 0 (LogSettings' automatic interval).
std::string power_of_two(std::uint64_t v);
double seconds_since(std::chrono::steady_clock::time_point t0);

struct CpuTimes {
  double process = 0, thread = 0;  // user + system seconds: all threads, the calling thread
};
CpuTimes cpu_times();  // getrusage: RUSAGE_SELF and RUSAGE_THREAD

// One run of a scene file, with or without a log.
struct RunConfig {
  std::string label;
  std::string scene;
  std::vector<std::string> overrides;  // scene overrides (--set)
  std::uint64_t events = 0;            // stop.events, applied after `overrides` (0: theirs or the scene's)
  EngineVariant variant;                // the study's engine variant (accuracy: the contact root)
  bool log = false;
  LogSettings settings;
  // Pair collisions per disk run before the clock starts (0: time from the start). The peers' way of
  // measuring a steady segment (ede-bench peers); the log, if any, records the warm-up too.
  double warmup_collisions_per_disk = 0;
  std::string log_path;
};

struct RunResult {
  bool ok = false;
  std::string failure;
  double disks = 0, events = 0, collisions = 0, logged = 0, bytes = 0, sim_time = 0;
  double wall = 0, cycles = 0, cpu_process = 0, cpu_main = 0;
  double timed_pairs = 0;  // pair collisions inside the timed segment
  double engine_bytes = 0, peak_rss = 0;
  double cpu_worker() const { return cpu_process - cpu_main > 0 ? cpu_process - cpu_main : 0; }
};

// The run in a child process; the log (if any) stays at c.log_path for the caller to read and delete.
RunResult run_measured(const RunConfig& c);

struct LogShape {
  bool ok = false;
  std::string failure;
  double file_bytes = 0, events = 0, chunks = 0, chunk_payload = 0;
  double keyframes = 0, resumable_keyframes = 0, keyframe_payload = 0;
  LogColumnSizes columns;  // filled when asked for
};

// Sizes of a complete log; with columns_level > 0 also each column compressed alone at that level.
LogShape read_shape(const std::string& path, int columns_level);

struct SeekResult {
  bool ok = false;
  std::string failure;
  double open = 0, replay_wall = 0, replay_events = 0;
  double state_replay_wall = 0, state_replay_events = 0;  // the same events applied without per-event records
  std::vector<double> create, seek;  // per seek time
};

// Replay::seek_time at t_end (k + 0.37) / kSeekTimes, each on a fresh Replay, and two replays of every
// event from the start (the state only, as a seek applies events; and with a record per event, as
// for_each_event gives tools); in a child process.
SeekResult measure_seeks(const std::string& path);

// A log built once (timed) and sought in `repeat` times.
struct SeekRow {
  std::string label;
  std::uint64_t interval = 0;
  bool rebuilds = false;  // automatic engine rebuilds (resumable keyframes) left on
  RunResult build;
  LogShape shape;
  std::vector<SeekResult> repeats;
  std::string failure;
};

// Builds the log `build` describes, reads its shape, seeks in it `repeat` times, deletes it.
SeekRow seek_row(const RunConfig& build, const std::string& label, std::uint64_t interval, bool rebuilds, int repeat);

struct SeekStats {
  double min = 0, median = 0, max = 0;  // seconds, over the seek times (each the median over repeats)
  double create = 0;                    // a fresh Replay, median
  double replay_events_per_second = 0;        // with per-event records (for_each_event), median over repeats
  double state_replay_events_per_second = 0;  // the state only (what a seek does), median over repeats
};
SeekStats seek_stats(const SeekRow& row);

}  // namespace ede::study
