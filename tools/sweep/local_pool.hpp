// Running a sweep's runs on this machine: `jobs` threads, each taking the next run by index and waiting
// for its child process (execute_run); rows are stored by index, so nothing depends on which run ends
// first. Threads only wait here; the work is in the children. Rejected: one process per worker slot with
// its own event loop (a thread blocked in waitpid is the simplest correct pool).
#pragma once

#include <vector>

#include "sweep.hpp"

namespace ede::sweep {

std::vector<RunRow> run_local(const Sweep& s, std::size_t jobs);

// "ede-sweep: 3/12 p001-s2 ok (0.42 s)" on stderr, one line per run (shared by both pools).
void report_run(const Sweep& s, const RunRow& row, std::size_t done);

}  // namespace ede::sweep
