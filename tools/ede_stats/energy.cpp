// ede-stats energy: total and per-species mean kinetic energy on a fine time grid, for one log or several
// (e.g. runs at restitution 1, 0.9 and 0.8: one curve each, labelled by the scene's restitution).
//
// The series comes from log_series (one walk over the events, exact running sums), so a grid finer than
// the collisions costs little. The default spacing is 1/20 of the mean free time the log gives over the
// whole run (N t_end / 2 pairs): in a cooling gas collisions slow down, so early on the grid is coarser
// relative to the local mean free time than later. The CSV is one long table (a label column names the
// run) so logs with different species fit in one file. Rejected: one CSV per log, which the figure would
// have to gather again.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/log_series.hpp"
#include "ede/scene.hpp"
#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct EnergyOptions {
  std::vector<std::string> logs;
  std::optional<double> dt;
  std::optional<std::size_t> points;
  std::string output, plot;
};

constexpr std::size_t kMaxPoints = 5'000'000;

struct Run {
  std::string path, label;
  double restitution = 1;
  LogOverview overview;
  LogSeries series;
  double dt = 0;
  std::string grid_text;
  double haff_tau = std::nan("");  // Haff's cooling time, for an inelastic run (haff_time)
  double haff_calibration = 0;     // collisions per disk the initial collision frequency was read from
};

// Haff's law for a homogeneous cooling gas of equal disks (2D): each collision loses on average
// (1 - xi^2) kT (the collision-weighted mean of (g.n)^2 is 4 kT / m for Maxwell-Boltzmann velocities), so
// dT/dt = -(1 - xi^2) omega T / 2 with the collision frequency omega proportional to sqrt(T):
//   E(t) / E(0) = (1 + t / tau)^-2,  tau = 4 / ((1 - xi^2) omega0),
// and the collisions per disk grow as C(t) = omega0 tau ln(1 + t / tau). The time t1 at which the log
// reaches C1 collisions per disk then gives omega0 exactly within the model, with no fitted curve:
//   omega0 = 4 (exp((1 - xi^2) C1 / 4) - 1) / ((1 - xi^2) t1).
// C1 = 2 (about 2N collisions: a 2% statistical error), or whatever the run reached.
void haff_time(Run& r) {
  const double a = 1 - r.restitution * r.restitution;
  const LogSeries& s = r.series;
  if (!(a > 0) || s.time.size() < 2) return;
  std::size_t k = 1;
  while (k + 1 < s.time.size() && s.collisions_per_particle(k) < 2) ++k;
  const double c1 = s.collisions_per_particle(k), t1 = s.time[k];
  if (!(c1 > 0) || !(t1 > 0)) return;
  const double omega0 = 4 * std::expm1(a * c1 / 4) / (a * t1);
  r.haff_tau = 4 / (a * omega0);
  r.haff_calibration = c1;
}

double haff_ratio(const Run& r, double t) { return 1 / ((1 + t / r.haff_tau) * (1 + t / r.haff_tau)); }

double restitution_of(const LogReader& log) {
  auto scene = parse_scene_text(log.header().scene_text, log.header().scene_name);
  return scene ? scene.value().physics.restitution : std::nan("");
}

Result<std::vector<double>> grid_for(const EnergyOptions& opt, const LogOverview& o, std::string& text) {
  const double end = o.end_time;
  std::vector<double> grid;
  if (opt.points) {
    const std::size_t k = std::max<std::size_t>(*opt.points, 2);
    if (k > kMaxPoints) return Error{"--points " + std::to_string(k) + " is more than " + std::to_string(kMaxPoints)};
    for (std::size_t i = 0; i < k; ++i) grid.push_back(i + 1 == k ? end : end * (double(i) / double(k - 1)));
    text = std::to_string(k) + " points";
    return grid;
  }
  const double tau = o.mean_free_time();
  double dt = opt.dt.value_or(std::isfinite(tau) ? tau / 20 : end / 1000);
  if (!(dt > 0)) dt = 1;  // a log that ends at t = 0: the grid is {0}
  grid = grid_to_end(end, dt, kMaxPoints);
  if (grid.empty())
    return Error{"the grid of spacing " + brief(dt) + " has more than " + std::to_string(kMaxPoints) +
                 " points; give a larger --dt or --points K"};
  text = std::to_string(grid.size()) + " points, dt = " + brief(dt) +
         (opt.dt ? "" : " (1/20 of the mean free time " + brief(tau) + ")");
  return grid;
}

// "ξ = 0.9", with the file name when two runs share a restitution (or the scene cannot be read).
void label_runs(std::vector<Run>& runs) {
  for (Run& r : runs) {
    int same = 0;
    for (const Run& o : runs) same += (o.restitution == r.restitution) ? 1 : 0;
    r.label = std::isnan(r.restitution) ? r.path : "ξ = " + brief(r.restitution);
    if (same > 1) r.label += " (" + r.path.substr(r.path.find_last_of('/') + 1) + ")";
  }
}

std::vector<std::string> species_union(const std::vector<Run>& runs) {
  std::vector<std::string> names;
  for (const Run& r : runs)
    for (const std::string& n : r.series.species_names)
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  return names;
}

std::string csv_of(const std::vector<Run>& runs) {
  const std::vector<std::string> names = species_union(runs);
  std::string text = "label,restitution,time,kinetic_energy,energy_ratio,mean_kinetic_energy,haff_ratio";
  for (const std::string& n : names) text += ",mean_kinetic_energy:" + n;
  text += "\n";
  for (const Run& r : runs) {
    const LogSeries& s = r.series;
    const double e0 = s.kinetic_energy.empty() ? 0 : s.kinetic_energy.front();
    for (std::size_t k = 0; k < s.time.size(); ++k) {
      text += r.label + "," + exact(r.restitution) + "," + exact(s.time[k]) + "," + exact(s.kinetic_energy[k]) + "," +
              (e0 > 0 ? exact(s.kinetic_energy[k] / e0) : "") + "," + exact(s.mean_kinetic_energy(k)) + "," +
              (std::isnan(r.haff_tau) ? "" : exact(haff_ratio(r, s.time[k])));
      for (const std::string& n : names) {
        const auto it = std::find(s.species_names.begin(), s.species_names.end(), n);
        text += "," + (it == s.species_names.end()
                           ? ""
                           : exact(s.species_mean_energy(std::size_t(it - s.species_names.begin()), k)));
      }
      text += "\n";
    }
  }
  return text;
}

void report(const Run& r) {
  const LogSeries& s = r.series;
  const double e0 = s.kinetic_energy.front(), e1 = s.kinetic_energy.back();
  std::printf("%s  (%s, %llu disks)\n", r.label.c_str(), r.path.c_str(), static_cast<unsigned long long>(s.disks()));
  std::printf("  grid            %s, t = 0 to %s\n", r.grid_text.c_str(), brief(s.time.back()).c_str());
  std::printf("  kinetic energy  E(0) = %s, E(end) = %s, E(end)/E(0) = %s\n", brief(e0).c_str(), brief(e1).c_str(),
              e0 > 0 ? brief(e1 / e0).c_str() : "-");
  for (std::size_t sp = 0; sp < s.species_names.size() && s.species_names.size() > 1; ++sp)
    std::printf("  %-15s <E> from %s to %s\n", s.species_names[sp].c_str(), brief(s.species_mean_energy(sp, 0)).c_str(),
                brief(s.species_mean_energy(sp, s.time.size() - 1)).c_str());
  double drift = 0;
  for (const double e : s.kinetic_energy) drift = std::max(drift, e0 > 0 ? std::abs(e / e0 - 1) : 0.0);
  if (r.restitution == 1) std::printf("  conservation    max |E(t)/E(0) - 1| = %s\n", brief(drift).c_str());
  if (!std::isnan(r.haff_tau))
    std::printf("  Haff's law      tau = %s (initial collision frequency from the first %s collisions per disk); "
                "at the end E/E(0) = %s against (1 + t/tau)^-2 = %s\n",
                brief(r.haff_tau).c_str(), brief(r.haff_calibration).c_str(), e0 > 0 ? brief(e1 / e0).c_str() : "-",
                brief(haff_ratio(r, s.time.back())).c_str());
}

int run_energy(const EnergyOptions& opt) {
  if (opt.dt && opt.points) return usage_error("energy: give --dt or --points, not both");
  if (opt.dt && !(*opt.dt > 0)) return usage_error("energy: --dt must be > 0");
  std::vector<Run> runs;
  for (const std::string& path : opt.logs) {
    auto opened = open_log_overview(path);
    if (!opened) return fail(opened.error().message);
    Run r;
    r.path = path;
    r.restitution = restitution_of(*opened.value().log);
    r.overview = opened.value().overview;
    auto grid = grid_for(opt, r.overview, r.grid_text);
    if (!grid) return fail(path + ": " + grid.error().message);
    auto series = log_series(opened.value().log, grid.value());
    if (!series) return fail(series.error().message);
    r.series = std::move(series).value();
    haff_time(r);
    runs.push_back(std::move(r));
  }
  label_runs(runs);
  for (const Run& r : runs) report(r);
  return write_csv_and_plot({.output = opt.output,
                             .plot = opt.plot,
                             .csv = csv_of(runs),
                             .script = "plot_energy.py",
                             .args = {opt.plot},
                             .figure_label = "figure: "});
}

}  // namespace

Command add_energy_command(CLI::App& app) {
  auto opt = std::make_shared<EnergyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "energy", "total and per-species mean kinetic energy on a fine time grid (one or several logs)");
  cmd->add_option("logs", opt->logs, "event log(s): one curve each")->required();
  auto* dt = cmd->add_option("--dt", opt->dt, "grid spacing (default: 1/20 of the log's mean free time)");
  auto* points = cmd->add_option("--points", opt->points, "K grid points from 0 to the end instead");
  dt->excludes(points);
  cmd->add_option("-o,--output", opt->output,
                  "write CSV: label,restitution,time,kinetic_energy,energy_ratio,mean_kinetic_energy,haff_ratio (Haff's "
                  "law for inelastic runs), then "
                  "mean_kinetic_energy:SPECIES per species");
  cmd->add_option("--plot", opt->plot, "draw E(t)/E(0) per log into FILE.png or FILE.svg");
  return [opt] { return run_energy(*opt); };
}

}  // namespace ede::stats_tool
