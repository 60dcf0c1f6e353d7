// The parts of `ede-crater scan` (scan.cpp): the runs, in-process on a few threads (scan_runs.cpp), and the
// table of results (scan_table.cpp).
//
// A scan is a list of runs, one per (value, seed), each a scene loaded with its overrides; every result is
// stored by the run's index, so files and tables depend on the scene, the values and the seeds alone, not
// on --jobs or on which run finished first. Rejected: one file for the whole scan (it mixed options,
// processes and tables in 300 lines).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "crater_tool.hpp"

namespace ede::crater_tool {

struct ScanRun {
  std::size_t value = 0;  // index into the scan's values
  std::uint64_t seed = 0;
  std::string name;       // file name stem in the output directory: v<value>-s<seed>
  std::string label;      // for messages: "KEY=VALUE, seed S"
  Scene scene;            // loaded with every override of this run
};

// Runs every scene with ede::Simulation, writing DIR/<name>.ede (the log) and DIR/<name>.txt (the run's
// summary), at most `jobs` at once on std::thread workers, and measures each log as soon as its run ended
// (measure_log, as `ede-crater LOG` does); without keep_logs the log is deleted once measured, so a scan
// needs the disk of `jobs` logs, not of all of them. After a run fails no further run starts; the error is
// the first failed run's (in run order). A run that stalls or collapses has a complete log and is not a
// failure: its status goes into the table, marked (run_suspect).
Result<std::vector<MeasuredLog>> run_scans(const std::vector<ScanRun>& runs, const std::string& dir, std::size_t jobs,
                                           bool progress, const MeasureOptions& measure, bool keep_logs);

// A run whose end makes its crater doubtful: inelastic collapse, a non-finite number, a log cut short.
bool run_suspect(const std::string& run_status);

// What the table is made of: the values as typed, the runs, each run's measurement (same order).
struct ScanResults {
  std::vector<std::string> values;
  std::vector<ScanRun> runs;
  std::vector<MeasuredLog> measured;
};

// DIR/scan.csv (one row per run) and DIR/scan-aggregate.csv (one row per value: mean and standard error).
Status write_scan_csv(const ScanResults& r, const std::string& per_run, const std::string& aggregate);
// The table on stdout: one metric (an index into crater_metric_names()) per value.
void print_scan_table(const ScanResults& r, const std::string& param, std::size_t metric);

}  // namespace ede::crater_tool
