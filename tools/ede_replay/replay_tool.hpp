// What the ede-replay subcommands share: registration, messages, exact numbers.
//
// Each subcommand lives in its own file and registers itself on the CLI11 app with add_*_command, which
// returns the function main calls once the command line is parsed. The work is the library's (ede::Log);
// these files parse, call and print. Times a user types are read exactly in the log's scalar type.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <string>

#include "ede/ede.hpp"
#include "report_error.hpp"

namespace ede::replay_tool {

using Command = std::function<int()>;

Command add_state_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_events_command(CLI::App& app);
Command add_verify_command(CLI::App& app);
Command add_diff_command(CLI::App& app);

// An error about the input: message on stderr, exit status 1.
inline int fail(const std::string& message) {
  ede::tools::report_error("ede-replay", message);
  return 1;
}

// A command line that parsed but asks for something impossible: exit status 2, like a parse error.
inline int usage_error(const std::string& message) {
  std::fprintf(stderr, "ede-replay: %s (see ede-replay --help)\n", message.c_str());
  return 2;
}

// Opens a log; a log that is not complete (a killed run, or damage) gets a warning on stderr, so a user
// never takes a partial log for a whole one.
inline Result<Log> open_log(const std::string& path) {
  auto log = Log::open(path);
  if (log && !log.value().info().complete)
    std::fprintf(stderr, "ede-replay: warning: %s is %s: %s\n", path.c_str(),
                 log.value().info().damaged ? "DAMAGED (read up to the damage)" : "incomplete (the run did not finish)",
                 log.value().info().incomplete_reason.c_str());
  return log;
}

// A time given on the command line, read exactly in the log's scalar type: one finite number >= 0.
inline Result<Time> parse_time(const Log& log, const std::string& text, const char* what) {
  auto v = parse_exact(text, log.info().scalar);
  if (!v) return Error{std::string(what) + " '" + text + "' is not a number (a time such as 0.5 or 1e-3)"};
  if (v.value() < 0) return Error{std::string(what) + " '" + text + "' is negative"};
  return v;
}

// The exact text of a value of the log.
inline std::string exact(const Log& log, Time v) { return exact_text(v, log.info().scalar); }

}  // namespace ede::replay_tool
