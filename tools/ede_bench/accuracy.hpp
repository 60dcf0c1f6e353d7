// ede-bench accuracy: what accuracy costs in time. The same scenes (examples/accuracy) under different
// settings (scalar type; stable or textbook contact root; a time-stepped simulation at several dt; the log
// off, on, and its keyframe interval), each giving its cost (ns per event, or CPU seconds) and the errors
// it leaves (energy drift, largest overlap, time reversal, divergence of runs one ulp apart, collision
// rate and cooling curve, seek time, bytes per event). Writes CSV tables, a Markdown table and a figure
// into one folder; the definitions are in docs/accuracy.md.
#pragma once

#include <cstdint>
#include <string>

namespace ede::bench {

struct AccuracyOptions {
  std::string out_dir = "docs/accuracy";        // CSV, tables.md and accuracy.png
  std::string scenes_dir = "examples/accuracy";
  std::uint64_t events = 10000000;               // engine events of the drift and overlap runs
  std::uint64_t timing_events = 2000000;         // engine events of each timed run
  int repeat = 5;
  bool quick = false;                            // a smoke run of well under a minute (tests)
  bool plot = true;
  std::string tmp_dir = "/tmp/ede-bench-accuracy";
};

int run_accuracy(const AccuracyOptions& options);

}  // namespace ede::bench
