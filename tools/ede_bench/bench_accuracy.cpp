// ede-bench accuracy [--out-dir DIR] [--scenes DIR] [--set key=value]... [--timing-events N] [--repeat N]
//   [--tmp-dir DIR] [--quick] [--no-plot]
// What accuracy costs in time (study/accuracy.hpp measures): writes DIR/engine.csv, time_stepped.csv,
// log.csv, tables.md (also printed) and accuracy.png. The error runs and the logs run each scene's
// stop.events (10^7 in examples/accuracy; --set stop.events=N). --quick is the smoke run the test makes.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "accuracy_report.hpp"
#include "commands.hpp"

namespace ede::bench {

namespace {

struct AccuracyOptions {
  study::StudyPlan plan;
  std::string out_dir = "docs/accuracy";  // CSV, tables.md and accuracy.png
  bool quick = false, no_plot = false;
};

int run_accuracy(AccuracyOptions o) {
  if (o.quick) {
    o.plan = study::quick_plan(o.plan);
    o.plan.overrides.insert(o.plan.overrides.begin(), "stop.events=200000");  // a --set wins
  }
  std::vector<std::string> scenes = {o.plan.scene("cooling")};  // the time-stepped part's second gas
  for (const std::string& name : study::engine_scenes()) scenes.push_back(o.plan.scene(name));
  if (!check_scenes(scenes, o.plan.overrides)) return 1;
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec) return fail("cannot create " + o.out_dir + ": " + ec.message());
  const auto results = study::run_accuracy_study(o.plan);
  if (!results) return fail("accuracy: " + results.error().message);
  if (Status s = write_report(results.value(), o.out_dir, !o.no_plot); !s) return fail(s.error().message);
  return results.value().ok() ? 0 : 1;
}

}  // namespace

Command accuracy_command(CLI::App& app) {
  auto o = std::make_shared<AccuracyOptions>();
  o->plan.scenes_dir = "examples/accuracy";
  o->plan.repeat = 5;
  o->plan.tmp_dir = "/tmp/ede-bench-accuracy";
  study::StudyPlan& plan = o->plan;
  CLI::App* a = app.add_subcommand("accuracy", "ns per event against the errors each accuracy setting leaves");
  a->add_option("--out-dir", o->out_dir, "folder for the CSV tables, tables.md and accuracy.png");
  a->add_option("--scenes", plan.scenes_dir, "folder of the study's scenes (examples/accuracy)");
  add_set_option(a, plan.overrides);
  a->add_option("--timing-events", plan.timing_events, "engine events per timed run (default 2*10^6)")
      ->check(CLI::Range(std::uint64_t(1000), std::uint64_t(1) << 40));
  CLI::Option* repeat = a->add_option("--repeat", plan.repeat, "timed runs per measurement; medians are reported")
                            ->check(CLI::Range(1, 100));
  a->add_option("--tmp-dir", plan.tmp_dir, "where the temporary logs go (deleted as soon as read)");
  a->add_flag("--quick", o->quick, "a smoke run (well under a minute): stop.events=200000, 1 repeat, shorter lists, __float128 on the first scene only");
  a->add_flag("--no-plot", o->no_plot, "write the tables only");
  return {a, [o, repeat] {
            if (o->quick && !repeat->count()) o->plan.repeat = 1;
            return run_accuracy(*o);
          }};
}

}  // namespace ede::bench
