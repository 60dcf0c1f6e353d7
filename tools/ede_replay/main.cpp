// ede-replay: what an event log holds, without rerunning the physics (except `verify`, whose job it is).
//
//   ede-replay LOG --at T|end [--csv] [-o FILE]      the state at time T (same as `ede-replay state ...`)
//   ede-replay state LOG --event N [-o FILE]         the state after the first N events
//   ede-replay info LOG [--scene]                    header, event counts, records, completeness
//   ede-replay events LOG [--from T0] [--to T1] [-o FILE]   events as CSV (or --from-event/--to-event)
//   ede-replay verify LOG                            re-run the logged scene and compare every event
//   ede-replay diff A B                              the first event at which two logs differ
//   ede-replay convert LOG -o OUT [--format-version 1|2|3]   the same log in another format version
//
// Thin: one file per subcommand, each parsing its options and calling the public ede::Log (states, events,
// verify, diff, convert). A first argument that is not a subcommand makes the command `state`, so the common
// case reads `ede-replay run.ede --at 5`. Exit status: 0 success (verify: identical; diff: identical),
// 1 an unreadable log or a difference found, 2 a bad command line.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tool_main.hpp"
#include "command_line.hpp"
#include "replay_tool.hpp"

static int run_main(int argc, char** argv) {
  using namespace ede::replay_tool;
  CLI::App app{
      "ede-replay: read an ede event log: the state at any time, a summary, the events, a check "
      "against a re-run, the first difference between two logs"};
  app.require_subcommand(1);
  const std::vector<std::pair<std::string, Command>> commands = {
      {"state", add_state_command(app)},   {"info", add_info_command(app)}, {"events", add_events_command(app)},
      {"verify", add_verify_command(app)}, {"diff", add_diff_command(app)}, {"export", add_export_command(app)},
      {"convert", add_convert_command(app)},
  };

  // `ede-replay LOG --at T` is `ede-replay state LOG --at T`.
  ede::tools::add_version_flags(app, "ede-replay");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv, "state")) return *stop;
  for (const auto& [name, run] : commands)
    if (app.got_subcommand(name)) return run();
  return usage_error("give a log, or a subcommand");
}

// Out of memory, a stray exception and a failed stdout become one message and a documented status.
int main(int argc, char** argv) { return ede::tools::run_tool("ede-replay", run_main, argc, argv); }
