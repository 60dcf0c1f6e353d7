// ede-bench: the project's benchmarks (not timed tests). Subcommands:
//   speed  events per second, ns and cycles per event, bytes per disk, against the all-pairs baseline.
#include <CLI/CLI.hpp>

#include "bench_speed.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ede-bench: benchmarks of the ede engine"};
  app.require_subcommand(1);

  ede::bench::SpeedOptions speed;
  CLI::App* s = app.add_subcommand("speed", "events per second for scenes, with the all-pairs baseline");
  s->add_option("scenes", speed.scenes, "scene files (e.g. examples/bench/*.toml)")->required();
  s->add_option("--repeat", speed.repeat, "runs per scene; medians are reported")->check(CLI::Range(1, 100));
  s->add_option("--events", speed.events, "override stop.events of every scene (0: keep)");
  s->add_option("--baseline-max-disks", speed.baseline_max_disks, "largest N for the all-pairs baseline");
  s->add_option("--baseline-seconds", speed.baseline_seconds, "approximate length of each baseline run");
  s->add_option("--csv", speed.csv_path, "also write the table as CSV");

  CLI11_PARSE(app, argc, argv);
  if (*s) return ede::bench::run_speed(speed);
  return 0;
}
