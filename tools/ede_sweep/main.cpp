// ede-sweep: a sweep file -> runs (local processes or MPI ranks) -> runs.csv and points.csv (docs/sweeps.md).
//
//   ede-sweep SWEEP.toml [--set key=value]... [--out-dir DIR] [-j N] [--no-timing] [-q]
//   ede-sweep SWEEP.toml --dry-run
//   ede-sweep SWEEP.toml --plot FIG.png [--quantity Q] [--against KEY] [--reference henderson|kolafa-rottner]...
//             [--mark-transition]
//   mpirun -n K ede-sweep SWEEP.toml
//
// Thin: loads the sweep, checks the base scene and the quantities before anything runs, picks the pool
// (MPI when started by mpirun with more than one rank, else local processes), writes the tables (kept
// current while it runs). Every point's scene is checked, and the results folder locked, before any run
// (tools/sweep/sweep_inputs.hpp).
// `--child K` (hidden) is the process of one run. Exit status: 0 when every run ended ok, 3 when some did
// not (the tables say which and why), 1 on a bad sweep file or an I/O error, 2 on a bad command line,
// 130/143 when interrupted (the finished runs are in the tables; running again goes on).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <filesystem>
#include <thread>

#include "command_line.hpp"
#include "dry_run.hpp"
#include "stop_signal.hpp"
#include "local_pool.hpp"
#include "mpi_pool.hpp"
#include "plot_runner.hpp"
#include "report_error.hpp"
#include "results_table.hpp"
#include "sweep.hpp"
#include "sweep_inputs.hpp"
#include "tool_main.hpp"

namespace {

using namespace ede::sweep;

struct Options {
  std::string sweep_path, out_dir, plot_path, quantity, against;
  std::vector<std::string> overrides, references;
  bool mark_transition = false;
  std::size_t jobs = std::max(1u, std::thread::hardware_concurrency());
  bool dry_run = false, no_timing = false, quiet = false;
  double pilot_seconds = 1.0;
  long long child = -1;
  std::string inputs;  // --child: the parent's inputs_digest
};

int fail(const std::string& message) {
  ede::tools::report_error("ede-sweep", message);
  return 1;
}

ede::Result<Sweep> load(const Options& opt) {
  auto spec = load_sweep_file(opt.sweep_path);
  if (!spec) return spec.error();
  Sweep s;
  s.spec = std::move(spec).value();
  for (const std::string& o : opt.overrides) s.spec.base_overrides.push_back(o);
  if (ede::Status q = check_quantities(s.spec.collect); !q) return ede::Error{opt.sweep_path + ": " + q.error().message};
  s.results = opt.out_dir.empty() ? s.spec.results : opt.out_dir;
  s.runs = expand_runs(s.spec);
  s.progress = !opt.quiet;
  s.inputs = inputs_digest(s.spec);
  s.child_argv = {std::filesystem::read_symlink("/proc/self/exe").string(), opt.sweep_path, "--out-dir", s.results,
                  "-q", "--inputs", s.inputs};
  for (const std::string& o : opt.overrides) s.child_argv.insert(s.child_argv.end(), {"--set", o});
  return s;
}

// A theory curve of Z against the packing fraction from the library's own function, written beside the
// tables for the figure script (which then draws what the library computes, not a copy of the formula).
ede::Result<std::string> write_reference_curve(const std::string& folder, const std::string& name) {
  const std::string path = folder + "/reference-" + name + ".csv";
  std::string text = "phi,z\n";
  for (int k = 0; k <= 360; ++k) {
    const double phi = 0.0025 * k;
    const double z = name == "henderson" ? ede::henderson_z(phi) : ede::kolafa_rottner_z(phi);
    if (std::isfinite(z)) text += std::to_string(phi) + "," + std::to_string(z) + "\n";
  }
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return ede::Error{path + ": cannot write the reference curve"};
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok) return ede::Error{path + ": cannot write the reference curve"};
  return path;
}

ede::Status plot(const Sweep& s, const Options& opt) {
  const std::vector<std::string> keys = parameter_columns(s.spec);
  if (keys.empty() || s.spec.collect.empty()) return ede::Error{"--plot needs a parameter and a collected quantity"};
  const std::string y = opt.quantity.empty() ? s.spec.collect.front() : opt.quantity;
  const std::string x = opt.against.empty() ? keys.front() : opt.against;
  std::vector<std::string> args = {s.results + "/points.csv", opt.plot_path, "--x", x, "--y", y};
  for (const std::string& name : opt.references) {
    auto curve = write_reference_curve(s.results, name);
    if (!curve) return curve.error();
    args.insert(args.end(), {"--reference-csv", name, curve.value()});
  }
  if (opt.mark_transition) {
    // Bernard and Krauth, PRL 107, 155704 (2011): liquid-hexatic coexistence 0.700-0.716, hexatic to 0.720.
    args.insert(args.end(), {"--band", "0.700", "0.716", "liquid + hexatic", "--band", "0.716", "0.720", "hexatic"});
  }
  return ede::tools::run_plot_script_to("plot_sweep.py", args, opt.plot_path);
}

// Keeps runs.csv and points.csv current while the sweep runs (at most every 2 s, and at the start: every run
// pending), so that a sweep killed mid-way (kill -9, a rank lost under mpirun, a full disk) leaves tables
// saying which runs finished and which are missing and why. A failed write is kept for the closing message.
struct TableKeeper {
  const Sweep& s;
  bool timing;
  std::chrono::steady_clock::time_point last{};
  bool written = false;
  std::string error;
  void operator()(const std::vector<RunRow>& rows) {
    const auto now = std::chrono::steady_clock::now();
    if (written && now - last < std::chrono::seconds(2)) return;
    written = true;
    last = now;
    if (ede::Status w = write_tables(s, rows, timing); !w) error = w.error().message;
  }
};

// The closing message when the final tables cannot be written: which runs are missing, and why.
int tables_not_written(const std::vector<RunRow>& rows, const std::string& why) {
  std::string m = why + "; the tables are not up to date. " + rows_summary(rows) + ".";
  std::size_t listed = 0;
  for (const RunRow& r : rows)
    if (r.status != "ok" && listed++ < 20) m += "\n  " + r.name + ": " + r.status + (r.error.empty() ? "" : ": " + r.error);
  return fail(m + "\nFix: free space in the results folder, then run the sweep again (finished runs are reused).");
}

int sweep_main(Sweep& s, const Options& opt, bool mpi) {
  std::error_code ec;
  std::filesystem::create_directories(runs_dir(s), ec);
  if (ec) return fail(runs_dir(s) + ": cannot create the results folder: " + ec.message());
  std::unique_ptr<ResultsLock> lock;
  if (!mpi || mpi_rank() == 0) {
    auto taken = ResultsLock::take(s.results);
    if (!taken) {
      fail(taken.error().message);
      if (mpi) mpi_abort(1);
      return 1;
    }
    lock = std::move(taken).value();
  }
  install_stop_handler();
  TableKeeper keeper{s, !opt.no_timing, {}, false, {}};
  s.on_rows = [&keeper](const std::vector<RunRow>& rows) { keeper(rows); };
  std::vector<RunRow> rows;
  if (mpi) {
    auto got = run_mpi(s);
    if (!got) return 0;  // a worker rank: rank 0 writes the tables
    rows = std::move(*got);
  } else {
    rows = run_local(s, opt.jobs);
  }
  if (ede::Status w = write_tables(s, rows, !opt.no_timing); !w) return tables_not_written(rows, w.error().message);
  std::printf("%s\nruns.csv and points.csv in %s\n", rows_summary(rows).c_str(), s.results.c_str());
  if (!opt.plot_path.empty())
    if (ede::Status p = plot(s, opt); !p) return fail(p.error().message);
  if (stop_requested()) return 128 + stop_signal();
  for (const RunRow& r : rows)
    if (r.status != "ok") return 3;
  return 0;
}

}  // namespace

int run(int argc, char** argv) {
  Options opt;
  CLI::App app{"ede-sweep: run a sweep (parameters x seeds) of a scene and collect one results table"};
  app.add_option("sweep", opt.sweep_path, "sweep file (TOML); see docs/sweeps.md")->required();
  app.add_option("--set", opt.overrides, "override a base scene value for every run, e.g. --set stop.time=1 (repeatable)");
  app.add_option("--out-dir", opt.out_dir, "the results folder (default: results = ... in the sweep file)");
  app.add_option("-j,--jobs", opt.jobs, "runs at once on this machine (default: every core)")->check(CLI::PositiveNumber);
  app.add_flag("--dry-run", opt.dry_run, "print the number of runs and an estimate of time and disk, run nothing");
  app.add_option("--pilot-seconds", opt.pilot_seconds, "--dry-run: wall seconds per pilot run (default 1)");
  app.add_flag("--no-timing", opt.no_timing, "leave the wall_seconds column out of runs.csv (tables then compare byte for byte)");
  app.add_option("--plot", opt.plot_path, "draw a quantity's mean and standard error against a parameter (PNG, PDF, SVG)");
  app.add_option("--quantity", opt.quantity, "--plot: the quantity (default: the first collected)");
  app.add_option("--against", opt.against, "--plot: the parameter key (default: the first)");
  app.add_option("--reference", opt.references,
                 "--plot: a theory curve of Z against the packing fraction: henderson, kolafa-rottner (repeatable)")
      ->check(CLI::IsMember({"henderson", "kolafa-rottner"}));
  app.add_flag("--mark-transition", opt.mark_transition,
               "--plot: shade the hard-disk liquid-hexatic coexistence (0.700-0.716) and hexatic (0.716-0.720) ranges");
  app.add_flag("-q,--quiet", opt.quiet, "no line per finished run");
  app.add_option("--child", opt.child, "(internal) run number K of the sweep in this process")->group("");
  app.add_option("--inputs", opt.inputs, "(internal) the digest of the sweep's inputs when it started")->group("");
  ede::tools::add_version_flags(app, "ede-sweep");

  const bool mpi = launched_by_mpirun() && [&] {
    for (int k = 1; k < argc; ++k)
      if (std::string(argv[k]) == "--child") return false;
    return true;
  }();
  int world = 1;
  if (mpi) {
    auto started = mpi_start(argc, argv);
    if (!started) return fail(started.error().message);
    world = started.value();
  }
  const auto finish = [&](int code) {
    if (mpi) mpi_finish();
    return code;
  };
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return finish(*stop);
  auto loaded = load(opt);
  if (opt.child >= 0 && !opt.inputs.empty() && (!loaded || loaded.value().inputs != opt.inputs)) {
    // The parent loaded this very command line: what changed since is the sweep file or its scene.
    ede::tools::report_error("ede-sweep", opt.sweep_path + " or its scene changed since the sweep started: run " +
                                              std::to_string(opt.child) + " is not run");
    return kInputsChanged;
  }
  if (!loaded) return finish(mpi_rank() == 0 ? fail(loaded.error().message) : 1);
  Sweep& s = loaded.value();
  if (opt.child >= 0) {
    if (std::size_t(opt.child) >= s.runs.size()) return fail("--child " + std::to_string(opt.child) + ": no such run");
    return run_child(s, std::size_t(opt.child));
  }
  std::vector<ede::Override> base;
  for (const std::string& o : s.spec.base_overrides) base.push_back({o});
  if (auto scene = ede::load_scene_file(s.spec.scene_path, base); !scene)
    return finish(mpi_rank() == 0 ? fail("the sweep's base scene: " + scene.error().message) : 1);
  if (ede::Status points = check_points(s); !points) return finish(mpi_rank() == 0 ? fail(points.error().message) : 1);
  if (opt.dry_run) {
    if (mpi_rank() == 0) std::printf("%s", dry_run_report(s, mpi ? std::size_t(std::max(1, world - 1)) : opt.jobs, opt.pilot_seconds).c_str());
    return finish(0);
  }
  return finish(sweep_main(s, opt, mpi && world > 1));
}

int main(int argc, char** argv) { return ede::tools::run_tool("ede-sweep", run, argc, argv); }
