// ede-bench: the project's benchmarks and studies (not timed tests), thin commands over ede_study:
//   speed     events per second, ns and cycles per event, bytes per disk, against the all-pairs baseline.
//   log       event log: bytes per event, zstd level, logging overhead, seek time and replay throughput.
//   stress    the hard cases run long (packing 0.8; restitution 0.5 with TC), every invariant checked.
//   effects   what each effect costs per event; specialized engines against the all-effects one.
//   accuracy  what accuracy costs in time: ns per event against the errors each setting leaves.
//   peers     pair collisions per second after a warm-up, log off and on: the table against other codes.
//   grow      dense starts by Lubachevsky-Stillinger growth: seconds to phi 0.72 and to jamming.
//   setup     time to start a run (placement, setup, first predictions) at 10^4..10^6 disks.
// The command-line language is docs/cli.md's; each subcommand's options are in its file (bench_*.cpp).
#include <CLI/CLI.hpp>

#include "tool_main.hpp"
#include "command_line.hpp"
#include "commands.hpp"

static int run_main(int argc, char** argv) {
  CLI::App app{"ede-bench: benchmarks and studies of the ede engine"};
  app.require_subcommand(1);
  const ede::bench::Command commands[] = {
      ede::bench::speed_command(app),   ede::bench::log_command(app),      ede::bench::stress_command(app),
      ede::bench::effects_command(app), ede::bench::accuracy_command(app), ede::bench::peers_command(app),
      ede::bench::grow_command(app),    ede::bench::setup_command(app),
  };
  ede::tools::add_version_flags(app, "ede-bench");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return *stop;
  for (const ede::bench::Command& c : commands)
    if (*c.app) return c.run();
  return 0;
}

// Out of memory, a stray exception and a failed stdout become one message and a documented status.
int main(int argc, char** argv) { return ede::tools::run_tool("ede-bench", run_main, argc, argv); }
