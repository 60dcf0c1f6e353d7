// ede-stats msd and ede-stats vacf: the mean-square displacement (exactly unwrapped) with the diffusion
// coefficient against Enskog's, and the exact velocity autocorrelation with its Green-Kubo integral.
// Thin: mean_square_displacement and velocity_autocorrelation (ede/transport.hpp). The Enskog value uses
// Henderson's g(sigma) at the log's packing fraction (one radius and one mass only).
#include <cmath>
#include <memory>

#include "stats_tool.hpp"
#include "table_cli.hpp"

namespace ede::stats_tool {

namespace {

struct TransportCli {
  std::string log, from, to, species;
  double lag_step = 0, max_lag = 0;
  std::size_t origins = 20, groups = 10;
  TableOutput out;
  bool loglog = false;
};

void add_common(CLI::App* cmd, TransportCli& o) {
  cmd->add_option("log", o.log, "event log (no gravity)")->required();
  cmd->add_option("--from", o.from, "window start (default: the start of the log)");
  cmd->add_option("--to", o.to, "window end, or 'end' (the default)");
  cmd->add_option("--max-lag", o.max_lag, "largest lag (default: a quarter of the window)");
  cmd->add_option("--lag-step", o.lag_step, "lag spacing (default: --max-lag / 100)");
  cmd->add_option("--species", o.species, "only this species (default: every disk)");
  cmd->add_option("--groups", o.groups, "groups of disks for the error (default 10)")->check(CLI::PositiveNumber);
}

Result<TransportOptions> read(const Log& log, const TransportCli& c) {
  auto w = read_window(log, c.from, c.to);
  if (!w) return w.error();
  auto sp = read_species(log, c.species);
  if (!sp) return sp.error();
  TransportOptions o;
  o.from = w.value().first, o.to = w.value().second;
  const double span = o.to.value_or(double(log.info().end_time)) - o.from.value_or(double(log.info().start_time));
  o.max_lag = c.max_lag > 0 ? c.max_lag : span / 4;
  o.lag_step = c.lag_step > 0 ? c.lag_step : o.max_lag / 100;
  o.origins = c.origins, o.groups = c.groups, o.species = sp.value();
  return o;
}

// Enskog's D for a monodisperse log (NaN otherwise), with Henderson's g(sigma).
double enskog_of(const Log& log, double& kT_out) {
  auto s = log.state_at(log.info().start_time);
  kT_out = NAN;
  if (!s || s.value().size() == 0) return NAN;
  const State& st = s.value();
  double k = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    if (st.radius[i] != st.radius[0] || st.mass[i] != st.mass[0]) return NAN;
    k += 0.5 * st.mass[i] * (st.vx[i] * st.vx[i] + st.vy[i] * st.vy[i]);
  }
  const double n = double(st.size()) / (st.lx * st.ly), sigma = 2 * st.radius[0];
  const double phi = n * M_PI * sigma * sigma / 4;
  kT_out = k / double(st.size());
  return enskog_diffusion(n, sigma, henderson_contact_value(phi), kT_out, st.mass[0]);
}

int run_msd(const TransportCli& c) {
  if (!c.out.plot.empty() && !plot_name_ok(c.out.plot)) return usage_error("--plot wants a .png or .svg file", "msd");
  auto opened = open_log_overview(c.log);
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value().log;
  auto o = read(log, c);
  if (!o) return fail(o.error().message);
  auto m = mean_square_displacement(log, o.value());
  if (!m) return fail(m.error().message);
  const MeanSquareDisplacement& r = m.value();
  double kT;
  const double d_e = enskog_of(log, kT);
  Summary s;
  s.add("log", c.log + " (" + std::to_string(r.disks) + " disks, " + std::to_string(r.origins) + " time origins)");
  s.add("D", brief(r.diffusion) + " ± " + brief(r.diffusion_error, 2) + " (slope / 4 over the last half of the lags)");
  if (d_e == d_e) s.add("Enskog D_E", brief(d_e) + " (Henderson g(sigma), initial kT; D / D_E = " + brief(r.diffusion / d_e, 4) + ")");
  s.number("diffusion", r.diffusion), s.number("diffusion_error", r.diffusion_error), s.number("enskog", d_e);
  Table t;
  std::vector<double> line(r.lag.size());
  for (std::size_t k = 0; k < line.size(); ++k) line[k] = 4 * r.diffusion * r.lag[k];
  t.add("lag", r.lag), t.add("msd", r.msd), t.add("error", r.error), t.add("four_d_lag", line);
  return finish_table("msd", c.out, s, t, {.x = "lag", .ys = "msd", .error = "error", .dashed = "four_d_lag",
                                            .title = "mean-square displacement (exactly unwrapped)", .xlabel = "lag [T]",
                                            .ylabel = "MSD [L²]", .scale = c.loglog ? "loglog" : "linear"});
}

int run_vacf(const TransportCli& c) {
  if (!c.out.plot.empty() && !plot_name_ok(c.out.plot)) return usage_error("--plot wants a .png or .svg file", "vacf");
  auto opened = open_log_overview(c.log);
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value().log;
  auto o = read(log, c);
  if (!o) return fail(o.error().message);
  auto v = velocity_autocorrelation(log, o.value());
  if (!v) return fail(v.error().message);
  const VelocityAutocorrelation& r = v.value();
  double kT;
  const double d_e = enskog_of(log, kT);
  Summary s;
  s.add("log", c.log + " (" + std::to_string(r.disks) + " disks)");
  s.add("C(0)", brief(r.c.front()) + " (<v^2>)");
  s.add("Green-Kubo D", brief(r.green_kubo.back()) + " at lag " + brief(r.lag.back()) + " ((1/2) integral of C)");
  if (d_e == d_e) s.add("Enskog D_E", brief(d_e) + " (Henderson g(sigma), initial kT)");
  s.number("c0", r.c.front()), s.number("green_kubo", r.green_kubo.back()), s.number("enskog", d_e);
  Table t;
  std::vector<double> norm(r.c.size());
  for (std::size_t k = 0; k < norm.size(); ++k) norm[k] = r.c[k] / r.c.front();
  t.add("lag", r.lag), t.add("c", r.c), t.add("error", r.error), t.add("c_norm", norm), t.add("green_kubo", r.green_kubo);
  return finish_table("vacf", c.out, s, t, {.x = "lag", .ys = "c_norm", .title = "velocity autocorrelation (exact)",
                                             .xlabel = "lag [T]", .ylabel = "C(t) / C(0)",
                                             .scale = c.loglog ? "loglog" : "linear"});
}

}  // namespace

Command add_msd_command(CLI::App& app) {
  auto opt = std::make_shared<TransportCli>();
  CLI::App* cmd = app.add_subcommand("msd", "mean-square displacement (exactly unwrapped), D against Enskog");
  add_common(cmd, *opt);
  cmd->add_option("--origins", opt->origins, "time origins (default 20)")->check(CLI::PositiveNumber);
  cmd->add_flag("--loglog", opt->loglog, "draw on logarithmic axes");
  opt->out.add(cmd, "write CSV: lag,msd,error,four_d_lag", "draw the MSD into FILE.png or FILE.svg");
  return [opt] { return run_msd(*opt); };
}

Command add_vacf_command(CLI::App& app) {
  auto opt = std::make_shared<TransportCli>();
  CLI::App* cmd = app.add_subcommand("vacf", "velocity autocorrelation, exact from the events, and its Green-Kubo D");
  add_common(cmd, *opt);
  cmd->add_flag("--loglog", opt->loglog, "draw |C| on logarithmic axes (the 2D long-time tail ~ 1/t is a line)");
  opt->out.add(cmd, "write CSV: lag,c,error,c_norm,green_kubo", "draw C(t)/C(0) into FILE.png or FILE.svg");
  return [opt] { return run_vacf(*opt); };
}

}  // namespace ede::stats_tool
