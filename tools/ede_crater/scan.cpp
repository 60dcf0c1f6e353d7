// ede-crater scan: one ede-sim run per (value, seed), then the crater of every log, per run and averaged.
//
//   ede-crater scan SCENE --param KEY --values V1,V2,... [--seeds K] [--jobs J] [--set k=v]... [--out DIR]
//                   [--metric NAME] [--plot FILE] [measuring options of `ede-crater LOG`]
//
// The scene is loaded once per value with the same overrides ede-sim will get, so a mistyped key or a bad
// value fails at once with the scene loader's message, before any run starts. Runs are ede-sim processes
// (next to this binary), J at a time; each writes DIR/v<i>-s<seed>.ede and its summary beside it. Then the
// logs are measured one after another in (value, seed) order, so the CSV files depend on nothing but the
// scene, the values and the seeds: not on --jobs, not on which run finished first.
// Rejected: measuring inside the pool as runs finish, which saves little (measuring is a replay, much
// faster than the run) and would make the order of the work, if not of the results, depend on timing.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <set>

#include "crater_tool.hpp"
#include "ede/scene.hpp"
#include "plot_runner.hpp"

namespace ede::crater_tool {

namespace {

struct Options {
  std::string scene, param, values_text, out = "crater-scan", metric = "depth", plot;
  std::size_t seeds = 1, jobs = 0;
  std::uint64_t first_seed = 1;
  std::vector<std::string> sets;
  bool quiet = false;
  MeasureOptions measure;
};

// The values, split at the commas outside brackets and braces: "[0,-5],[0,-10]" is two values.
Result<std::vector<std::string>> split_values(const std::string& text) {
  std::vector<std::string> out;
  std::string current;
  int depth = 0;
  bool quoted = false;
  for (const char c : text) {
    if (c == '"') quoted = !quoted;
    if (!quoted && (c == '[' || c == '{')) ++depth;
    if (!quoted && (c == ']' || c == '}')) --depth;
    if (c == ',' && depth == 0 && !quoted) {
      out.push_back(current);
      current.clear();
    } else if (!(std::isspace(static_cast<unsigned char>(c)) && depth == 0 && !quoted)) {
      current += c;
    }
  }
  out.push_back(current);
  std::set<std::string> seen;
  for (const std::string& v : out) {
    if (v.empty()) return Error{"--values '" + text + "' has an empty value; separate values by single commas"};
    if (!seen.insert(v).second) return Error{"--values lists '" + v + "' twice"};
  }
  return out;
}

// Where the value sits on the plot's axis: a number itself, an array of numbers its length (a velocity
// vector gives the speed); nothing for other values (the plot then places them evenly).
std::string axis_position(const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (!value.empty() && end == value.c_str() + value.size() && std::isfinite(v)) return exact(v);
  if (value.size() < 2 || value.front() != '[' || value.back() != ']') return "";
  double sum = 0;
  const std::string inner = value.substr(1, value.size() - 2);
  const char* p = inner.c_str();
  while (*p) {
    const double c = std::strtod(p, &end);
    if (end == p || !std::isfinite(c)) return "";
    sum += c * c;
    p = end;
    while (*p == ' ') ++p;
    if (*p == ',') ++p;
  }
  return exact(std::sqrt(sum));
}

Result<std::string> ede_sim_path() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return Error{"cannot find this program's own path (/proc/self/exe) to locate ede-sim next to it"};
  const std::filesystem::path sim = self.parent_path() / "ede-sim";
  if (access(sim.c_str(), X_OK) != 0)
    return Error{"ede-sim is not next to ede-crater (" + sim.string() + "); build it (cmake --build ... --target ede-sim)"};
  return sim.string();
}

struct Run {
  std::size_t value = 0;
  std::uint64_t seed = 0;
  std::string name;  // file name stem in the output directory
};

std::vector<std::string> overrides_for(const Options& opt, const std::string& value, std::uint64_t seed) {
  std::vector<std::string> o = opt.sets;
  o.push_back(opt.param + "=" + value);
  o.push_back("seed=" + std::to_string(seed));
  return o;
}

// The scene with every value loads (the loader's own messages otherwise).
Status check_scene(const Options& opt, const std::vector<std::string>& values) {
  for (const std::string& v : values) {
    std::vector<Override> overrides;
    for (const std::string& o : overrides_for(opt, v, opt.first_seed)) overrides.push_back({o});
    auto scene = load_scene_file(opt.scene, overrides);
    if (!scene) return Error{"with " + opt.param + "=" + v + ": " + scene.error().message};
  }
  return Ok{};
}

struct Stats {
  std::size_t n = 0;
  double mean = 0, stderr_ = 0;  // standard error of the mean: s / sqrt(n), s with n - 1; NaN if n < 2
};

Stats stats_of(const std::vector<double>& xs) {
  Stats s;
  s.n = xs.size();
  if (s.n == 0) return s;
  for (const double x : xs) s.mean += x;
  s.mean /= double(s.n);
  if (s.n < 2) return s.stderr_ = NAN, s;
  double ss = 0;
  for (const double x : xs) ss += (x - s.mean) * (x - s.mean);
  s.stderr_ = std::sqrt(ss / double(s.n - 1)) / std::sqrt(double(s.n));
  return s;
}


Status write_results(const std::vector<std::string>& values, const std::vector<Run>& runs,
                     const std::vector<MeasuredLog>& measured, const std::string& per_run, const std::string& aggregate) {
  std::string s = "value,x,seed,log,run_status,time,time_source,energy_fraction";
  for (const std::string& m : kMetricNames) s += "," + m;
  s += "\n";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const CraterMeasurement& c = measured[k].crater;
    s += csv_field(values[runs[k].value]) + "," + axis_position(values[runs[k].value]) + "," +
         std::to_string(runs[k].seed) + "," + csv_field(runs[k].name + ".ede") + "," + csv_field(measured[k].run_status) +
         "," + exact(c.time) + "," + to_string(c.source) + "," + exact(c.energy_fraction);
    for (const double v : metric_values(c)) s += "," + exact(v);
    s += "\n";
  }
  if (Status w = write_text_file(per_run, s); !w) return w;

  std::string a = "value,x,n";
  for (const std::string& m : kMetricNames) a += "," + m + "_mean," + m + "_stderr";
  a += "\n";
  for (std::size_t v = 0; v < values.size(); ++v) {
    std::vector<std::vector<double>> columns(kMetricNames.size());
    for (std::size_t k = 0; k < runs.size(); ++k)
      if (runs[k].value == v) {
        const std::vector<double> m = metric_values(measured[k].crater);
        for (std::size_t c = 0; c < m.size(); ++c) columns[c].push_back(m[c]);
      }
    a += csv_field(values[v]) + "," + axis_position(values[v]) + "," + std::to_string(columns[0].size());
    for (const auto& col : columns) {
      const Stats st = stats_of(col);
      a += "," + exact(st.mean) + "," + tools::exact_cell(st.stderr_);
    }
    a += "\n";
  }
  return write_text_file(aggregate, a);
}

// "t = a" or "t = a-b": the times the runs of one value were measured at.
std::string time_range(double lo, double hi) { return "t = " + brief(lo) + (lo == hi ? "" : "-" + brief(hi)); }

void print_table(const Options& opt, const std::vector<std::string>& values, const std::vector<Run>& runs,
                 const std::vector<MeasuredLog>& measured, std::size_t metric) {
  std::printf("%-24s %4s  %s (mean +- standard error)   measured at\n", opt.param.c_str(), "n",
              kMetricNames[metric].c_str());
  for (std::size_t v = 0; v < values.size(); ++v) {
    std::vector<double> xs;
    std::size_t at_end = 0, requested = 0;
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k < runs.size(); ++k)
      if (runs[k].value == v) {
        const CraterMeasurement& c = measured[k].crater;
        xs.push_back(metric_values(c)[metric]);
        at_end += c.source == CraterTimeSource::LogEnd ? 1 : 0;
        requested += c.source == CraterTimeSource::Requested ? 1 : 0;
        lo = std::min(lo, c.time), hi = std::max(hi, c.time);
      }
    const Stats st = stats_of(xs);
    const std::string when = requested    ? "the time asked for"
                             : at_end == 0 ? "energy fraction reached"
                                           : std::to_string(at_end) + " of " + std::to_string(st.n) + " at the log's end";
    std::printf("%-24s %4zu  %-12s +- %-12s  %s, %s\n", values[v].c_str(), st.n, brief(st.mean).c_str(),
                std::isnan(st.stderr_) ? "-" : brief(st.stderr_).c_str(), when.c_str(), time_range(lo, hi).c_str());
  }
}

int run_scan(const Options& opt) {
  auto values = split_values(opt.values_text);
  if (!values) return usage_error(values.error().message);
  std::size_t metric = 0;
  while (metric < kMetricNames.size() && kMetricNames[metric] != opt.metric) ++metric;
  if (metric == kMetricNames.size()) return usage_error("--metric '" + opt.metric + "' is not a metric of the scan CSV");
  if (auto s = settings_from(opt.measure); !s) return usage_error(s.error().message);
  if (Status s = check_scene(opt, values.value()); !s) return fail(s.error().message);
  auto sim = ede_sim_path();
  if (!sim) return fail(sim.error().message);
  std::error_code ec;
  std::filesystem::create_directories(opt.out, ec);
  if (ec) return fail("cannot create the output directory '" + opt.out + "': " + ec.message());

  std::vector<Run> runs;
  std::vector<Job> jobs;
  for (std::size_t v = 0; v < values.value().size(); ++v)
    for (std::uint64_t seed = opt.first_seed; seed < opt.first_seed + opt.seeds; ++seed) {
      Run r{v, seed, "v" + std::to_string(v) + "-s" + std::to_string(seed)};
      const std::string base = opt.out + "/" + r.name;
      Job j{{sim.value(), opt.scene, "-q", "-o", base + ".ede"}, base + ".txt", base + ".err",
            opt.param + "=" + values.value()[v] + ", seed " + std::to_string(seed)};
      for (const std::string& o : overrides_for(opt, values.value()[v], seed)) j.argv.insert(j.argv.end(), {"--set", o});
      runs.push_back(r);
      jobs.push_back(j);
    }
  const std::size_t parallel = opt.jobs ? opt.jobs : std::size_t(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  // Exit status 3: the run stalled (inelastic collapse); its log is complete and is measured like any other.
  const std::vector<JobResult> results = run_jobs(jobs, parallel, {0, 3}, !opt.quiet);
  for (std::size_t k = 0; k < results.size(); ++k)
    if (!results[k].failure.empty() || !results[k].started) {
      const std::string err = jobs[k].stderr_path;
      std::string text;
      if (std::FILE* f = std::fopen(err.c_str(), "r")) {
        char b[4096];
        for (std::size_t n; (n = std::fread(b, 1, sizeof b, f)) > 0;) text.append(b, n);
        std::fclose(f);
      }
      while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
      return fail("the run " + jobs[k].label + " failed (" +
                  (results[k].started ? results[k].failure : std::string("not started")) + "): " + text);
    }

  std::vector<MeasuredLog> measured;
  for (const Run& r : runs) {
    auto m = measure_log(opt.out + "/" + r.name + ".ede", opt.measure);
    if (!m) return fail(m.error().message);
    measured.push_back(std::move(m).value());
  }
  const std::string per_run = opt.out + "/scan.csv", aggregate = opt.out + "/scan-aggregate.csv";
  if (Status s = write_results(values.value(), runs, measured, per_run, aggregate); !s) return fail(s.error().message);
  print_table(opt, values.value(), runs, measured, metric);
  std::printf("wrote %s (one row per run), %s (per value)\n", per_run.c_str(), aggregate.c_str());
  if (!opt.plot.empty()) {
    if (Status s = tools::run_plot_script("plot_crater.py", {"scan", aggregate, opt.plot, "--metric", opt.metric,
                                                              "--param", opt.param});
        !s)
      return fail(s.error().message);
    std::printf("wrote %s (figure)\n", opt.plot.c_str());
  }
  return 0;
}

}  // namespace

Command add_scan_command(CLI::App& app) {
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("scan", "run a scene for several values of one parameter and seeds, then "
                                             "measure every crater");
  cmd->add_option("scene", opt->scene, "scene file (TOML), e.g. examples/crater.toml")->required();
  cmd->add_option("--param", opt->param,
                  "the scene key to vary, as for --set: species.projectile.mass, physics.restitution, ...")
      ->required();
  cmd->add_option("--values", opt->values_text,
                  "its values, comma-separated TOML values: 5,25,125 or '[0,-2.5],[0,-5]'")
      ->required();
  cmd->add_option("--seeds", opt->seeds, "runs per value, with seeds --first-seed, --first-seed + 1, ... (default 1)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--first-seed", opt->first_seed, "the first seed (default 1)");
  cmd->add_option("--jobs,-j", opt->jobs, "ede-sim processes at a time (default: the number of cores)");
  cmd->add_option("--set", opt->sets, "override a scene value in every run, e.g. --set stop.time=0.5 (repeatable)");
  cmd->add_option("--out", opt->out, "directory for the logs and CSV files (default crater-scan)");
  cmd->add_option("--metric", opt->metric, "the metric the table and figure show: count, depth (default), width, "
                                           "area, or another column of scan.csv");
  cmd->add_option("--plot", opt->plot, "draw the metric against the parameter with error bars (.png or .svg)");
  cmd->add_flag("-q,--quiet", opt->quiet, "no progress messages");
  add_measure_options(*cmd, opt->measure);
  return [opt] { return run_scan(*opt); };
}

}  // namespace ede::crater_tool
