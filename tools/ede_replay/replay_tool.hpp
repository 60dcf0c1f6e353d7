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
#include "open_log.hpp"
#include "report_error.hpp"
#include "time_option.hpp"

namespace ede::replay_tool {

using Command = std::function<int()>;

Command add_state_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_events_command(CLI::App& app);
Command add_verify_command(CLI::App& app);
Command add_diff_command(CLI::App& app);
Command add_export_command(CLI::App& app);
Command add_convert_command(CLI::App& app);

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

inline Result<Log> open_log(const std::string& path) { return tools::open_log_warning("ede-replay", path); }

// A time bounding a range (events --from/--to), read exactly in the log's scalar type: one finite number
// >= 0, which may lie beyond the log (the range is then empty). --at goes through tools::read_time.
inline Result<Time> parse_time(const Log& log, const std::string& text, const char* what) {
  auto v = parse_exact(text, log.info().scalar);
  if (!v) return Error{std::string(what) + " '" + text + "' is not a number (a time such as 0.5 or 1e-3)"};
  if (v.value() < 0) return Error{std::string(what) + " '" + text + "' is negative"};
  return v;
}

// The exact text of a value of the log.
inline std::string exact(const Log& log, Time v) { return exact_text(v, log.info().scalar); }

}  // namespace ede::replay_tool
