// Running a measurement in a forked child: its peak memory is its own (wait4's rusage), a crash or an
// exhausted machine cannot take the whole benchmark down, and every run starts from a clean heap.
// The child writes its result as text to a pipe; the parent gets that text, the exit status and rusage.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace ede::study {

struct ChildResult {
  bool ok = false;             // exited with status 0
  std::string output;          // what the child wrote
  std::string failure;         // why not ok
  std::uint64_t peak_rss_bytes = 0;
};

// Runs `body` in a child process; `body` returns the text to send back and the exit status.
ChildResult run_in_child(const std::function<int(std::string& output)>& body);

}  // namespace ede::study
