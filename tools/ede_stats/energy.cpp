// ede-stats energy: total and per-species mean kinetic energy on a fine time grid, for one log or several
// (e.g. runs at restitution 1, 0.9 and 0.8: one curve each, labelled by the scene's restitution), with
// Haff's law beside each inelastic run.
//
// Thin: energy_curve (ede/analysis.hpp) builds the grid, walks the log once and computes Haff's cooling
// time; this file labels the runs, prints a report per run and writes one long CSV (a label column names
// the run) so logs with different species fit in one file. Rejected: one CSV per log, which the figure
// would have to gather again.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct EnergyOptions {
  std::vector<std::string> logs;
  std::string from, to, output, plot;
  std::optional<double> every;
  std::optional<std::size_t> points;
};

struct Run {
  std::string path, label;
  EnergyCurve curve;
};

std::string grid_text(const EnergyCurve& c) {
  const std::string points = std::to_string(c.series.time.size()) + " points";
  if (c.spacing == 0) return points;
  std::string why;
  if (c.default_spacing)
    why = std::isfinite(c.mean_free_time) ? " (1/20 of the mean free time " + brief(c.mean_free_time) + ")"
                                          : " (1/1000 of the range: no pair collisions)";
  return points + ", dt = " + brief(c.spacing) + why;
}

// "ξ = 0.9", with the file name when two runs share a restitution (or the scene cannot be read).
void label_runs(std::vector<Run>& runs) {
  for (Run& r : runs) {
    int same = 0;
    for (const Run& o : runs) same += (o.curve.restitution == r.curve.restitution) ? 1 : 0;
    r.label = std::isnan(r.curve.restitution) ? r.path : "ξ = " + brief(r.curve.restitution);
    if (same > 1) r.label += " (" + r.path.substr(r.path.find_last_of('/') + 1) + ")";
  }
}

std::vector<std::string> species_union(const std::vector<Run>& runs) {
  std::vector<std::string> names;
  for (const Run& r : runs)
    for (const std::string& n : r.curve.series.species_names)
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  return names;
}

std::string csv_of(const std::vector<Run>& runs) {
  const std::vector<std::string> names = species_union(runs);
  std::string text = "label,restitution,time,kinetic_energy,energy_ratio,mean_kinetic_energy,haff_ratio";
  for (const std::string& n : names) text += ",mean_kinetic_energy:" + n;
  // Logs of a stepped potential (format version 3) add the potential and the total energy.
  const bool stepped = std::any_of(runs.begin(), runs.end(), [](const Run& r) { return !r.curve.series.potential_energy.empty(); });
  if (stepped) text += ",potential_energy,total_energy";
  text += "\n";
  for (const Run& r : runs) {
    const LogSeries& s = r.curve.series;
    for (std::size_t k = 0; k < s.time.size(); ++k) {
      text += r.label + "," + exact_double(r.curve.restitution) + "," + exact_double(s.time[k]) + "," + exact_double(s.kinetic_energy[k]) +
              "," + exact_cell(r.curve.ratio(k)) + "," + exact_double(s.mean_kinetic_energy(k)) + "," +
              exact_cell(r.curve.haff_ratio(k));
      for (const std::string& n : names) {
        const auto it = std::find(s.species_names.begin(), s.species_names.end(), n);
        text += "," + (it == s.species_names.end()
                           ? ""
                           : exact_double(s.species_mean_energy(std::size_t(it - s.species_names.begin()), k)));
      }
      if (stepped)
        text += s.potential_energy.empty() ? std::string(",,")
                                           : "," + exact_double(s.potential_energy[k]) + "," +
                                                 exact_double(s.kinetic_energy[k] + s.potential_energy[k]);
      text += "\n";
    }
  }
  return text;
}

void report(const Run& r) {
  const EnergyCurve& c = r.curve;
  const LogSeries& s = c.series;
  const std::size_t last = s.time.size() - 1;
  const std::string end_ratio = c.initial_energy > 0 ? brief(c.ratio(last)) : "-";
  std::printf("%s  (%s, %llu disks)\n", r.label.c_str(), r.path.c_str(), static_cast<unsigned long long>(s.disks()));
  std::printf("  grid            %s, t = %s to %s\n", grid_text(c).c_str(), brief(s.time.front()).c_str(),
              brief(s.time.back()).c_str());
  std::printf("  kinetic energy  E(0) = %s, E(end) = %s, E(end)/E(0) = %s\n", brief(c.initial_energy).c_str(),
              brief(s.kinetic_energy.back()).c_str(), end_ratio.c_str());
  for (std::size_t sp = 0; sp < s.species_names.size() && s.species_names.size() > 1; ++sp)
    std::printf("  %-15s <E> from %s to %s\n", s.species_names[sp].c_str(), brief(s.species_mean_energy(sp, 0)).c_str(),
                brief(s.species_mean_energy(sp, last)).c_str());
  if (!s.potential_energy.empty()) {
    double total0 = s.kinetic_energy.front() + s.potential_energy.front(), drift = 0;
    for (std::size_t k = 0; k < s.time.size(); ++k)
      drift = std::max(drift, std::abs(s.kinetic_energy[k] + s.potential_energy[k] - total0));
    std::printf("  potential       U(0) = %s, U(end) = %s (a stepped potential)\n", brief(s.potential_energy.front()).c_str(),
                brief(s.potential_energy.back()).c_str());
    std::printf("  total           E + U = %s at the start, %s at the end; max |E + U - (E + U)(0)| = %s\n",
                brief(total0).c_str(), brief(s.kinetic_energy.back() + s.potential_energy.back()).c_str(),
                brief(drift).c_str());
  } else if (c.restitution == 1) {
    std::printf("  conservation    max |E(t)/E(0) - 1| = %s\n", brief(c.max_drift()).c_str());
  }
  if (std::isfinite(c.enskog_tau))
    std::printf("  Haff's law      tau = %s +- %s from Enskog's rate at t = 0 (omega_E = %s per disk, not fitted); "
                "at the end E/E(0) = %s against (1 + t/tau)^-2 = %s\n",
                brief(c.enskog_tau).c_str(), brief(c.enskog_tau_error).c_str(), brief(c.enskog_rate0).c_str(),
                end_ratio.c_str(), brief(c.haff_ratio(last)).c_str());
  else if (!c.enskog_note.empty())
    std::printf("  Enskog          no reference: %s\n", c.enskog_note.c_str());
  if (!std::isnan(c.haff_tau))
    std::printf("  Haff's law      tau = %s from the first %s collisions per disk (a check on the above)%s\n",
                brief(c.haff_tau).c_str(), brief(c.haff_calibration).c_str(),
                std::isfinite(c.enskog_tau) ? "" : ("; at the end (1 + t/tau)^-2 = " + brief(c.haff_ratio(last))).c_str());
}

Result<Run> measure(const EnergyOptions& opt, const std::string& path) {
  auto opened = open_log_overview(path);
  if (!opened) return opened.error();
  EnergyCurveRequest request;
  request.every = opt.every, request.points = opt.points;
  if (!opt.from.empty() || !opt.to.empty()) {
    auto from = read_analysis_time(opened.value(), opt.from, "--from", "0");
    if (!from) return from.error();
    auto to = read_analysis_time(opened.value(), opt.to, "--to", "end");
    if (!to) return to.error();
    request.from = from.value(), request.to = to.value();
  }
  auto curve = energy_curve(opened.value().log, request);
  if (!curve) return curve.error();
  return Run{path, "", std::move(curve).value()};
}

int run_energy(const EnergyOptions& opt) {
  if (opt.every && !(*opt.every > 0)) return usage_error("energy: --every must be > 0");
  std::vector<Run> runs;
  for (const std::string& path : opt.logs) {
    auto run = measure(opt, path);
    if (!run) return fail(run.error().message);
    runs.push_back(std::move(run).value());
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
  auto* every = cmd->add_option("--every", opt->every, "grid spacing (default: 1/20 of the log's mean free time)");
  auto* points = cmd->add_option("--points", opt->points, "K evenly spaced grid points instead, both ends included");
  every->excludes(points);
  cmd->add_option("--from", opt->from, "the grid's first time (default 0)");
  cmd->add_option("--to", opt->to, "the grid's last time, or 'end' (the default)");
  cmd->add_option("-o,--output", opt->output,
                  "write CSV: label,restitution,time,kinetic_energy,energy_ratio,mean_kinetic_energy,haff_ratio (Haff's "
                  "law for inelastic runs), then mean_kinetic_energy:SPECIES per species");
  cmd->add_option("--plot", opt->plot, "draw E(t)/E(0) per log into FILE.png or FILE.svg");
  return [opt] { return run_energy(*opt); };
}

}  // namespace ede::stats_tool
