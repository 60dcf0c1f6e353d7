// ede-stats impacts: the distributions of the impact parameter |b| / (r_i + r_j) and of the relative speed
// at pair collisions over a range of a log, against their equilibrium laws (uniform on [0, 1]; the
// flux-weighted Maxwellian g^2 exp(-mu g^2 / 2kT)), with KS tests, and the mean impulses.
// Thin: impact_statistics (ede/collision_stats.hpp) does the work; this file reads the range, prints the
// summary (or --json), writes one CSV row per bin and has plot_impacts.py draw both panels.
// Rejected: two more columns in `ede-stats collisions`, whose rows are times, not bins.
#include <memory>
#include <optional>

#include "ede/collision_stats.hpp"
#include "stats_tool.hpp"
#include "table_cli.hpp"

namespace ede::stats_tool {

namespace {

struct ImpactsCli {
  std::string log, from, to;
  std::size_t bins = 20;
  TableOutput out;
};

Table table_of(const ImpactStatistics& r) {
  Table t;
  std::vector<double> bl, br, gl, gr, one(r.impact.bins(), 1.0);
  for (std::size_t k = 0; k < r.impact.bins(); ++k) {
    bl.push_back(r.impact.edges[k]), br.push_back(r.impact.edges[k + 1]);
    gl.push_back(r.speed.edges[k]), gr.push_back(r.speed.edges[k + 1]);
  }
  t.add("b_left", bl), t.add("b_right", br), t.add("b_density", r.impact_density), t.add("b_law", one);
  t.add("g_left", gl), t.add("g_right", gr), t.add("g_density", r.speed_density), t.add("g_law", r.speed_law);
  return t;
}

int run_impacts(const ImpactsCli& c) {
  if (!c.out.plot.empty() && !plot_name_ok(c.out.plot)) return usage_error("--plot wants a .png or .svg file", "impacts");
  if (c.bins < 1 || c.bins > 100000) return usage_error("--bins must be between 1 and 100000", "impacts");
  auto opened = open_log_overview(c.log);
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value().log;
  auto w = read_window(log, c.from, c.to);
  if (!w) return fail(w.error().message);
  ImpactRequest request;
  request.bins = c.bins;
  if (w.value().first) request.range.from_time = *w.value().first;
  if (w.value().second) request.range.to_time = *w.value().second;
  auto got = impact_statistics(log, request);
  if (!got) return fail(got.error().message);
  const ImpactStatistics& r = got.value();
  Summary s;
  s.add("log", c.log + " (" + std::to_string(opened.value().overview.disks) + " disks)");
  s.add("collisions", std::to_string(r.pair_collisions) + " pair, " + std::to_string(r.wall_collisions) +
                          " wall and segment" + (r.truncated ? " (histograms and tests: the first ones only)" : ""));
  s.add("kT", brief(r.kT) + " (at the start of the range, centre-of-mass frame in a periodic box)");
  s.add("<|b|/sigma>", brief(r.mean_impact) + " (uniform law: 0.5); KS against U(0,1): D = " +
                           brief(r.impact_ks.statistic, 3) + ", p = " + p_value_text(r.impact_ks.p_value, 3));
  s.add("<g>", brief(r.mean_speed) + "; KS of mu g^2/2kT against Gamma(3/2) (flux-weighted Maxwellian): D = " +
                   brief(r.speed_ks.statistic, 3) + ", p = " + p_value_text(r.speed_ks.p_value, 3));
  s.add("<|J|>", brief(r.mean_impulse) + " per pair collision" +
                     (r.wall_collisions ? ", " + brief(r.mean_wall_impulse) + " per wall collision" : std::string()));
  s.number("pair_collisions", double(r.pair_collisions)), s.number("wall_collisions", double(r.wall_collisions));
  s.number("kT", r.kT), s.number("mean_impact", r.mean_impact), s.number("mean_speed", r.mean_speed);
  s.number("impact_ks_d", r.impact_ks.statistic), s.number("impact_ks_p", r.impact_ks.p_value);
  s.number("speed_ks_d", r.speed_ks.statistic), s.number("speed_ks_p", r.speed_ks.p_value);
  s.number("mean_impulse", r.mean_impulse), s.number("mean_wall_impulse", r.mean_wall_impulse);
  return finish_table("impacts", c.out, s, table_of(r),
                      {.title = "pair collisions: " + std::to_string(r.pair_collisions) + ", kT = " + brief(r.kT, 4),
                       .script = "plot_impacts.py"});
}

}  // namespace

Command add_impacts_command(CLI::App& app) {
  auto opt = std::make_shared<ImpactsCli>();
  CLI::App* cmd = app.add_subcommand(
      "impacts", "impact parameter and relative speed at pair collisions against their equilibrium laws (KS)");
  cmd->add_option("log", opt->log, "event log")->required();
  cmd->add_option("--from", opt->from, "first time of the range (default: the start of the log)");
  cmd->add_option("--to", opt->to, "last time of the range, or 'end' (the default)");
  cmd->add_option("--bins", opt->bins, "bins of each histogram (default 20)");
  opt->out.add(cmd, "write CSV, one row per bin: b_left,b_right,b_density,b_law,g_left,g_right,g_density,g_law",
               "draw both histograms against their laws into FILE.png or FILE.svg");
  return [opt] { return run_impacts(*opt); };
}

}  // namespace ede::stats_tool
