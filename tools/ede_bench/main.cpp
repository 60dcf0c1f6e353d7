// ede-bench: the project's benchmarks (not timed tests). Subcommands:
//   speed  events per second, ns and cycles per event, bytes per disk, against the all-pairs baseline.
//   log    event log: bytes per event, zstd level, logging overhead, seek time and replay throughput.
//   effects what each physical effect costs per event; specialized engines against the all-effects one.
//   stress the hard cases run long (packing 0.8; restitution 0.5 with TC), every invariant checked.
#include <CLI/CLI.hpp>

#include "bench_effects.hpp"
#include "bench_log.hpp"
#include "bench_speed.hpp"
#include "bench_stress.hpp"
#include "command_line.hpp"

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

  ede::bench::LogBenchOptions log;
  bool quick = false;
  CLI::App* l = app.add_subcommand("log", "event log: bytes per event, zstd level, overhead, seek, replay speed");
  l->add_option("scenes", log.scenes, "scene files (default: four N = 10^3 and 10^4 scenes of examples/bench)");
  l->add_option("--reference", log.reference, "the scene of the level, overhead and seek measurements");
  CLI::Option* repeat = l->add_option("--repeat", log.repeat, "runs per configuration; medians are reported")
                            ->check(CLI::Range(1, 100));
  CLI::Option* events = l->add_option("--events", log.events, "override stop.events of every scene (0: keep)");
  CLI::Option* seek_events =
      l->add_option("--seek-events", log.seek_events, "engine events (stop.events) of the logs built for seeking");
  l->add_flag("--skip-seek", log.skip_seek, "skip the seek and replay measurements");
  l->add_option("--levels", log.levels, "zstd levels to compare")->delimiter(',')->check(CLI::Range(1, 22));
  l->add_option("--csv", log.csv_prefix, "also write the tables as PREFIX-{scenes,columns,levels,seek}.csv");
  l->add_option("--out-dir", log.out_dir, "where the temporary logs go (deleted at the end)");
  l->add_flag("--quick", quick, "a smoke run (well under a minute): 1 repeat, 5e5 events, 2e6 seek events");

  ede::bench::StressOptions stress;
  CLI::App* st = app.add_subcommand("stress", "hard cases run long with every invariant checked");
  st->add_option("--events", stress.events, "engine events per scene (default 10^7)");
  st->add_option("--disks", stress.disks, "disks per scene (default 10^4)");
  st->add_option("--checks", stress.checks, "invariant checks per scene (default 50)")->check(CLI::Range(1, 100000));
  st->add_option("--out-dir", stress.out_dir, "where the logs go (default /tmp)");
  st->add_flag("--keep-logs", stress.keep_logs, "keep the logs");

  ede::bench::EffectsOptions effects;
  bool effects_quick = false;
  CLI::App* ef = app.add_subcommand("effects", "cost per event of each effect; specialized vs all-effects engine");
  ef->add_option("--scene", effects.scene, "the gas to switch effects on in (two species named a and b, walls)");
  CLI::Option* effects_repeat =
      ef->add_option("--repeat", effects.repeat, "interleaved rounds; medians are reported")->check(CLI::Range(1, 100));
  CLI::Option* effects_events = ef->add_option("--events", effects.events, "engine events per run")
                                    ->check(CLI::Range(std::uint64_t(1000), std::uint64_t(1) << 40));
  ef->add_option("--csv", effects.csv_path, "also write the table as CSV");
  ef->add_flag("--quick", effects_quick, "a smoke run (seconds): 1 round of 2e5 events");

  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return *stop;
  if (*ef) {
    if (effects_quick) {
      if (!effects_repeat->count()) effects.repeat = 1;
      if (!effects_events->count()) effects.events = 200000;
    }
    return ede::bench::run_effects(effects);
  }
  if (*st) return ede::bench::run_stress(stress);
  if (*s) return ede::bench::run_speed(speed);
  if (*l) {
    if (log.scenes.empty()) log.scenes = ede::bench::default_log_bench_scenes();
    if (log.reference.empty()) log.reference = ede::bench::default_log_bench_reference();
    if (quick) {
      if (!repeat->count()) log.repeat = 1;
      if (!events->count()) log.events = 500000;
      if (!seek_events->count()) log.seek_events = 2000000;
    }
    return ede::bench::run_log_bench(log);
  }
  return 0;
}
