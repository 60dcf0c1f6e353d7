// One run's row of the results table, and its file beside the run's log (runs/<name>.json).
//
// The row file is what makes a run done: the child process writes it (atomically: a temporary file then a
// rename) only after the log is closed and measured, with the log's content digest; a rerun reuses the
// row when the log's digest still matches. It is also what a worker sends to rank 0 under MPI, as text, so
// the table never needs the workers' file system. JSON (nlohmann-json, already a dependency) keeps NaN as
// null and doubles as their shortest round trip. Rejected: a CSV line per run (quoting, and the
// parameters' TOML text holds commas) and Cap'n Proto (a schema for eight fields).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/simulation.hpp"

namespace ede::sweep {

struct RunRow {
  std::size_t index = 0;
  std::string name;
  std::vector<std::string> overrides;  // what defines the run (checked on reuse)
  std::vector<std::string> collect;    // the quantities' names (a changed `collect` is measured again)
  std::vector<double> values;          // one per collected quantity (NaN: none)
  std::vector<std::string> notes;      // text a tool's own measurement adds (ede-crater scan: the log's status)
  std::string measured_with;           // the measuring settings besides `collect` (Sweep::measured_with)
  std::string status;                  // ok, a run status (stalled, collapsed, ...), failed, timeout, killed
  std::string error;                   // why, when status is not ok
  double wall_seconds = 0;             // the run's process, start to row written
  std::string log;                     // relative to the results folder
  std::string digest;                  // the log's content digest (empty without a complete log)
  std::string summary;                 // the run summary's fields the quantities use, as JSON (summary_to_json)
  bool reused = false;                 // not written: this execution reused an earlier row
};

// The run summary's fields that quantities read (counts, collisions per disk, times, energies), so that a
// finished run is measured again for a changed `collect` without running it again.
std::string summary_to_json(const RunSummary& s);
Result<RunSummary> summary_from_json(const std::string& text);

std::string row_to_json(const RunRow& row);
Result<RunRow> row_from_json(const std::string& text, const std::string& where);
Status write_row_file(const std::string& path, const RunRow& row);
Result<RunRow> read_row_file(const std::string& path);

// Statuses that are the run's own outcome (deterministic): a rerun keeps them. Others are retried.
bool final_status(const std::string& status);

}  // namespace ede::sweep
