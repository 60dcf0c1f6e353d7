// Other processes, one way for the whole tree: a program run to its end (python3 for figures, ffmpeg for
// movies, a sweep's ede-sim runs, with a deadline) and a function run in a forked child (the benchmarks'
// measurements). Both are waited for with wait4, which also gives the child's own peak memory.
//
// Programs start with posix_spawn, the C library's well-kept API for it: no shell (arguments go to the
// program as they are, so file names with spaces or quotes are safe), no fork in a threaded process
// (posix_spawn does exactly the async-signal-safe part), and a program that cannot be executed is an error
// of the call itself, not a mysterious exit status 127. The child's stdin is /dev/null (ffmpeg would
// otherwise read keystrokes), its stdout goes to a file or /dev/null, its stderr to a file or back to
// the caller through a pipe. With a deadline the child is polled every few milliseconds and stopped past
// it (SIGTERM: an ede-sim run stops at its next check and keeps a resumable log; SIGKILL a second later).
// run_in_child forks without exec, for a measurement in a single-threaded process: its heap is clean and
// its peak memory its own, and a crash or an exhausted machine cannot take the whole benchmark down.
// Rejected: three spawners (tools, sweeps, benchmarks), each with its own waiting and status decoding;
// fork + exec by hand; system() (a shell between us and the file names); a SIGCHLD handler (a sweep's
// pool threads each wait for their own child).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::tools {

// How a child ended.
struct ProcessEnd {
  int exit_status = 0;  // its exit status, or 128 + the signal that ended it
  bool signalled = false;
  bool timed_out = false;  // stopped past the deadline
  double wall_seconds = 0;
  std::uint64_t peak_rss_bytes = 0;  // its own peak resident memory
};

struct SpawnRequest {
  std::vector<std::string> argv;  // argv[0]: the program, a path or (search_path) a name on PATH
  bool search_path = false;       // look argv[0] up on PATH (posix_spawnp)
  std::string stdout_path;        // where the child's stdout goes; empty: /dev/null
  std::string stderr_path;        // where its stderr goes; empty: back to the caller (SpawnResult::err)
  double timeout = 0;             // seconds; 0: none
};

struct SpawnResult : ProcessEnd {
  std::string err;  // what it wrote to stderr (when not to a file)
};

// Runs the program to its end. Fails only if it could not be started or waited for (the error says why).
Result<SpawnResult> run_program(const SpawnRequest& request);

// Stops every program run_program is waiting for (SIGTERM), e.g. after Ctrl-C of a sweep. Async-signal-safe.
void terminate_children();

// The full path of an executable `name` on PATH, if there is one.
std::optional<std::string> find_program(const std::string& name);

struct ChildResult : ProcessEnd {
  bool ok = false;      // exited with status 0
  std::string output;   // what the child sent back
  std::string failure;  // why not ok
};

// Runs `body` in a forked child; `body` returns the exit status and fills the text to send back.
ChildResult run_in_child(const std::function<int(std::string& output)>& body);

}  // namespace ede::tools
