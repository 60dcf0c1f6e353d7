// Running another program from a tool (python3 for figures, ffmpeg for movies): posix_spawn, the C
// library's well-kept API for it, with file actions for the child's standard streams.
//
// No shell: arguments go to the program as they are, so file names with spaces or quotes are safe. The
// child's stdin is /dev/null (ffmpeg would otherwise read keystrokes), its stdout goes to a file or
// /dev/null, and its stderr is captured through a pipe for the error message. posix_spawn reports a
// program that cannot be executed as an error of the call itself, not as a mysterious exit status 127.
// Rejected: fork + exec by hand (three copies of it existed, each with its own mistakes about what a child
// may do between the two) and system() (a shell between us and the file names).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::tools {

struct SpawnRequest {
  std::vector<std::string> argv;  // argv[0]: the program, a path or (search_path) a name on PATH
  bool search_path = false;       // look argv[0] up on PATH (posix_spawnp)
  std::string stdout_path;        // where the child's stdout goes; empty: /dev/null
};

struct SpawnResult {
  int exit_status = 0;  // the child's exit status, or 128 + the signal that killed it
  std::string err;      // what it wrote to stderr
};

// Runs the program to its end. Fails only if it could not be started (the error says why).
Result<SpawnResult> run_program(const SpawnRequest& request);

// The full path of an executable `name` on PATH, if there is one.
std::optional<std::string> find_program(const std::string& name);

}  // namespace ede::tools
