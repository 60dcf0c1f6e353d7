// What every part of a sweep shares: the loaded sweep, its runs, where results go, how to start a run's
// own process (the tool's own program with --child K), and how a run is measured.
//
// A run is done by a child process (the tool itself with the same command line and --child K), whatever
// runs the sweep: the local pool's threads and MPI's worker ranks both call execute_run, which reuses a
// finished run's row or starts the child, retries a child that died, and returns the row. A crash of one
// run (out of memory, a bug, kill -9) ends its process only. Two tools run sweeps this way: ede-sweep
// (a sweep file, the quantities of quantities.hpp) and `ede-crater scan` (one parameter, its own crater
// measurement through the `measure` hook, its files beside its CSV: runs_folder ""). Rejected: running
// in-process on threads, as ede-crater scan did (one bad run takes the sweep down; two pools to keep),
// and running ede-sim children (the quantities would need a second process per run to read the log).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "quantities.hpp"
#include "run_row.hpp"
#include "sweep_file.hpp"

namespace ede::sweep {

// What a run's measurement gets: its log (complete, closed), its summary, and whether the run was done
// by this process (false: an earlier process's run measured again, with the summary the row kept).
struct RunToMeasure {
  const PlannedRun& run;
  const std::string& log_path;
  const Log& log;
  const RunSummary& summary;
  bool fresh;
};

// A run's measurement: one value per `collect` name, and the tool's own text (RunRow::notes).
struct Measured {
  std::vector<double> values;
  std::vector<std::string> notes;
};

struct Sweep {
  SweepSpec spec;
  std::vector<PlannedRun> runs;
  std::string results;                  // the results folder
  std::string runs_folder = "runs";     // the runs' files, under `results` ("": in it)
  std::vector<std::string> child_argv;  // this program and its arguments (then --child K)
  std::string tool = "ede-sweep";       // the name in progress lines
  bool progress = true;
  bool keep_logs = true;                // false: a run's log is deleted once measured (no reuse then)
  // Empty: collect_quantities(spec.collect, ...). A tool measuring otherwise sets it in the parent and in
  // the child alike, with measured_with naming its settings: a finished run whose row was measured with
  // other settings is measured again on a rerun, not reused.
  std::function<Result<Measured>(const RunToMeasure&)> measure;
  std::string measured_with;
  // inputs_digest (sweep_inputs.hpp) when the sweep started: the children refuse to run if it changed.
  std::string inputs;
  // Called by the pools with every row so far (unfinished ones "pending") after each finished run, under
  // their lock: ede-sweep keeps its tables current with it, so a sweep killed mid-way leaves tables that
  // say which runs are missing.
  std::function<void(const std::vector<RunRow>&)> on_rows;
};

// The exit status of a child that found the sweep file or its scene changed since its parent started.
inline constexpr int kInputsChanged = 65;

// The folder of the runs' files, and a run's files in it.
std::string runs_dir(const Sweep& s);
std::string log_path(const Sweep& s, const PlannedRun& r);
std::string row_path(const Sweep& s, const PlannedRun& r);
// The log's path as the table shows it: relative to the results folder.
std::string log_cell(const Sweep& s, const PlannedRun& r);

// This process's command line as it was started (/proc/self/exe and /proc/self/cmdline): a tool's
// child_argv, so that a child sees exactly the options its parent saw.
std::vector<std::string> own_command_line();

// The child's job: run K (resuming its log if an earlier process was killed), measure it, write its row.
// Returns the process's exit status.
int run_child(const Sweep& s, std::size_t k);

// The worker's job: the row of run k, from an earlier execution if it is complete and its log's digest
// matches, else from a child process (again up to spec.retries times if it dies).
RunRow execute_run(const Sweep& s, std::size_t k);

// The row an earlier execution left for run k, if it still holds (reuse).
std::optional<RunRow> reusable_row(const Sweep& s, const PlannedRun& r);

// Run k's row before it has finished: status "pending", saying why it has no result yet.
RunRow pending_row(const Sweep& s, std::size_t k);

}  // namespace ede::sweep
