// What every part of ede-sweep shares: the loaded sweep, its runs, where results go, and how to start a
// run's own process (this same program with --child K).
//
// A run is done by a child process (`ede-sweep SWEEP --child K`, with the sweep's own --set and
// --out-dir), whatever runs the sweep: the local pool's threads and MPI's worker ranks both call
// execute_run, which reuses a finished run's row or starts the child, retries a child that died, and
// returns the row. A crash of one run (out of memory, a bug, kill -9) ends its process only. Rejected:
// running in-process on threads as ede-crater scan does (one bad run takes the sweep down) and running
// ede-sim children (the quantities would need a second process per run to read the log).
#pragma once

#include <string>
#include <vector>

#include "quantities.hpp"
#include "run_row.hpp"
#include "sweep_file.hpp"

namespace ede::sweep {

struct Sweep {
  SweepSpec spec;
  std::vector<PlannedRun> runs;
  std::string results;                  // the results folder
  std::vector<std::string> child_argv;  // this program, the sweep file, --out-dir, --set ... (then --child K)
  bool progress = true;
};

// The folder of the runs' files, and a run's files in it.
std::string runs_dir(const Sweep& s);
std::string log_path(const Sweep& s, const PlannedRun& r);
std::string row_path(const Sweep& s, const PlannedRun& r);

// The child's job: run K (resuming its log if an earlier process was killed), measure it, write its row.
// Returns the process's exit status.
int run_child(const Sweep& s, std::size_t k);

// The worker's job: the row of run k, from an earlier execution if it is complete and its log's digest
// matches, else from a child process (again up to spec.retries times if it dies).
RunRow execute_run(const Sweep& s, std::size_t k);

// The row an earlier execution left for run k, if it still holds (reuse).
std::optional<RunRow> reusable_row(const Sweep& s, const PlannedRun& r);

}  // namespace ede::sweep
