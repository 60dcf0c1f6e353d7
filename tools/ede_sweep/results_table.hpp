// The sweep's two tables: runs.csv (one row per run, in sweep order) and points.csv (per point: mean and
// standard error over its seeds' runs that ended ok), both depending on the sweep file alone: rows are
// placed by run index and numbers printed exactly (17 digits), so the number of workers, their order
// and the machine's speed change nothing except the wall_seconds column (the last, left out with
// --no-timing so that two executions can be compared byte for byte). Rejected: appending rows as runs
// finish (the order would be the workers').
#pragma once

#include <string>
#include <vector>

#include "sweep.hpp"

namespace ede::sweep {

Status write_tables(const Sweep& s, const std::vector<RunRow>& rows, bool timing);

// Counts by status for the closing line: "12 runs: 11 ok, 1 failed (3 reused)".
std::string rows_summary(const std::vector<RunRow>& rows);

}  // namespace ede::sweep
