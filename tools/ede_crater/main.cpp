// ede-crater: the crater a projectile leaves in a bed of disks, measured from event logs (docs/crater.md).
//
//   ede-crater LOG [--at T|end | --energy-fraction F] [--species NAME] [--threshold X] [-o CSV] [--plot FILE]
//   ede-crater scan SCENE --param KEY --values V1,V2,... [--seeds K] [-j J] [--set k=v]... [--out-dir DIR]
//
// Thin: one file per subcommand, each parsing its options and calling libede (ede/crater.hpp); the
// numbers come from logs by replay (a scan is a sweep of tools/sweep: each run's process runs its scene
// through ede::Simulation, then measures its log). A first argument that is not a subcommand makes the
// command `measure`. Exit status: 0 success, 1 bad input (a missing log, an unknown species, a scene
// error), 2 a bad command line.
// Rejected: a separate ede-scan program, which would repeat every measuring option.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tool_main.hpp"
#include "command_line.hpp"
#include "crater_tool.hpp"

static int run_main(int argc, char** argv) {
  using namespace ede::crater_tool;
  CLI::App app{"ede-crater: measure the crater a projectile leaves in a bed of disks, from ede-sim's event logs"};
  app.require_subcommand(1);
  const std::vector<std::pair<std::string, Command>> commands = {
      {"measure", add_measure_command(app)},
      {"scan", add_scan_command(app)},
  };

  // `ede-crater LOG ...` is `ede-crater measure LOG ...`.
  ede::tools::add_version_flags(app, "ede-crater");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv, "measure")) return *stop;
  for (const auto& [name, run] : commands)
    if (app.got_subcommand(name)) return run();
  return usage_error("give a log, or a subcommand");
}

// Out of memory, a stray exception and a failed stdout become one message and a documented status.
int main(int argc, char** argv) { return ede::tools::run_tool("ede-crater", run_main, argc, argv); }
