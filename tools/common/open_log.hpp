// Opening a log in a tool: ede::Log::open, plus the warning every tool gives for a log that is not
// complete (a killed run, or damage), so a user never takes a partial log for a whole one. The tool reads
// what is there; the warning says how far that goes. Rejected: refusing incomplete logs (a killed run's
// log is worth reading).
#pragma once

#include <cstdio>
#include <string>

#include "ede/log.hpp"
#include "file_checks.hpp"

namespace ede::tools {

inline Result<Log> open_log_warning(const char* tool, const std::string& path) {
  note_input("the log", path);  // no output of this tool may replace it
  auto log = Log::open(path);
  if (log && !log.value().info().complete)
    std::fprintf(stderr, "%s: warning: %s is %s: %s\n", tool, path.c_str(),
                 log.value().info().damaged ? "DAMAGED (read up to the damage)" : "incomplete (the run did not finish)",
                 log.value().info().incomplete_reason.c_str());
  return log;
}

}  // namespace ede::tools
