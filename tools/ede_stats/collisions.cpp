// ede-stats collisions: pair collisions per disk over time, the collision rate and mean free time, and the
// GasLab speed classes (% slow, medium, fast against the initial mean speed) over time.
//
// Thin: collision_series (ede/analysis.hpp) gives the counts, the rate per interval, the mean free time
// and the speed classes; this file prints a summary, writes the CSV (no rate in the first row: no interval
// before it) and has plot_collisions.py draw it. Rejected: a CSV column for every count a log keeps
// (cell crossings, wraps), which no figure of a gas needs.
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct CollisionOptions {
  std::string log, output, plot;
  std::optional<double> every;
};

constexpr const char* kCollisionsCsvHeader =
    "time,pair_collisions,wall_collisions,collisions_per_particle,collision_rate,mean_free_time,slow_percent,"
    "medium_percent,fast_percent,enskog_rate\n";

std::string csv_of(const CollisionSeries& c) {
  const LogSeries& s = c.series;
  std::string text = kCollisionsCsvHeader;
  for (std::size_t k = 0; k < s.time.size(); ++k) {
    const SpeedClasses& sc = c.classes[k];
    text += exact_double(s.time[k]) + "," + std::to_string(s.pair_collisions[k]) + "," + std::to_string(s.wall_collisions[k]) +
            "," + exact_double(s.collisions_per_particle(k)) + "," + exact_cell(c.rate[k]) + "," +
            exact_cell(c.mean_free_time[k]) + "," + exact_double(sc.slow_percent) + "," + exact_double(sc.medium_percent) + "," +
            exact_double(sc.fast_percent) + "," + exact_cell(c.enskog_rate[k]) + "\n";
  }
  return text;
}

void report(const std::string& path, const LogOverview& o, const CollisionSeries& c) {
  const LogSeries& s = c.series;
  const std::size_t last = s.time.size() - 1;
  const double t = s.time[last], v = c.reference_speed;
  std::printf("log                     %s (%zu disks, t = 0 to %s)\n", path.c_str(), o.disks, brief(t).c_str());
  std::printf("pair collisions         %llu (%s per disk)\n", static_cast<unsigned long long>(s.pair_collisions[last]),
              brief(s.collisions_per_particle(last)).c_str());
  std::printf("wall collisions         %llu\n", static_cast<unsigned long long>(s.wall_collisions[last]));
  if (t > 0)
    std::printf("collision rate          %s per disk per unit time (average over the run)\n",
                brief(s.collisions_per_particle(last) / t).c_str());
  std::printf("mean free time          %s (N t / 2 pairs)\n", brief(o.mean_free_time()).c_str());
  const EnskogReference& e = c.enskog;
  if (!e.applicable) {
    std::printf("Enskog                  no reference: %s\n", e.why_not.c_str());
  } else {
    double measured = 0, expected = 0;  // time-weighted over the intervals
    for (std::size_t k = 1; k < s.time.size(); ++k)
      if (std::isfinite(c.rate[k]) && std::isfinite(c.enskog_rate[k]))
        measured += c.rate[k] * (s.time[k] - s.time[k - 1]), expected += c.enskog_rate[k] * (s.time[k] - s.time[k - 1]);
    std::printf("Enskog rate at t = 0    omega_E = 2 n sigma g(sigma) sqrt(pi kT/m) = %s per disk (n = N/(Lx Ly) = %s, "
                "phi = %s, g(sigma) = %s Henderson, kT = %s: %s)\n",
                brief(e.rate).c_str(), brief(e.number_density).c_str(), brief(e.packing_fraction).c_str(),
                brief(e.g_contact).c_str(), brief(e.temperature.kT).c_str(),
                e.temperature.degrees < double(o.disks) ? "centre-of-mass frame, N - 1 disks" : "box frame, N disks");
    if (expected > 0)
      std::printf("measured / Enskog       %s over the run (each interval against omega_E at its kT)\n",
                  brief(measured / expected).c_str());
  }
  std::printf("speed classes           v_ref = %s (initial mean speed): slow < %s, fast > %s\n", brief(v).c_str(),
              brief(0.5 * v).c_str(), brief(1.5 * v).c_str());
  for (const std::size_t k : {std::size_t(0), last})
    std::printf("  t = %-18s slow %5s%%  medium %5s%%  fast %5s%%\n", brief(s.time[k]).c_str(),
                fixed_text(c.classes[k].slow_percent, 1).c_str(), fixed_text(c.classes[k].medium_percent, 1).c_str(),
                fixed_text(c.classes[k].fast_percent, 1).c_str());
}

int run_collisions(const CollisionOptions& opt) {
  if (opt.every && !(*opt.every > 0)) return usage_error("collisions: --every must be > 0");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const LogOverview& overview = opened.value().overview;
  const double end = overview.end_time;
  const double every = opt.every.value_or(end > 0 ? end / 100 : 1);
  const std::vector<double> times = time_grid_to(0, end, every, 1'000'000);
  if (times.empty()) return usage_error("collisions: --every " + brief(every) + " gives more than a million times");
  auto series = collision_series(opened.value().log, times);
  if (!series) return fail(series.error().message);
  report(opt.log, overview, series.value());
  return write_csv_and_plot({.output = opt.output,
                             .plot = opt.plot,
                             .csv = csv_of(series.value()),
                             .script = "plot_collisions.py",
                             .args = {opt.plot},
                             .figure_label = "figure                  "});
}

}  // namespace

Command add_collisions_command(CLI::App& app) {
  auto opt = std::make_shared<CollisionOptions>();
  CLI::App* cmd = app.add_subcommand(
      "collisions", "collisions per disk over time, collision rate, mean free time, and speed classes");
  cmd->add_option("log", opt->log, "event log")->required();
  cmd->add_option("--every", opt->every, "grid spacing (default: 1/100 of the run)");
  cmd->add_option("-o,--output", opt->output,
                  "write CSV: time,pair_collisions,wall_collisions,collisions_per_particle,collision_rate,"
                  "mean_free_time,slow_percent,medium_percent,fast_percent,enskog_rate (Enskog's rate for the "
                  "interval, docs/kinetic-theory.md)");
  cmd->add_option("--plot", opt->plot, "draw collisions per disk, rate and speed classes into FILE.png or FILE.svg");
  return [opt] { return run_collisions(*opt); };
}

}  // namespace ede::stats_tool
