// ede-stats pressure: the pressure of a logged gas, on the walls and from the virial, with error bars.
//
//   ede-stats pressure LOG [--from T0] [--to T1|end] [--blocks B] [-o CSV] [--plot FILE.png|svg]
//
// Thin: libede's measure_pressure (ede/pressure.hpp) replays the window once and does the physics and the
// statistics; this file prints the summary (N, A, phi, kT, P_wall per wall and mean, P_virial, each with
// its standard error, their ratio Z to the ideal gas, Henderson's equation of state), writes one CSV row
// per block, and has tools/plot/plot_pressure.py draw the blocks from that CSV (the tail every ede-stats
// subcommand shares, stats_cli.hpp).
// Exit status: 0 success (warnings go to stderr), 1 an unreadable log or an impossible window, 2 a bad
// command line. Rejected: printing the CSV on stdout when -o is absent, which would mix it with the
// summary a user reads.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct PressureCliOptions {
  std::string log, csv, plot, from, to;
  std::size_t blocks = 20, bins = 64;
  double equilibration = 20;
};

// For the summary: 6 significant digits unless told otherwise; NaN (no value) as "n/a".
std::string num(double v, int digits = 6) { return std::isnan(v) ? "n/a" : brief(v, digits); }

std::string pm(const BlockStats& s) { return num(s.mean) + " ± " + num(s.error, 2); }

void line(const char* label, const std::string& text) { std::printf("%-12s%s\n", label, text.c_str()); }

void print_system(const PressureReport& r, const std::string& path) {
  line("log", path + " (" + to_string(r.boundary) + ", " + std::to_string(r.disks) + " disks, " +
                  to_string(r.scalar) + ")");
  std::string box = num(r.lx) + " x " + num(r.ly) + ", A = " + num(r.area);
  if (r.has_walls()) box += "; virial area A_v = A - r (Lx + Ly) = " + num(r.virial_area);
  line("box", box);
  line("phi", num(r.packing_fraction) + " (mean radius " + num(r.mean_radius) + ")");
  std::string window = "t = " + num(r.t0) + " to " + num(r.t1) + " (log ends at " + num(r.end_time) + ")";
  if (r.default_start) window += "; start: equilibration, mean free time " + num(r.mean_free_time);
  line("window", window);
  line("blocks", std::to_string(r.blocks) + " of length " + num((r.t1 - r.t0) / double(r.blocks)) + ", " +
                     std::to_string(r.bins_per_block) + " bins each for the blocking analysis");
  line("collisions", "pair " + std::to_string(r.totals.pair_collisions) + ", wall " +
                         std::to_string(r.totals.wall_collisions) + " in the window");
  line("kT", pm(r.kT.stats) + " (K / N, time averaged" + (r.has_walls() ? ")" : ", centre-of-mass frame)"));
}

std::string z_text(const PressureSeries& z) { return "Z = P A / (N kT) = " + pm(z.stats); }

std::string check_text(const PressureSeries& s) {
  const BlockingAnalysis& b = s.blocking;
  const std::string lag1 = std::isnan(s.stats.lag1) ? "n/a" : fixed_text(s.stats.lag1, 2);
  std::string t = "lag-1 correlation " + lag1 + ", blocking error " + num(b.error, 2);
  switch (b.trend) {
    case BlockingTrend::Plateau: t += " (plateau at " + std::to_string(b.levels[b.plateau].blocks) + " blocks)"; break;
    case BlockingTrend::Rising: t += " (no plateau: still rising)"; break;
    case BlockingTrend::Falling: t += " (falling with block length: anticorrelated, the block error is an upper bound)"; break;
  }
  return t;
}

void print_results(const PressureReport& r) {
  if (r.has_walls()) {
    static const char* const names[] = {"left", "right", "bottom", "top"};
    std::string walls;
    for (int w = 0; w < 4; ++w) walls += std::string(w ? ", " : "") + names[w] + " " + pm(r.wall[w].stats);
    line("P_wall", walls);
    line("P_wall", "mean " + pm(r.wall_mean.stats) + "   " + z_text(r.z_wall));
  } else {
    line("P_wall", "n/a (periodic box: no walls)");
  }
  line("P_virial", pm(r.virial.stats) + "   " + z_text(r.z_virial));
  if (r.has_walls()) line("difference", "P_wall - P_virial = " + pm(r.wall_minus_virial.stats));
  const double to_box = r.area / r.expected_area();
  std::string ideal = "N kT / A = " + num(r.ideal());
  std::string henderson = "Z(phi) = (1 + phi^2/8) / (1 - phi)^2 = " + num(henderson_z(r.packing_fraction)) +
                          ", Z N kT / A = " + num(r.henderson());
  if (r.has_walls()) {
    ideal += "; in this walled box N kT / A_v = " + num(r.ideal() * to_box);
    henderson += "; Z N kT / A_v = " + num(r.henderson() * to_box);
  }
  line("ideal gas", ideal);
  line("Henderson", henderson);
  const double z_kr = kolafa_rottner_z(r.packing_fraction);
  line("Kolafa-R.", std::isnan(z_kr) ? "n/a: phi above the fit's range (0.707, the fluid's edge)"
                                     : "Z(phi) = " + num(z_kr) + " (Mol. Phys. 104, 3435 (2006)), Z N kT / A = " +
                                           num(z_kr * r.ideal()));
  if (r.has_walls()) line("checks", "wall: " + check_text(r.wall_mean));
  line(r.has_walls() ? "" : "checks", "virial: " + check_text(r.virial));
}

constexpr const char* kCsvHeader =
    "block,t0,t1,kT,P_left,P_right,P_bottom,P_top,P_wall,P_virial,Z_wall,Z_virial,pair_collisions,wall_collisions\n";

std::string csv_of(const PressureReport& r) {
  std::string text = kCsvHeader;
  const auto wall = [&](const PressureSeries& s, std::size_t k) { return r.has_walls() ? exact_cell(s.block[k]) : ""; };
  for (std::size_t k = 0; k < r.blocks; ++k) {
    text += std::to_string(k) + "," + exact_cell(r.block_t0[k]) + "," + exact_cell(r.block_t1[k]) + "," +
            exact_cell(r.kT.block[k]);
    for (std::size_t w = 0; w < 4; ++w) text += "," + wall(r.wall[w], k);
    text += "," + wall(r.wall_mean, k) + "," + exact_cell(r.virial.block[k]) + "," + wall(r.z_wall, k) + "," +
            exact_cell(r.z_virial.block[k]) + "," + std::to_string(r.block_pair_collisions[k]) + "," +
            std::to_string(r.block_wall_collisions[k]) + "\n";
  }
  return text;
}

// The figure script's arguments after the CSV's path.
std::vector<std::string> figure_args(const PressureReport& r, const std::string& plot, const std::string& log) {
  const double to_box = r.area / r.expected_area();
  std::vector<std::string> args = {plot,
                                   "--ideal",
                                   exact_cell(r.ideal() * to_box),
                                   "--henderson",
                                   exact_cell(r.henderson() * to_box),
                                   "--virial",
                                   exact_cell(r.virial.stats.mean),
                                   exact_cell(r.virial.stats.error),
                                   "--title",
                                   log + ": N = " + std::to_string(r.disks) + ", phi = " +
                                       num(r.packing_fraction, 4) + ", " + to_string(r.boundary)};
  if (r.has_walls())
    args.insert(args.end(),
                {"--wall", exact_cell(r.wall_mean.stats.mean), exact_cell(r.wall_mean.stats.error), "--walled"});
  return args;
}

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool plot_extension_ok(const std::string& path) {
  const auto ends = [&](const char* ext) {
    const std::size_t n = std::strlen(ext);
    if (path.size() <= n) return false;
    std::string tail = path.substr(path.size() - n);
    for (char& c : tail) c = char(std::tolower(static_cast<unsigned char>(c)));
    return tail == ext;
  };
  return ends(".png") || ends(".svg");
}

// The window as typed: --from and --to exact in the log's scalar type; --to end is the default.
Result<PressureOptions> window(const Log& log, const PressureCliOptions& opt) {
  PressureOptions o;
  o.blocks = opt.blocks, o.bins_per_block = opt.bins;
  o.equilibration_mean_free_times = opt.equilibration;
  if (!opt.from.empty()) {
    auto from = tools::read_time(log, opt.from, "--from", false);
    if (!from) return from.error();
    o.from = double(from.value().t);
  }
  if (!opt.to.empty()) {
    auto to = tools::read_time(log, opt.to, "--to");
    if (!to) return to.error();
    if (!to.value().end) o.to = double(to.value().t);
  }
  return o;
}

int run_pressure(const PressureCliOptions& opt) {
  if (opt.blocks < 2) return usage_error("--blocks must be at least 2 (an error needs several blocks)", "pressure");
  if (opt.bins < 1 || opt.blocks * opt.bins > 10'000'000)
    return usage_error("--bins must be at least 1, and blocks x bins at most 10^7", "pressure");
  if (!opt.plot.empty() && !plot_extension_ok(opt.plot))
    return usage_error("--plot wants a file name ending in .png or .svg, not '" + opt.plot + "'", "pressure");
  auto log = tools::open_log_warning("ede-stats", opt.log);
  if (!log) return fail(log.error().message);
  auto options = window(log.value(), opt);
  if (!options) return fail(options.error().message);
  auto report = measure_pressure(log.value(), options.value());
  if (!report) return fail(report.error().message);
  const PressureReport& r = report.value();
  print_system(r, opt.log);
  print_results(r);
  std::fflush(stdout);
  for (const std::string& w : r.warnings) warn(w);
  if (opt.csv.empty() && opt.plot.empty()) return 0;
  return write_csv_and_plot({.output = opt.csv,
                             .plot = opt.plot,
                             .csv = csv_of(r),
                             .script = "plot_pressure.py",
                             .args = figure_args(r, opt.plot, base_name(opt.log))});
}

}  // namespace

Command add_pressure_command(CLI::App& app) {
  auto opt = std::make_shared<PressureCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "pressure", "pressure on the walls and from the virial, with block-average errors, vs ideal gas and Henderson");
  cmd->add_option("log", opt->log, "event log written by ede-sim -o")->required();
  cmd->add_option("--from", opt->from,
                  "window start (default: after --equilibration mean free times, at most half the run)");
  cmd->add_option("--to", opt->to, "window end, or 'end' (the default)");
  cmd->add_option("--blocks,-b", opt->blocks, "blocks for the error estimate, at least 2 (default 20)");
  cmd->add_option("--bins", opt->bins,
                  "fine bins per block, for the blocking analysis (default 64; a power of 2 makes the "
                  "blocks one of its levels)");
  cmd->add_option("--equilibration", opt->equilibration,
                  "mean free times skipped when --from is not given (default 20)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("-o,--output", opt->csv, "CSV file: one row per block");
  cmd->add_option("--plot", opt->plot, "figure (PNG or SVG by extension): block pressures vs time");
  return [opt] { return run_pressure(*opt); };
}

}  // namespace ede::stats_tool
