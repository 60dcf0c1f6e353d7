// ede-crater scan: one run per (value, seed), then the crater of every log, per run and averaged.
//
//   ede-crater scan SCENE --param KEY --values V1,V2,... [--seeds K] [-j J] [--set k=v]... [--out-dir DIR]
//                   [--metric NAME] [--plot FILE] [--no-logs] [measuring options of `ede-crater LOG`]
//
// Every run's scene is loaded first, with the overrides of that run, so a mistyped key or a bad value
// fails at once with the scene loader's message, before any run starts or any file is written. The runs
// are a sweep (tools/sweep, as ede-sweep does them; scan_runs.cpp): J processes at a time, each run
// measured in its own process exactly as `ede-crater LOG` measures it (results stored by index: the tables
// never depend on timing), and with --no-logs its log deleted then. Running the same scan again reuses
// the runs whose logs and rows are complete. Runs that ended in inelastic collapse, with a non-finite
// number or unfinished are marked in scan.csv (suspect), counted in scan-aggregate.csv (n_suspect),
// flagged in the table and ringed in the figure. Rejected: measuring after all runs (every log on disk at
// once).
#include <cctype>
#include <filesystem>
#include <memory>
#include <set>
#include <thread>

#include "stop_signal.hpp"
#include "plot_runner.hpp"
#include "scan.hpp"

namespace ede::crater_tool {

namespace {

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

std::size_t metric_index(const std::string& name) {
  const std::vector<std::string>& names = crater_metric_names();
  std::size_t k = 0;
  while (k < names.size() && names[k] != name) ++k;
  return k;
}

int run_scan(const ScanOptions& opt) {
  auto values = split_values(opt.values_text);
  if (!values) return usage_error(values.error().message);
  const std::size_t metric = metric_index(opt.metric);
  if (metric == crater_metric_names().size())
    return usage_error("--metric '" + opt.metric + "' is not a metric of the scan CSV");
  if (auto s = settings_from(opt.measure); !s) return usage_error(s.error().message);
  const sweep::Sweep sweep = scan_sweep(opt, values.value());
  if (opt.child >= 0) {
    if (std::size_t(opt.child) >= sweep.runs.size()) return fail("--child " + std::to_string(opt.child) + ": no such run");
    return sweep::run_child(sweep, std::size_t(opt.child));
  }
  if (Status s = check_scan_scenes(sweep, opt.param); !s) return fail(s.error().message);
  std::error_code ec;
  std::filesystem::create_directories(opt.out_dir, ec);
  if (ec) return fail("cannot create the output directory '" + opt.out_dir + "': " + ec.message());

  sweep::install_stop_handler();
  const std::size_t jobs = opt.jobs ? opt.jobs : std::max(1u, std::thread::hardware_concurrency());
  auto rows = run_scan_runs(sweep, jobs);
  if (sweep::stop_requested()) {
    ede::tools::report_error("ede-crater", "interrupted; the same command again goes on from the finished runs");
    return 128 + sweep::stop_signal();
  }
  if (!rows) return fail(rows.error().message);
  const ScanResults r{values.value(), std::move(rows).value()};
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
  auto opt = std::make_shared<ScanOptions>();
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
  cmd->add_option("-j,--jobs", opt->jobs, "runs at a time, each in its own process (default: the number of cores)");
  cmd->add_option("--set", opt->sets, "override a scene value in every run, e.g. --set stop.time=0.5 (repeatable)");
  cmd->add_option("--out-dir", opt->out_dir, "directory for the logs and CSV files (default crater-scan)");
  cmd->add_option("--metric", opt->metric, "the metric the table and figure show: count, depth (default), width, "
                                           "area, or another column of scan.csv");
  cmd->add_option("--plot", opt->plot, "draw the metric against the parameter with error bars (.png or .svg)");
  cmd->add_flag("--no-logs", opt->no_logs,
                "keep only the results (CSV files, run summaries, figure): each run's log is measured as soon as "
                "the run ends, then deleted");
  cmd->add_flag("-q,--quiet", opt->quiet, "no progress messages");
  cmd->add_option("--child", opt->child, "(internal) run number K of the scan in this process")->group("");
  add_measure_options(*cmd, opt->measure);
  return [opt] { return run_scan(*opt); };
}

}  // namespace ede::crater_tool
