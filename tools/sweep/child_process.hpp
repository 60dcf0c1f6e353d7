// A run's own process: started with posix_spawn, waited for with a deadline.
//
// tools/common/spawn.hpp runs a program to its end; a sweep also needs a deadline (a stalled run is
// stopped and recorded, not waited for forever), so this starts the child and, with a deadline, polls
// waitpid(WNOHANG) every few milliseconds until it ends or the deadline passes (without one it blocks in
// waitpid) (then SIGTERM: the run stops at its next
// check and keeps a resumable log; SIGKILL a second later if it has not ended). The child's stderr goes to
// a file beside its log, stdout to /dev/null. Rejected: fork in a threaded process (only async-signal-safe
// calls are allowed in the child; posix_spawn does exactly the safe part) and a SIGCHLD handler (the pool's
// threads each wait for their own child).
#pragma once

#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::sweep {

struct ChildEnd {
  int exit_status = 0;  // the exit status, or 128 + the signal that ended it
  bool signalled = false;
  bool timed_out = false;
  double wall_seconds = 0;
};

// Runs argv[0] (a path) with argv, stderr to stderr_path; timeout 0: none.
Result<ChildEnd> run_child_process(const std::vector<std::string>& argv, const std::string& stderr_path, double timeout);

// Stops every child still running (SIGTERM), e.g. after Ctrl-C of the sweep. Async-signal-safe.
void terminate_children();

// Ctrl-C or SIGTERM of the sweep: no run starts or is retried after it, running children are stopped
// (their logs stay resumable), and the tables hold what finished. install_stop_handler sets that up.
void install_stop_handler();
bool stop_requested();
int stop_signal();

}  // namespace ede::sweep
