// ede-stats hist: the normalised histogram of speeds or kinetic energies at one time, or pooled over
// several, against the 2D Maxwell-Boltzmann law at the measured temperature; the initial (t = 0)
// histogram in the same bins beside it.
//
// The temperature is measured on the sample itself (kT = <m v^2 / 2>), and the KS test always runs on
// kinetic energies (exponential with mean kT for any mix of masses; for one mass the same statistic as on
// speeds). Bins are K equal bins from 0 to the largest value of the sample or the initial state. Pooled
// times closer than ~2 mean free times see nearly the same disks: a warning says so, and the report says
// the p-value is then approximate. Rejected: fitting kT by least squares to the histogram, which would
// make the temperature depend on the binning.
#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ede/analysis.hpp"
#include "analysis/log_series.hpp"
#include "stats_cli.hpp"
#include "stats_tool.hpp"

namespace ede::stats_tool {

namespace {

struct HistOptions {
  std::string log, at, species, quantity = "speed", output, plot;
  std::optional<double> from, to, every;
  std::size_t bins = 40;
};

// The values of the selected disks in one snapshot or several pooled; their masses (the same at every time).
struct Sample {
  std::vector<double> values, energies, masses;
  void add(const GasSnapshot& s, std::int32_t species, Quantity q) {
    const std::vector<double> e = kinetic_energies(s, species);
    const std::vector<double> v = q == Quantity::Speed ? speeds(s, species) : e;
    values.insert(values.end(), v.begin(), v.end());
    energies.insert(energies.end(), e.begin(), e.end());
    if (masses.empty()) masses = ede::masses(s, species);
  }
  double kT() const {
    long double sum = 0;
    for (const double e : energies) sum += e;
    return energies.empty() ? 0.0 : double(sum / energies.size());
  }
  double max() const { return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end()); }
};

struct Times {
  std::vector<double> list;
  std::string text;  // for reports and titles
  bool pooled = false;
};

Result<Times> sample_times(const HistOptions& opt, const LogOverview& o) {
  Times t;
  if (!opt.every) {
    auto at = parse_time(opt.at.empty() ? "end" : opt.at, "--at", o.end_time);
    if (!at) return at.error();
    t.list = {at.value()};
    t.text = "t = " + brief(at.value());
    return t;
  }
  const double from = opt.from.value_or(0), to = opt.to.value_or(o.end_time);
  if (to > o.end_time)
    return Error{"--to " + brief(to) + " is after the end of the log (t = " + exact(o.end_time) + ")"};
  t.list = time_grid(from, to, *opt.every, 1'000'000);
  if (t.list.empty())
    return Error{"--from " + brief(from) + " --to " + brief(to) + " --every " + brief(*opt.every) +
                 " gives no time (or more than a million)"};
  t.pooled = t.list.size() > 1;
  t.text = t.pooled ? "t = " + brief(t.list.front()) + " to " + brief(t.list.back()) + " every " + brief(*opt.every) +
                          " (" + std::to_string(t.list.size()) + " times pooled)"
                    : "t = " + brief(t.list.front());
  if (t.pooled && *opt.every < 2 * o.mean_free_time())
    warn("--every " + brief(*opt.every) + " is shorter than 2 mean free times (" + brief(2 * o.mean_free_time()) +
         "): the pooled samples are not independent");
  return t;
}

std::string hist_csv(const Histogram& h, const Histogram& h0, const MaxwellBoltzmann& mb, Quantity q) {
  const std::vector<double> d = densities(h), d0 = densities(h0);
  std::string text = "bin_left,bin_right,density,count,mb_density,initial_density,initial_count\n";
  for (std::size_t k = 0; k < h.bins(); ++k)
    text += exact(h.edges[k]) + "," + exact(h.edges[k + 1]) + "," + exact(d[k]) + "," + std::to_string(h.count[k]) +
            "," + exact(mb.bin_density(q, h.edges[k], h.edges[k + 1])) + "," + exact(d0[k]) + "," +
            std::to_string(h0.count[k]) + "\n";
  return text;
}

std::string curve_csv(const MaxwellBoltzmann& mb, Quantity q, double hi) {
  std::string text = "x,mb_density\n";
  constexpr int points = 400;
  for (int k = 0; k <= points; ++k) {
    const double x = hi * k / points;
    text += exact(x) + "," + exact(mb.density(q, x)) + "\n";
  }
  return text;
}

std::string p_text(double p) { return p < 1e-300 ? "< 1e-300" : brief(p); }

void report(const HistOptions& opt, const LogOverview& o, const Times& times, const Sample& now,
            const Sample& initial, const KsResult& ks, const KsResult& ks0, double kT) {
  const std::size_t per_time = now.values.size() / times.list.size();
  std::printf("log              %s (%zu disks)\n", opt.log.c_str(), o.disks);
  std::printf("disks            %s: %zu\n", opt.species.empty() ? "all" : ("species " + opt.species).c_str(), per_time);
  std::printf("times            %s; %zu samples of %s\n", times.text.c_str(), now.values.size(), opt.quantity.c_str());
  std::printf("kT               %s  (<m v^2/2>, 2D equipartition, k = 1)\n", brief(kT).c_str());
  std::printf("KS vs MB         D = %s, p = %s  (energies against exp(-E/kT)/kT at the measured kT)\n",
              brief(ks.statistic).c_str(), p_text(ks.p_value).c_str());
  if (initial.kT() > 0)
    std::printf("initial (t = 0)  kT = %s, KS vs MB at that kT: D = %s, p = %s\n", brief(initial.kT()).c_str(),
                brief(ks0.statistic).c_str(), p_text(ks0.p_value).c_str());
  else
    std::printf("initial (t = 0)  at rest\n");
  std::printf("mean free time   %s (from the whole log)\n", brief(o.mean_free_time()).c_str());
  std::printf("note             kT is fitted from the same sample, which makes p somewhat too large%s\n",
              times.pooled ? "; the pooled times are counted as independent samples, so p is approximate" : "");
}

int run_hist(const HistOptions& opt) {
  if ((opt.from || opt.to) && !opt.every) return usage_error("hist: --from and --to need --every DT");
  if (opt.every && !(*opt.every > 0)) return usage_error("hist: --every must be > 0");
  if (opt.bins < 1 || opt.bins > 100000) return usage_error("hist: --bins must be between 1 and 100000");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const std::shared_ptr<LogReader>& log = opened.value().log;
  const LogOverview& o = opened.value().overview;
  auto species = species_index(log->header(), opt.species);
  if (!species) return fail(log->path() + ": " + species.error().message);
  auto times = sample_times(opt, o);
  if (!times) return fail(log->path() + ": " + times.error().message);
  const Quantity q = opt.quantity == "energy" ? Quantity::Energy : Quantity::Speed;

  Sample now, initial;
  std::vector<double> snapshot_times = {0.0};
  snapshot_times.insert(snapshot_times.end(), times.value().list.begin(), times.value().list.end());
  bool first = true;
  Status s = for_each_snapshot(log, snapshot_times, [&](const GasSnapshot& snap) {
    (first ? initial : now).add(snap, species.value(), q);
    first = false;
  });
  if (!s) return fail(s.error().message);

  const double kT = now.kT();
  if (!(kT > 0)) return fail(log->path() + ": the selected disks are at rest (kT = 0): no distribution to compare");
  const KsResult ks = ks_test_mb_energies(now.energies, kT);
  const KsResult ks0 = initial.kT() > 0 ? ks_test_mb_energies(initial.energies, initial.kT()) : KsResult{};
  const MaxwellBoltzmann mb = maxwell_boltzmann_for(initial.masses, kT);
  const double hi = std::max(now.max(), initial.max());
  const std::vector<double> edges = uniform_edges(0, hi > 0 ? hi : 1, opt.bins);
  const Histogram h = make_histogram(now.values, edges), h0 = make_histogram(initial.values, edges);

  // The Maxwell-Boltzmann curve goes to the figure script as a second CSV.
  const std::unique_ptr<TempFile> curve = opt.plot.empty() ? nullptr : std::make_unique<TempFile>(".csv");
  const std::string title = std::string(opt.species.empty() ? "all disks" : opt.species) +
                            ", N = " + std::to_string(now.values.size() / times.value().list.size()) + ", " +
                            times.value().text + "\nkT = " + brief(kT) + ", KS D = " + brief(ks.statistic) +
                            " (p = " + p_text(ks.p_value) + ")";
  return write_csv_and_plot(
      {.output = opt.output,
       .plot = opt.plot,
       .csv = hist_csv(h, h0, mb, q),
       .script = "plot_hist.py",
       .args = {curve ? curve->path() : "", opt.plot, opt.quantity, title},
       .figure_label = "figure           ",
       .after_csv = [&]() -> Status {
         report(opt, o, times.value(), now, initial, ks, ks0, kT);
         if (curve && (curve->path().empty() || !write_file(curve->path(), curve_csv(mb, q, edges.back()))))
           return Error{"cannot write the Maxwell-Boltzmann curve for the figure"};
         return Ok{};
       }});
}

}  // namespace

Command add_hist_command(CLI::App& app) {
  auto opt = std::make_shared<HistOptions>();
  CLI::App* cmd = app.add_subcommand(
      "hist", "histogram of speeds or energies at a time (or pooled over times) against Maxwell-Boltzmann");
  cmd->add_option("log", opt->log, "event log")->required();
  auto* at = cmd->add_option("--at", opt->at, "time T, or 'end' (the default)");
  auto* from = cmd->add_option("--from", opt->from, "pool from this time (default 0)");
  auto* to = cmd->add_option("--to", opt->to, "pool up to this time (default: the end)");
  auto* every = cmd->add_option("--every", opt->every, "pool the times from, from + DT, ... up to --to");
  at->excludes(from)->excludes(to)->excludes(every);
  cmd->add_option("--species", opt->species, "only the disks of this species (default: all)");
  cmd->add_option("--quantity", opt->quantity, "speed (default) or energy")
      ->check(CLI::IsMember({"speed", "energy"}));
  cmd->add_option("--bins", opt->bins, "number of bins (default 40)");
  cmd->add_option("-o,--output", opt->output,
                  "write the histogram as CSV: bin_left,bin_right,density,count,mb_density,initial_density,"
                  "initial_count");
  cmd->add_option("--plot", opt->plot, "draw the histogram into FILE.png or FILE.svg");
  return [opt] { return run_hist(*opt); };
}

}  // namespace ede::stats_tool
