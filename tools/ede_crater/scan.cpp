// ede-crater scan: one run per (value, seed), then the crater of every log, per run and averaged.
//
//   ede-crater scan SCENE --param KEY --values V1,V2,... [--seeds K] [-j J] [--set k=v]... [--out-dir DIR]
//                   [--metric NAME] [--plot FILE] [measuring options of `ede-crater LOG`]
//
// Every run's scene is loaded first, with the overrides of that run, so a mistyped key or a bad value
// fails at once with the scene loader's message, before any run starts or any file is written. The runs
// go in-process, J at a time (scan_runs.cpp), each log measured by its worker as soon as its run ends,
// exactly as `ede-crater LOG` measures it (results stored by index: the tables never depend on timing), and
// with --no-logs deleted then. Runs that ended in inelastic collapse, with a non-finite number or
// unfinished are marked in scan.csv (suspect), counted in scan-aggregate.csv (n_suspect), flagged in the
// table and ringed in the figure. Rejected: measuring after all runs (every log on disk at once).
#include <cctype>
#include <filesystem>
#include <memory>
#include <set>
#include <thread>

#include "plot_runner.hpp"
#include "scan.hpp"

namespace ede::crater_tool {

namespace {

struct Options {
  std::string scene, param, values_text, out_dir = "crater-scan", metric = "depth", plot;
  std::size_t seeds = 1, jobs = 0;
  std::uint64_t first_seed = 1;
  std::vector<std::string> sets;
  bool quiet = false, no_logs = false;
  MeasureOptions measure;
};

// The values, split at the commas outside brackets, braces and quotes: "[0,-5],[0,-10]" is two values.
Result<std::vector<std::string>> split_values(const std::string& text) {
  std::vector<std::string> out(1);
  int depth = 0;
  bool quoted = false;
  for (const char c : text) {
    if (c == '"') quoted = !quoted;
    if (!quoted && (c == '[' || c == '{')) ++depth;
    if (!quoted && (c == ']' || c == '}')) --depth;
    if (c == ',' && depth == 0 && !quoted) out.emplace_back();
    else if (!(std::isspace(static_cast<unsigned char>(c)) && depth == 0 && !quoted)) out.back() += c;
  }
  std::set<std::string> seen;
  for (const std::string& v : out) {
    if (v.empty()) return Error{"--values '" + text + "' has an empty value; separate values by single commas"};
    if (!seen.insert(v).second) return Error{"--values lists '" + v + "' twice"};
  }
  return out;
}

// Every run of the scan, its scene loaded with the --set overrides, KEY=VALUE and seed=S (in that order).
Result<std::vector<ScanRun>> plan_runs(const Options& opt, const std::vector<std::string>& values) {
  std::vector<ScanRun> runs;
  for (std::size_t v = 0; v < values.size(); ++v)
    for (std::uint64_t seed = opt.first_seed; seed < opt.first_seed + opt.seeds; ++seed) {
      std::vector<Override> overrides;
      for (const std::string& o : opt.sets) overrides.push_back({o});
      overrides.push_back({opt.param + "=" + values[v]});
      overrides.push_back({"seed=" + std::to_string(seed)});
      auto scene = load_scene_file(opt.scene, overrides);
      if (!scene) return Error{"with " + opt.param + "=" + values[v] + ": " + scene.error().message};
      runs.push_back({v, seed, "v" + std::to_string(v) + "-s" + std::to_string(seed),
                      opt.param + "=" + values[v] + ", seed " + std::to_string(seed), std::move(scene).value()});
    }
  return runs;
}

std::size_t metric_index(const std::string& name) {
  const std::vector<std::string>& names = crater_metric_names();
  std::size_t k = 0;
  while (k < names.size() && names[k] != name) ++k;
  return k;
}

int run_scan(const Options& opt) {
  auto values = split_values(opt.values_text);
  if (!values) return usage_error(values.error().message);
  const std::size_t metric = metric_index(opt.metric);
  if (metric == crater_metric_names().size())
    return usage_error("--metric '" + opt.metric + "' is not a metric of the scan CSV");
  if (auto s = settings_from(opt.measure); !s) return usage_error(s.error().message);
  auto runs = plan_runs(opt, values.value());
  if (!runs) return fail(runs.error().message);
  std::error_code ec;
  std::filesystem::create_directories(opt.out_dir, ec);
  if (ec) return fail("cannot create the output directory '" + opt.out_dir + "': " + ec.message());

  const std::size_t jobs = opt.jobs ? opt.jobs : std::max(1u, std::thread::hardware_concurrency());
  auto measured = run_scans(runs.value(), opt.out_dir, jobs, !opt.quiet, opt.measure, !opt.no_logs);
  if (!measured) return fail(measured.error().message);
  ScanResults r{values.value(), std::move(runs).value(), std::move(measured).value()};
  const std::string per_run = opt.out_dir + "/scan.csv", aggregate = opt.out_dir + "/scan-aggregate.csv";
  if (Status s = write_scan_csv(r, per_run, aggregate); !s) return fail(s.error().message);
  print_scan_table(r, opt.param, metric);
  std::printf("wrote %s (one row per run), %s (per value)\n", per_run.c_str(), aggregate.c_str());
  if (opt.plot.empty()) return 0;
  if (Status s = tools::run_plot_script_to(
          "plot_crater.py", {"scan", aggregate, opt.plot, "--metric", opt.metric, "--param", opt.param}, opt.plot);
      !s)
    return fail(s.error().message);
  std::printf("wrote %s (figure)\n", opt.plot.c_str());
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
  cmd->add_option("-j,--jobs", opt->jobs, "runs at a time, each on its own thread (default: the number of cores)");
  cmd->add_option("--set", opt->sets, "override a scene value in every run, e.g. --set stop.time=0.5 (repeatable)");
  cmd->add_option("--out-dir", opt->out_dir, "directory for the logs and CSV files (default crater-scan)");
  cmd->add_option("--metric", opt->metric, "the metric the table and figure show: count, depth (default), width, "
                                           "area, or another column of scan.csv");
  cmd->add_option("--plot", opt->plot, "draw the metric against the parameter with error bars (.png or .svg)");
  cmd->add_flag("--no-logs", opt->no_logs,
                "keep only the results (CSV files, run summaries, figure): each run's log is measured as soon as "
                "the run ends, then deleted");
  cmd->add_flag("-q,--quiet", opt->quiet, "no progress messages");
  add_measure_options(*cmd, opt->measure);
  return [opt] { return run_scan(*opt); };
}

}  // namespace ede::crater_tool
