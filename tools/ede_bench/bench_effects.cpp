// ede-bench effects [--scene FILE] [--repeat N] [--set key=value]... [-o FILE.csv] [--quick]: what each
// effect costs per event, specialized engines against the all-effects one, and the elastic gas against
// ede-bench-elastic (study/effects.hpp measures); a Markdown table, the rows as CSV with -o.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "study/effects.hpp"
#include "study/measurement.hpp"

namespace ede::bench {

namespace {

using study::fmt;

struct EffectsOptions {
  study::EffectsPlan plan;
  std::string csv_path;
  bool quick = false;
};

std::string with_spread(const study::Spread& s) { return fmt(s.median) + " (" + fmt(s.low) + "-" + fmt(s.high) + ")"; }

// ede-bench-elastic, next to this executable.
std::string elastic_only_binary() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("ede-bench-elastic") : (self.parent_path() / "ede-bench-elastic").string();
}

void print_table(const study::EffectsResults& r) {
  std::printf("Scene %s (%zu disks), %llu events per run, %d rounds; ns/event: the event loop's CPU time, "
              "medians over rounds; ratios per round then median (min-max over rounds in brackets), on %s.\n\n",
              r.scene.c_str(), r.disks, static_cast<unsigned long long>(r.events), r.rounds,
              r.cycles ? "user-mode cycles per event" : "CPU time per event (no perf events here)");
  std::printf("| effects switched on | engine (ede-sim's effects line) | ns/event | cycles/event | vs elastic | "
              "all-effects engine ns/event | all-effects / specialized |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|\n");
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    const study::EffectRow& row = r.rows[k];
    std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", row.label.c_str(), row.engine.c_str(),
                fmt(row.ns_per_event).c_str(), row.cycles_per_event > 0 ? fmt(row.cycles_per_event).c_str() : "n/a",
                k == 0 ? "1" : with_spread(row.vs_elastic).c_str(),
                row.all_effects ? fmt(row.all_effects_ns_per_event).c_str() : "(walls only)",
                row.all_effects ? with_spread(row.all_effects_ratio).c_str() : "");
  }
  const double slower = r.elastic_vs_elastic_only.low - 1;
  const std::string verdict =
      r.elastic_not_slower() ? "not slower with every effect compiled in"
                             : "slower with every effect compiled in, by " + fmt(100 * slower, 2) + "% at least: investigate";
  std::printf("\nElastic gas, every effect compiled in (ede-bench, through make_engine): %s ns/event; only the "
              "elastic path compiled in (ede-bench-elastic): %s ns/event; ratio %s: %s.\n",
              fmt(r.elastic_ns_per_event).c_str(), fmt(r.elastic_only_ns_per_event).c_str(),
              with_spread(r.elastic_vs_elastic_only).c_str(), verdict.c_str());
}

std::string csv_of(const study::EffectsResults& r) {
  std::ostringstream o;
  o << "effects,engine,ns_per_event,cycles_per_event,ratio_to_elastic,all_effects_ns_per_event,all_effects_ratio,"
       "all_effects_ratio_low,all_effects_ratio_high\n";
  char line[1024];
  for (const study::EffectRow& row : r.rows) {
    std::snprintf(line, sizeof line, "\"%s\",\"%s\",%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", row.label.c_str(),
                  row.engine.c_str(), row.ns_per_event, row.cycles_per_event, row.vs_elastic.median,
                  row.all_effects ? row.all_effects_ns_per_event : 0.0, row.all_effects_ratio.median,
                  row.all_effects_ratio.low, row.all_effects_ratio.high);
    o << line;
  }
  return o.str();
}

int run_effects(EffectsOptions o) {
  if (o.quick) o.plan.overrides.insert(o.plan.overrides.begin(), "stop.events=200000");  // a --set wins
  if (!check_scenes({o.plan.scene}, o.plan.overrides)) return 1;
  o.plan.elastic_only_binary = elastic_only_binary();
  const auto results = study::run_effects_study(o.plan);
  if (!results) return fail("effects: " + results.error().message);
  print_table(results.value());
  if (!o.csv_path.empty() && !write_file(o.csv_path, csv_of(results.value()))) return 1;
  return 0;
}

}  // namespace

Command effects_command(CLI::App& app) {
  auto o = std::make_shared<EffectsOptions>();
  CLI::App* ef = app.add_subcommand("effects", "cost per event of each effect; specialized vs all-effects engine");
  ef->add_option("--scene", o->plan.scene, "the gas to switch effects on in (two species named a and b, walls)");
  CLI::Option* repeat =
      ef->add_option("--repeat", o->plan.repeat, "interleaved rounds; medians are reported")->check(CLI::Range(1, 100));
  add_set_option(ef, o->plan.overrides);
  ef->add_option("-o,--output", o->csv_path, "also write the table as CSV to this file");
  ef->add_flag("--quick", o->quick, "a smoke run (seconds): 1 round of 2e5 events (stop.events=200000)");
  return {ef, [o, repeat] {
            if (o->quick && !repeat->count()) o->plan.repeat = 1;
            return run_effects(*o);
          }};
}

}  // namespace ede::bench
