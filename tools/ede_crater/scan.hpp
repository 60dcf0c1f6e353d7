// The parts of `ede-crater scan` (scan.cpp): the scan as a sweep of tools/sweep (scan_runs.cpp), and the
// table of results (scan_table.cpp).
//
// A scan is a sweep of one parameter: one run per (value, seed), each its own process (this program with
// --child K), measured there as `ede-crater LOG` measures a log, its row sent back in its row file. Every
// result is stored by the run's index, so files and tables depend on the scene, the values and the seeds
// alone, not on --jobs or on which run finished first. Rejected: a pool of the scan's own (it had one:
// in-process threads, where one crashing run ended the scan; the sweep's pool isolates runs, retries a
// killed one and reuses finished runs on a rerun) and one file for the whole scan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "crater_tool.hpp"
#include "sweep.hpp"

namespace ede::crater_tool {

struct ScanOptions {
  std::string scene, param, values_text, out_dir = "crater-scan", metric = "depth", plot;
  std::size_t seeds = 1, jobs = 0;
  std::uint64_t first_seed = 1;
  std::vector<std::string> sets;
  bool quiet = false, no_logs = false;
  long long child = -1;  // (internal) this process does run K of the scan
  MeasureOptions measure;
};

// One run's line of the table, as its process measured it.
struct ScanRow {
  std::size_t value = 0;   // index into the scan's values
  std::uint64_t seed = 0;
  std::string log;         // the log's file name in the output directory: v<value>-s<seed>.ede
  std::string run_status;  // the log's: "reached stop.energy_fraction", a collapse, "incomplete: ..."
  CraterScanRun crater;    // the metrics, when and why measured then
  double energy_fraction = 0;
};

// The scan as a sweep: its runs named v<value>-s<seed> in the output directory (logs, <name>.txt run
// summaries, <name>.json rows), measured with measure_log and the scan's measuring options.
sweep::Sweep scan_sweep(const ScanOptions& opt, const std::vector<std::string>& values);

// Every run's scene loads with its overrides (the scene loader's message, naming the value, otherwise).
Status check_scan_scenes(const sweep::Sweep& s, const std::string& param);

// Does the runs, at most `jobs` at once, and returns their rows in run order; a run without a measurement
// (failed, killed again and again, interrupted) is an error naming the first such run and why. A run that
// stalls or collapses has a complete log and is not a failure: its status goes into the table, marked.
Result<std::vector<ScanRow>> run_scan_runs(const sweep::Sweep& s, std::size_t jobs);

// A run whose end makes its crater doubtful: inelastic collapse, a non-finite number, a log cut short.
bool run_suspect(const std::string& run_status);

// What the table is made of: the values as typed and the runs' rows (in run order).
struct ScanResults {
  std::vector<std::string> values;
  std::vector<ScanRow> rows;
};

// DIR/scan.csv (one row per run) and DIR/scan-aggregate.csv (one row per value: mean and standard error).
Status write_scan_csv(const ScanResults& r, const std::string& per_run, const std::string& aggregate);
// The table on stdout: one metric (an index into crater_metric_names()) per value.
void print_scan_table(const ScanResults& r, const std::string& param, std::size_t metric);

}  // namespace ede::crater_tool
