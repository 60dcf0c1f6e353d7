// Opening a log in a tool: LogReader::open, plus the warning every tool gives for a log that is not
// complete (a killed run, or damage), so a user never takes a partial log for a whole one. The tool reads
// what is there; the warning says how far that goes.
#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "log/log_reader.hpp"

namespace ede::tools {

inline Result<std::shared_ptr<LogReader>> open_log_warning(const char* tool, const std::string& path) {
  auto log = LogReader::open(path);
  if (log && !log.value()->complete())
    std::fprintf(stderr, "%s: warning: %s is %s: %s\n", tool, path.c_str(),
                 log.value()->damaged() ? "DAMAGED (read up to the damage)" : "incomplete (the run did not finish)",
                 log.value()->incomplete_reason().c_str());
  return log;
}

}  // namespace ede::tools
