// ede-stats hist: the normalised histogram of speeds or kinetic energies at one time, or pooled over
// several, against the 2D Maxwell-Boltzmann law at the measured temperature, with the initial (t = 0)
// histogram in the same bins beside it.
//
// Thin: measure_distribution (ede/analysis.hpp) takes the samples, kT, the KS tests, the law and both
// histograms; this file reads the times, prints the report, writes the CSV and has plot_hist.py draw it
// (the law's fine curve goes to the script as a second CSV). Pooled times closer than 2 mean free times
// see nearly the same disks: a warning says so. Rejected: computing the samples here, where the Python
// module and the viewer could not reuse them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct HistOptions {
  std::string log, at, from, to, species, quantity = "speed", output, plot;
  std::optional<double> every;
  std::size_t bins = 40;
};

struct Times {
  std::vector<double> list;
  std::string text;  // for the report and the title
  bool pooled = false;
};

Result<Times> sample_times(const HistOptions& opt, const OpenedLog& o) {
  Times t;
  if (!opt.every) {
    auto at = read_analysis_time(o, opt.at, "--at", "end");
    if (!at) return at.error();
    return Times{{at.value()}, "t = " + brief(at.value()), false};
  }
  auto from = read_analysis_time(o, opt.from, "--from", "0");
  if (!from) return from.error();
  auto to = read_analysis_time(o, opt.to, "--to", "end");
  if (!to) return to.error();
  t.list = time_grid(from.value(), to.value(), *opt.every, 1'000'000);
  if (t.list.empty())
    return Error{o.log.info().path + ": --from " + brief(from.value()) + " --to " + brief(to.value()) + " --every " + brief(*opt.every) +
                 " gives no time (or more than a million)"};
  t.pooled = t.list.size() > 1;
  t.text = t.pooled ? "t = " + brief(t.list.front()) + " to " + brief(t.list.back()) + " every " + brief(*opt.every) +
                          " (" + std::to_string(t.list.size()) + " times pooled)"
                    : "t = " + brief(t.list.front());
  const double mft = o.overview.mean_free_time();
  if (t.pooled && *opt.every < 2 * mft)
    warn("--every " + brief(*opt.every) + " is shorter than 2 mean free times (" + brief(2 * mft) +
         "): the pooled samples are not independent");
  return t;
}

std::string hist_csv(const DistributionReport& r) {
  const Histogram& h = r.histogram;
  std::string text = "bin_left,bin_right,density,count,mb_density,initial_density,initial_count\n";
  for (std::size_t k = 0; k < h.bins(); ++k)
    text += exact(h.edges[k]) + "," + exact(h.edges[k + 1]) + "," + exact(r.density[k]) + "," +
            std::to_string(h.count[k]) + "," + exact(r.law_density[k]) + "," + exact(r.initial_density[k]) + "," +
            std::to_string(r.initial.count[k]) + "\n";
  return text;
}

std::string curve_csv(const DistributionReport& r) {
  std::string text = "x,mb_density\n";
  for (std::size_t k = 0; k < r.curve_x.size(); ++k) text += exact(r.curve_x[k]) + "," + exact(r.curve_density[k]) + "\n";
  return text;
}

void report(const HistOptions& opt, const OpenedLog& o, const Times& times, const DistributionReport& r) {
  std::printf("log              %s (%zu disks)\n", opt.log.c_str(), o.overview.disks);
  std::printf("disks            %s: %zu\n", opt.species.empty() ? "all" : ("species " + opt.species).c_str(), r.disks);
  std::printf("times            %s; %zu samples of %s\n", times.text.c_str(), r.samples, opt.quantity.c_str());
  std::printf("kT               %s  (<m v^2/2>, 2D equipartition, k = 1)\n", brief(r.kT).c_str());
  std::printf("KS vs MB         D = %s, p = %s  (energies against exp(-E/kT)/kT at the measured kT)\n",
              brief(r.ks.statistic).c_str(), p_value_text(r.ks.p_value).c_str());
  if (r.initial_kT > 0)
    std::printf("initial (t = 0)  kT = %s, KS vs MB at that kT: D = %s, p = %s\n", brief(r.initial_kT).c_str(),
                brief(r.initial_ks.statistic).c_str(), p_value_text(r.initial_ks.p_value).c_str());
  else
    std::printf("initial (t = 0)  at rest\n");
  std::printf("mean free time   %s (from the whole log)\n", brief(o.overview.mean_free_time()).c_str());
  std::printf("note             kT is fitted from the same sample, which makes p somewhat too large%s\n",
              times.pooled ? "; the pooled times are counted as independent samples, so p is approximate" : "");
}

int run_hist(const HistOptions& opt) {
  if ((!opt.from.empty() || !opt.to.empty()) && !opt.every) return usage_error("hist: --from and --to need --every DT");
  if (opt.every && !(*opt.every > 0)) return usage_error("hist: --every must be > 0");
  if (opt.bins < 1 || opt.bins > 100000) return usage_error("hist: --bins must be between 1 and 100000");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const OpenedLog& o = opened.value();
  auto species = read_species(o.log, opt.species);
  if (!species) return fail(species.error().message);
  auto times = sample_times(opt, o);
  if (!times) return fail(times.error().message);
  const Quantity q = opt.quantity == "energy" ? Quantity::Energy : Quantity::Speed;
  auto measured = measure_distribution(o.log, {times.value().list, species.value(), q, opt.bins});
  if (!measured) return fail(measured.error().message);
  const DistributionReport& r = measured.value();
  const std::string title = std::string(opt.species.empty() ? "all disks" : opt.species) + ", N = " +
                            std::to_string(r.disks) + ", " + times.value().text + "\nkT = " + brief(r.kT) +
                            ", KS D = " + brief(r.ks.statistic) + " (p = " + p_value_text(r.ks.p_value) + ")";
  return write_csv_and_plot({.output = opt.output,
                             .plot = opt.plot,
                             .csv = hist_csv(r),
                             .script = "plot_hist.py",
                             .args = {"", opt.plot, opt.quantity, title},
                             .figure_label = "figure           ",
                             .after_csv = [&]() -> Status { return report(opt, o, times.value(), r), Ok{}; },
                             .extra_csv = opt.plot.empty() ? "" : curve_csv(r),
                             .extra_csv_arg = 0});
}

}  // namespace

Command add_hist_command(CLI::App& app) {
  auto opt = std::make_shared<HistOptions>();
  CLI::App* cmd = app.add_subcommand(
      "hist", "histogram of speeds or energies at a time (or pooled over times) against Maxwell-Boltzmann");
  cmd->add_option("log", opt->log, "event log")->required();
  auto* at = cmd->add_option("--at", opt->at, "time T (exact in the log's scalar type), or 'end' (the default)");
  auto* from = cmd->add_option("--from", opt->from, "pool from this time (default 0)");
  auto* to = cmd->add_option("--to", opt->to, "pool up to this time, or 'end' (the default)");
  auto* every = cmd->add_option("--every", opt->every, "pool the times from, from + DT, ... up to --to");
  at->excludes(from)->excludes(to)->excludes(every);
  cmd->add_option("--species", opt->species, "only the disks of this species (default: all)");
  cmd->add_option("--quantity", opt->quantity, "speed (default) or energy")->check(CLI::IsMember({"speed", "energy"}));
  cmd->add_option("--bins", opt->bins, "number of bins (default 40)");
  cmd->add_option("-o,--output", opt->output,
                  "write the histogram as CSV: bin_left,bin_right,density,count,mb_density,initial_density,"
                  "initial_count");
  cmd->add_option("--plot", opt->plot, "draw the histogram into FILE.png or FILE.svg");
  return [opt] { return run_hist(*opt); };
}

}  // namespace ede::stats_tool
