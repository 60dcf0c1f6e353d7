// ede-stats viscosity: the shear viscosity from the exact stress integral, against Enskog's 2D viscosity.
// An equilibrium run (one periodic log): by the Helfand moment with its block error and by the Green-Kubo
// integral. Sheared runs (one or more Lees-Edwards logs): -<P_xy> / gamma of each, and with two or more
// the zero-shear limit fitted in gamma*^2. The route follows the first log (sheared or not).
// Thin: shear_viscosity, sheared_viscosity and zero_shear_viscosity (ede/viscosity.hpp) do everything;
// this parses, prints and writes the table.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "stats_tool.hpp"
#include "table_cli.hpp"

namespace ede::stats_tool {

namespace {

struct ViscosityCli {
  std::vector<std::string> logs;
  std::string from, to;
  double lag_step = 0, max_lag = 0;
  std::size_t blocks = 10;
  TableOutput out;
  bool loglog = false;
};

std::string plus_minus(double value, double error) { return brief(value) + " ± " + brief(error, 2); }

// Sheared runs: each one's mean stress over its rate, and the zero-shear fit over them.
int run_sheared(const ViscosityCli& c) {
  std::vector<ShearedViscosity> runs;
  Summary s;
  for (const std::string& path : c.logs) {
    auto opened = open_log_overview(path);
    if (!opened) return fail(opened.error().message);
    const Log& log = opened.value().log;
    auto window = read_window(log, c.from, c.to);
    if (!window) return fail(window.error().message);
    ShearedOptions o;
    o.from = window.value().first, o.to = window.value().second, o.blocks = c.blocks;
    auto v = sheared_viscosity(log, o);
    if (!v) return fail(v.error().message);
    const ShearedViscosity& r = v.value();
    s.add("log", path + " (" + std::to_string(r.disks) + " disks, shear rate " + brief(r.shear_rate) + ", window " +
                     brief(r.from) + " to " + brief(r.to) + " in " + std::to_string(r.blocks) + " blocks)");
    s.add("  kT", plus_minus(r.kT, r.kT_error) + " (relative to the flow; " + std::to_string(r.thermostat_events) +
                      " thermostat redraws)");
    s.add("  P_xy", plus_minus(r.shear_stress, r.shear_stress_error) + " (kinetic " + brief(r.kinetic_shear_stress) +
                        ", collisional " + brief(r.collisional_shear_stress) + "); P_xx - P_yy " +
                        plus_minus(r.normal_stress_difference, r.normal_stress_difference_error) + "; pressure " +
                        brief(r.pressure));
    s.add("  eta", plus_minus(r.viscosity, r.viscosity_error) + " (-P_xy / rate)");
    if (r.reduced_viscosity == r.reduced_viscosity)
      s.add("  reduced", "eta* " + plus_minus(r.reduced_viscosity, r.reduced_viscosity_error) + " at rate* " +
                             brief(r.reduced_rate, 4) + " (sigma " + brief(r.sigma) + ")");
    if (r.enskog == r.enskog)
      s.add("  Enskog eta_E", brief(r.enskog) + " at this kT (phi " + brief(r.packing_fraction, 4) + "); eta / eta_E = " +
                                  brief(r.viscosity / r.enskog, 4));
    else
      s.add("  Enskog eta_E", r.enskog_note);
    const double first = r.block_kT.front(), last = r.block_kT.back();
    if (std::fabs(last - first) > 4 * std::sqrt(double(r.blocks)) * r.kT_error && r.kT_error > 0)
      s.add("  warning", "kT moves from " + brief(first) + " in the first block to " + brief(last) +
                             " in the last: not a steady state yet (start the window later with --from)");
    runs.push_back(r);
  }
  // One row per run, in order of the reduced rate (the figure's x).
  std::stable_sort(runs.begin(), runs.end(), [](const ShearedViscosity& a, const ShearedViscosity& b) {
    return a.reduced_rate < b.reduced_rate;
  });
  Table t;
  const auto column = [&](double ShearedViscosity::*field) {
    std::vector<double> v;
    for (const ShearedViscosity& r : runs) v.push_back(r.*field);
    return v;
  };
  t.add("shear_rate", column(&ShearedViscosity::shear_rate));
  t.add("reduced_rate", column(&ShearedViscosity::reduced_rate));
  std::vector<double> rate2;
  for (const ShearedViscosity& r : runs) rate2.push_back(r.reduced_rate * r.reduced_rate);
  t.add("reduced_rate_squared", rate2);
  t.add("eta", column(&ShearedViscosity::viscosity)), t.add("eta_error", column(&ShearedViscosity::viscosity_error));
  t.add("reduced_eta", column(&ShearedViscosity::reduced_viscosity));
  t.add("reduced_eta_error", column(&ShearedViscosity::reduced_viscosity_error));
  t.add("kT", column(&ShearedViscosity::kT)), t.add("shear_stress", column(&ShearedViscosity::shear_stress));
  t.add("shear_stress_error", column(&ShearedViscosity::shear_stress_error));
  t.add("enskog", column(&ShearedViscosity::enskog));
  double reduced_enskog = std::numeric_limits<double>::quiet_NaN();
  std::string dashed;
  if (runs.size() >= 2) {
    auto fit = zero_shear_viscosity(runs);
    if (!fit) return fail(fit.error().message);
    const ZeroShearFit& f = fit.value();
    reduced_enskog = f.enskog_reduced;
    std::vector<double> line;
    for (const double x : rate2) line.push_back(f.reduced_viscosity + f.slope * x);
    t.add("zero_shear_fit", line);
    dashed = "zero_shear_fit";
    s.add("zero shear", "eta0* " + plus_minus(f.reduced_viscosity, f.reduced_viscosity_error) + " (fit eta* = eta0* + b rate*^2 over " +
                            std::to_string(f.points) + " runs; b " + plus_minus(f.slope, f.slope_error) + ", chi2 " +
                            brief(f.chi2, 3) + " on " + std::to_string(f.points - 2) + " degrees of freedom)");
    if (f.enskog_reduced == f.enskog_reduced)
      s.add("Enskog eta_E*", brief(f.enskog_reduced) + " (phi " + brief(f.packing_fraction, 4) + "); eta0* / eta_E* = " +
                                 brief(f.reduced_viscosity / f.enskog_reduced, 4) + " ± " +
                                 brief(f.reduced_viscosity_error / f.enskog_reduced, 2));
    s.number("zero_shear_reduced_viscosity", f.reduced_viscosity);
    s.number("zero_shear_reduced_viscosity_error", f.reduced_viscosity_error);
    s.number("zero_shear_slope", f.slope), s.number("chi2", f.chi2), s.number("enskog_reduced", f.enskog_reduced);
  } else {
    const ShearedViscosity& r = runs.front();
    s.number("viscosity", r.viscosity), s.number("viscosity_error", r.viscosity_error), s.number("kT", r.kT);
    s.number("reduced_viscosity", r.reduced_viscosity), s.number("reduced_viscosity_error", r.reduced_viscosity_error);
    s.number("reduced_rate", r.reduced_rate), s.number("enskog", r.enskog);
    reduced_enskog = r.enskog_reduced;
  }
  t.add("enskog_reduced", std::vector<double>(runs.size(), reduced_enskog));
  if (reduced_enskog == reduced_enskog) dashed += dashed.empty() ? "enskog_reduced" : ",enskog_reduced";
  return finish_table("viscosity", c.out, s, t,
                      {.x = "reduced_rate_squared", .ys = "reduced_eta", .error = "reduced_eta_error",
                       .dashed = dashed, .title = "shear viscosity of sheared runs, -P_xy / rate, reduced",
                       .xlabel = "(rate sigma sqrt(m / kT))^2", .ylabel = "eta sigma / sqrt(m kT)", .scale = "points"});
}

int run_viscosity(const ViscosityCli& c) {
  if (!c.out.plot.empty() && !plot_name_ok(c.out.plot)) return usage_error("--plot wants a .png or .svg file", "viscosity");
  {
    auto first = Log::open(c.logs.front());
    if (first && first.value().info().lees_edwards) return run_sheared(c);
  }
  if (c.logs.size() > 1)
    return usage_error("several logs are for sheared runs (Lees-Edwards) at different rates; an equilibrium run "
                       "takes one log", "viscosity");
  auto opened = open_log_overview(c.logs.front());
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value().log;
  auto window = read_window(log, c.from, c.to);
  if (!window) return fail(window.error().message);
  ViscosityOptions o;
  o.from = window.value().first, o.to = window.value().second;
  const double span = o.to.value_or(double(log.info().end_time)) - o.from.value_or(log.info().start_time);
  o.max_lag = c.max_lag > 0 ? c.max_lag : span / 50;
  o.lag_step = c.lag_step > 0 ? c.lag_step : o.max_lag / 100;
  o.blocks = c.blocks;
  auto v = shear_viscosity(log, o);
  if (!v) return fail(v.error().message);
  const ShearViscosity& r = v.value();
  const double block_length = double(r.origins) * r.bin_width / double(r.blocks);
  Summary s;
  s.add("log", c.logs.front() + " (" + std::to_string(r.disks) + " disks, " + std::to_string(r.bins) + " bins of " +
                   brief(r.bin_width) + ", " + std::to_string(r.origins) + " origins in " + std::to_string(r.blocks) +
                   " blocks)");
  s.add("kT", brief(r.kT) + " (K' / (N - 1), time average)");
  s.add("pressure", brief(r.pressure) + " ((P_xx + P_yy) / 2)");
  s.add("mean P_xy", plus_minus(r.mean_shear_stress, r.mean_shear_stress_error) + "; mean (P_xx - P_yy)/2 " +
                         plus_minus(r.mean_normal_stress, r.mean_normal_stress_error) + " (0 in equilibrium)");
  s.add("eta", plus_minus(r.viscosity, r.viscosity_error) + " (the Helfand moment's slope over lags " +
                   brief(r.lag[(r.lag.size() - 1) / 2]) + " to " + brief(r.lag.back()) + ")");
  s.add("eta(t) (Helfand)", plus_minus(r.eta.back(), r.error.back()) + " at lag " + brief(r.lag.back()) +
                             " (P_xy: " + brief(r.eta_xy.back()) + ", (P_xx - P_yy)/2: " + brief(r.eta_normal.back()) + ")");
  s.add("eta (Green-Kubo)", plus_minus(r.green_kubo.back(), r.green_kubo_error.back()) + " at lag " +
                                brief(r.lag.back()));
  if (r.enskog == r.enskog)
    s.add("Enskog eta_E", brief(r.enskog) + " (phi " + brief(r.packing_fraction, 4) + ", g(sigma) " +
                              brief(r.g_contact, 5) + "; dilute eta_0 " + brief(r.dilute) + "; eta / eta_E = " +
                              brief(r.viscosity / r.enskog, 4) + ")");
  else
    s.add("Enskog eta_E", r.enskog_note);
  if (block_length < 2 * r.lag.back())
    s.add("warning", "a block of origins spans " + brief(block_length) + ", under twice the largest lag: the "
                     "blocks are correlated and the error is too small (use fewer --blocks or a longer window)");
  s.number("viscosity", r.viscosity), s.number("viscosity_error", r.viscosity_error);
  s.number("eta", r.eta.back()), s.number("eta_error", r.error.back()), s.number("green_kubo", r.green_kubo.back());
  s.number("green_kubo_error", r.green_kubo_error.back()), s.number("kT", r.kT), s.number("pressure", r.pressure);
  s.number("enskog", r.enskog), s.number("dilute", r.dilute), s.number("packing_fraction", r.packing_fraction);
  s.number("mean_shear_stress", r.mean_shear_stress), s.number("mean_shear_stress_error", r.mean_shear_stress_error);
  Table t;
  t.add("lag", r.lag), t.add("eta", r.eta), t.add("error", r.error), t.add("eta_xy", r.eta_xy);
  t.add("eta_normal", r.eta_normal), t.add("green_kubo", r.green_kubo), t.add("green_kubo_error", r.green_kubo_error);
  t.add("acf", r.acf), t.add("enskog", std::vector<double>(r.lag.size(), r.enskog));
  return finish_table("viscosity", c.out, s, t,
                      {.x = "lag", .ys = "eta,green_kubo", .error = "error", .dashed = r.enskog == r.enskog ? "enskog" : "",
                       .title = "shear viscosity (Helfand, Green-Kubo) from the exact stress integral",
                       .xlabel = "lag [T]", .ylabel = "eta(t) [M / T]", .scale = c.loglog ? "loglog" : "linear"});
}

}  // namespace

Command add_viscosity_command(CLI::App& app) {
  auto opt = std::make_shared<ViscosityCli>();
  CLI::App* cmd = app.add_subcommand(
      "viscosity", "shear viscosity (exact stress integral) of an equilibrium run, or of sheared runs and their "
                   "zero-shear limit, against Enskog");
  cmd->add_option("logs", opt->logs,
                  "event log: an equilibrium run (periodic, elastic, no thermostat), or one or more sheared runs "
                  "(Lees-Edwards) at different rates")
      ->required();
  cmd->add_option("--from", opt->from, "window start (default: the start of the log)");
  cmd->add_option("--to", opt->to, "window end, or 'end' (the default)");
  cmd->add_option("--max-lag", opt->max_lag, "equilibrium: largest lag (default: the window / 50)");
  cmd->add_option("--lag-step", opt->lag_step, "equilibrium: lag spacing and bin width (default: --max-lag / 100)");
  cmd->add_option("--blocks", opt->blocks,
                  "contiguous blocks of time origins (sheared: of the window) for the error (default 10)")
      ->check(CLI::Range(2, 1000000));
  cmd->add_flag("--loglog", opt->loglog, "draw on logarithmic axes");
  opt->out.add(cmd,
               "write CSV: lag,eta,error,eta_xy,eta_normal,green_kubo,green_kubo_error,acf,enskog (equilibrium); "
               "one row per run: shear_rate,reduced_rate,...,reduced_eta,reduced_eta_error,... (sheared)",
               "draw eta(t), or reduced eta against reduced rate squared, into FILE.png or FILE.svg");
  return [opt] { return run_viscosity(*opt); };
}

}  // namespace ede::stats_tool
