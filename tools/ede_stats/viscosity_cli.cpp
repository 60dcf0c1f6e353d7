// ede-stats viscosity: the shear viscosity of an equilibrium run from the exact stress integral, by the
// Helfand moment with its block error and by the Green-Kubo integral, against Enskog's 2D viscosity.
// Thin: shear_viscosity (ede/viscosity.hpp) does everything; this parses, prints and writes the table.
#include <cmath>
#include <memory>

#include "stats_tool.hpp"
#include "table_cli.hpp"

namespace ede::stats_tool {

namespace {

struct ViscosityCli {
  std::string log, from, to;
  double lag_step = 0, max_lag = 0;
  std::size_t blocks = 10;
  TableOutput out;
  bool loglog = false;
};

int run_viscosity(const ViscosityCli& c) {
  if (!c.out.plot.empty() && !plot_name_ok(c.out.plot)) return usage_error("--plot wants a .png or .svg file", "viscosity");
  auto opened = open_log_overview(c.log);
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
  s.add("log", c.log + " (" + std::to_string(r.disks) + " disks, " + std::to_string(r.bins) + " bins of " +
                   brief(r.bin_width) + ", " + std::to_string(r.origins) + " origins in " + std::to_string(r.blocks) +
                   " blocks)");
  s.add("kT", brief(r.kT) + " (K' / (N - 1), time average)");
  s.add("pressure", brief(r.pressure) + " ((P_xx + P_yy) / 2)");
  s.add("mean P_xy", brief(r.mean_shear_stress) + " ± " + brief(r.mean_shear_stress_error, 2) +
                         "; mean (P_xx - P_yy)/2 " + brief(r.mean_normal_stress) + " ± " +
                         brief(r.mean_normal_stress_error, 2) + " (0 in equilibrium)");
  s.add("eta", brief(r.viscosity) + " ± " + brief(r.viscosity_error, 2) + " (the Helfand moment's slope over lags " +
                   brief(r.lag[(r.lag.size() - 1) / 2]) + " to " + brief(r.lag.back()) + ")");
  s.add("eta(t) (Helfand)", brief(r.eta.back()) + " ± " + brief(r.error.back(), 2) + " at lag " + brief(r.lag.back()) +
                             " (P_xy: " + brief(r.eta_xy.back()) + ", (P_xx - P_yy)/2: " + brief(r.eta_normal.back()) + ")");
  s.add("eta (Green-Kubo)", brief(r.green_kubo.back()) + " ± " + brief(r.green_kubo_error.back(), 2) + " at lag " +
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
  CLI::App* cmd = app.add_subcommand("viscosity", "shear viscosity of an equilibrium run (exact stress integral), against Enskog");
  cmd->add_option("log", opt->log, "event log (periodic, elastic, no thermostat)")->required();
  cmd->add_option("--from", opt->from, "window start (default: the start of the log)");
  cmd->add_option("--to", opt->to, "window end, or 'end' (the default)");
  cmd->add_option("--max-lag", opt->max_lag, "largest lag (default: the window / 50)");
  cmd->add_option("--lag-step", opt->lag_step, "lag spacing and bin width (default: --max-lag / 100)");
  cmd->add_option("--blocks", opt->blocks, "contiguous blocks of time origins for the error (default 10)")
      ->check(CLI::Range(2, 1000000));
  cmd->add_flag("--loglog", opt->loglog, "draw on logarithmic axes");
  opt->out.add(cmd, "write CSV: lag,eta,error,eta_xy,eta_normal,green_kubo,green_kubo_error,acf,enskog",
               "draw eta(t) into FILE.png or FILE.svg");
  return [opt] { return run_viscosity(*opt); };
}

}  // namespace ede::stats_tool
