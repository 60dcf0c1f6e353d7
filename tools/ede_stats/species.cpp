// ede-stats species: per species and for all disks, the number of disks, their masses, mean speed, mean
// kinetic energy and temperature, at one time or on a grid of times.
//
// Thin: species_tables (ede/analysis.hpp) gives the numbers; this file prints a text table for reading
// and a CSV (one row per time and species, "all" last) for figures and scripts. --species keeps one
// species' rows. Rejected: one table column per species and row per time, whose width would depend on
// the log.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct SpeciesOptions {
  std::string log, at, species, output, plot, average;
  std::optional<double> every;
};

constexpr const char* kSpeciesCsvHeader =
    "time,species,n,mass_min,mass_max,mean_speed,mean_kinetic_energy,kT,mean_speed_error,"
    "mean_kinetic_energy_error\n";

std::string csv_rows(const SpeciesTable& table) {
  std::string text;
  for (const SpeciesStats& s : table.rows)
    text += exact_double(table.time) + "," + s.name + "," + std::to_string(s.n) + "," + exact_double(s.mass_min) + "," +
            exact_double(s.mass_max) + "," + exact_double(s.mean_speed) + "," + exact_double(s.mean_kinetic_energy) + "," + exact_double(s.kT) +
            "," + exact_double(s.mean_speed_error) + "," + exact_double(s.mean_kinetic_energy_error) + "\n";
  return text;
}

std::string mass_text(const SpeciesStats& s) {
  return s.mass_min == s.mass_max ? brief(s.mass_min) : brief(s.mass_min) + "-" + brief(s.mass_max);
}

void print_table(const SpeciesTable& table) {
  std::printf("t = %s\n", brief(table.time).c_str());
  std::printf("  %-14s %10s %15s %13s %13s %13s\n", "species", "N", "mass", "mean speed", "mean KE", "kT");
  for (const SpeciesStats& s : table.rows)
    std::printf("  %-14s %10llu %15s %13s %13s %13s\n", s.name.c_str(), static_cast<unsigned long long>(s.n),
                mass_text(s).c_str(), brief(s.mean_speed).c_str(), brief(s.mean_kinetic_energy).c_str(),
                brief(s.kT).c_str());
}

Result<std::vector<double>> times_of(const SpeciesOptions& opt, const OpenedLog& o) {
  if (!opt.every) {
    auto at = read_analysis_time(o, opt.at, "--at", "end");
    if (!at) return at.error();
    return std::vector<double>{at.value()};
  }
  std::vector<double> times = time_grid_to(0, o.overview.end_time, *opt.every, 100'000);
  if (times.empty()) return Error{"--every " + brief(*opt.every) + " gives more than 100000 times"};
  return times;
}

// --time-average FROM:TO (either may be empty: 0, the end): species_time_averages (ede/kinetic_theory.hpp).
int run_time_average(const SpeciesOptions& opt, const OpenedLog& o) {
  const std::size_t colon = opt.average.find(':');
  if (colon == std::string::npos) return usage_error("species: --time-average takes FROM:TO, e.g. 1:5 or 1: (to the end)");
  auto from = read_analysis_time(o, opt.average.substr(0, colon), "--time-average FROM", "0");
  if (!from) return fail(from.error().message);
  auto to = read_analysis_time(o, opt.average.substr(colon + 1), "--time-average TO", "end");
  if (!to) return fail(to.error().message);
  auto rows = species_time_averages(o.log, from.value(), to.value());
  if (!rows) return fail(rows.error().message);
  std::printf("time average over t = %s to %s (2000 times, error from 20 blocks)\n", brief(from.value()).c_str(),
              brief(to.value()).c_str());
  std::printf("  %-14s %10s %16s %13s\n", "species", "N", "<m v^2/2> = kT", "+- error");
  std::string csv = "species,n,mean_kinetic_energy,error\n";
  for (const SpeciesTimeAverage& a : rows.value()) {
    std::printf("  %-14s %10llu %16s %13s\n", a.name.c_str(), static_cast<unsigned long long>(a.n),
                brief(a.mean_kinetic_energy).c_str(), brief(a.error).c_str());
    csv += a.name + "," + std::to_string(a.n) + "," + exact_double(a.mean_kinetic_energy) + "," + exact_double(a.error) + "\n";
  }
  return write_csv_and_plot({.output = opt.output, .plot = "", .csv = csv, .script = "", .args = {}, .figure_label = ""});
}

int run_species(const SpeciesOptions& opt) {
  if (opt.every && !(*opt.every > 0)) return usage_error("species: --every must be > 0");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const OpenedLog& o = opened.value();
  if (!opt.average.empty()) return run_time_average(opt, o);
  auto species = read_species(o.log, opt.species);
  if (!species) return fail(species.error().message);
  auto times = times_of(opt, o);
  if (!times) return opt.every ? usage_error("species: " + times.error().message) : fail(times.error().message);
  auto tables = species_tables(o.log, times.value(), species.value());
  if (!tables) return fail(tables.error().message);
  std::string csv = kSpeciesCsvHeader;
  for (const SpeciesTable& table : tables.value()) {
    print_table(table);
    csv += csv_rows(table);
  }
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
  auto* at = cmd->add_option("--at", opt->at, "time T (exact in the log's scalar type), or 'end' (the default)");
  auto* every = cmd->add_option("--every", opt->every, "at 0, DT, 2 DT, ... and the end");
  at->excludes(every);
  auto* average = cmd->add_option("--time-average", opt->average,
                                  "FROM:TO: the time average of <m v^2/2> per species over [FROM, TO] (either may be "
                                  "empty: 0, the end), with a block-average error; -o writes species,n,mean_kinetic_energy,error");
  average->excludes(at)->excludes(every);
  cmd->add_option("--species", opt->species, "only this species (default: every species, then all disks)");
  cmd->add_option("-o,--output", opt->output,
                  "write CSV: time,species,n,mass_min,mass_max,mean_speed,mean_kinetic_energy,kT,"
                  "mean_speed_error,mean_kinetic_energy_error");
  cmd->add_option("--plot", opt->plot, "draw kT and mean speed per species into FILE.png or FILE.svg");
  return [opt] { return run_species(*opt); };
}

}  // namespace ede::stats_tool
