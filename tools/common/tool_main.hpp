// The frame around every tool's main: what escapes it becomes one clear message and a documented exit
// status instead of an abort, and stdout is checked at the end.
//
// Out of memory (std::bad_alloc, from anywhere on the main thread) prints how much the process had taken
// and the limit it ran into, and exits 1; an ede::Exception prints its message (exit 1); anything else is
// reported as an internal error (exit 1) rather than std::terminate's exit 134. Finally stdout is flushed
// and checked: `--json > /dev/full` is an error naming <stdout>, not a silent exit 0. Rejected: a
// try/catch in each tool (eight copies, and the one forgotten is the one that aborts) and an atexit
// handler for stdout (it cannot change the exit status cleanly).
#pragma once

#include <cstdint>
#include <string>

namespace ede::tools {

// Runs body(argc, argv) inside the frame; returns the exit status for main to return.
int run_tool(const char* tool, int (*body)(int, char**), int argc, char** argv);

// "out of memory: ..." with the process's peak and its limits (ulimit -v, the cgroup's, the machine's).
std::string out_of_memory_message(const std::string& doing);

// The address-space limit (RLIMIT_AS) and the memory the machine has available, in bytes (0: unknown or
// unlimited); the smaller of the two that are known, for checks before a big allocation.
std::uint64_t memory_available_bytes();

}  // namespace ede::tools
