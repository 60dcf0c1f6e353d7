// ede-stats species: per species and for all disks, the number of disks, their masses, mean speed, mean
// kinetic energy and temperature, at one time or on a grid of times.
//
// The states come from for_each_snapshot (Replay::seek_time, forward only), the numbers from
// species_stats (gas_observables.hpp). The text table is for reading; the CSV (one row per time and
// species, "all" last) is for figures and scripts. Rejected: one table column per species and row per
// time, whose width would depend on the log.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/log_series.hpp"
#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct SpeciesOptions {
  std::string log, at, output, plot;
  std::optional<double> every;
};

constexpr const char* kSpeciesCsvHeader =
    "time,species,n,mass_min,mass_max,mean_speed,mean_kinetic_energy,kT,mean_speed_error,"
    "mean_kinetic_energy_error\n";

std::string csv_rows(double t, const std::vector<SpeciesStats>& stats) {
  std::string text;
  for (const SpeciesStats& s : stats)
    text += exact(t) + "," + s.name + "," + std::to_string(s.n) + "," + exact(s.mass_min) + "," + exact(s.mass_max) +
            "," + exact(s.mean_speed) + "," + exact(s.mean_kinetic_energy) + "," + exact(s.kT) + "," +
            exact(s.mean_speed_error) + "," + exact(s.mean_kinetic_energy_error) + "\n";
  return text;
}

std::string mass_text(const SpeciesStats& s) {
  return s.mass_min == s.mass_max ? brief(s.mass_min) : brief(s.mass_min) + "-" + brief(s.mass_max);
}

void print_table(double t, const std::vector<SpeciesStats>& stats) {
  std::printf("t = %s\n", brief(t).c_str());
  std::printf("  %-14s %10s %15s %13s %13s %13s\n", "species", "N", "mass", "mean speed", "mean KE", "kT");
  for (const SpeciesStats& s : stats)
    std::printf("  %-14s %10llu %15s %13s %13s %13s\n", s.name.c_str(), static_cast<unsigned long long>(s.n),
                mass_text(s).c_str(), brief(s.mean_speed).c_str(), brief(s.mean_kinetic_energy).c_str(),
                brief(s.kT).c_str());
}

int run_species(const SpeciesOptions& opt) {
  if (opt.every && !(*opt.every > 0)) return usage_error("species: --every must be > 0");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const std::shared_ptr<LogReader>& log = opened.value().log;
  const double end = opened.value().overview.end_time;
  std::vector<double> times;
  if (opt.every) {
    times = grid_to_end(end, *opt.every, 100'000);
    if (times.empty()) return usage_error("species: --every " + brief(*opt.every) + " gives more than 100000 times");
  } else {
    auto at = parse_time(opt.at.empty() ? "end" : opt.at, "--at", end);
    if (!at) return fail(log->path() + ": " + at.error().message);
    times = {at.value()};
  }
  std::string csv = kSpeciesCsvHeader;
  Status s = for_each_snapshot(log, times, [&](const GasSnapshot& snap) {
    const std::vector<SpeciesStats> stats = species_stats(snap);
    print_table(snap.time, stats);
    csv += csv_rows(snap.time, stats);
  });
  if (!s) return fail(s.error().message);
  std::printf("(kT = <m v^2/2>: in 2D, equipartition gives two degrees of freedom of kT/2 each, so kT equals the "
              "mean kinetic energy; k = 1)\n");
  return write_csv_and_plot({.output = opt.output,
                             .plot = opt.plot,
                             .csv = csv,
                             .script = "plot_species.py",
                             .args = {opt.plot},
                             .figure_label = "figure: "});
}

}  // namespace

Command add_species_command(CLI::App& app) {
  auto opt = std::make_shared<SpeciesOptions>();
  CLI::App* cmd =
      app.add_subcommand("species", "per species and for all disks: N, masses, mean speed, mean kinetic energy, kT");
  cmd->add_option("log", opt->log, "event log")->required();
  auto* at = cmd->add_option("--at", opt->at, "time T, or 'end' (the default)");
  auto* every = cmd->add_option("--every", opt->every, "at 0, DT, 2 DT, ... and the end");
  at->excludes(every);
  cmd->add_option("-o,--output", opt->output,
                  "write CSV: time,species,n,mass_min,mass_max,mean_speed,mean_kinetic_energy,kT,"
                  "mean_speed_error,mean_kinetic_energy_error");
  cmd->add_option("--plot", opt->plot, "draw kT and mean speed per species into FILE.png or FILE.svg");
  return [opt] { return run_species(*opt); };
}

}  // namespace ede::stats_tool
