// ede-sim: scene -> run -> event log, summary (text or JSON), final state as CSV.
//
//   ede-sim SCENE.toml [-o LOG] [--set key=value]... [--json] [--final-state FILE.csv] [-q]
//   ede-sim --resume LOG [--json] [--final-state FILE.csv] [-q]
//   ede-sim --continue LOG [--at T] -o NEW_LOG [--set key=value]...   (a new run from LOG's state at T)
//
// Thin: parses the command line, hands the scene to ede::Simulation, prints. Exit status (docs/cli.md): 0
// when the run ended on a stop condition or ran out of events, 3 on inelastic collapse (stalled, or a
// cluster slowed below resolvable speeds), 4 when a non-finite number appeared (the event is named), 1 on
// bad input, an I/O error or too little memory, 2 on a bad command line, 130 (143) when interrupted by
// Ctrl-C (SIGTERM): then the summary so far, what the log kept and how to resume are printed.
// Before anything runs: no output may be an input (tools/common/file_checks.hpp), and a scene whose run
// would not fit in memory is refused with the estimate; the first seconds are a pilot for the run's
// length (pace_watch.hpp).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "ede/ede.hpp"
#include "file_checks.hpp"
#include "interrupt.hpp"
#include "ede/number_text.hpp"
#include "pace_watch.hpp"
#include "progress.hpp"
#include "report_error.hpp"
#include "tool_main.hpp"

namespace {

struct Options {
  std::string scene_path, log_path, resume_path, continue_path, final_state_path;
  std::vector<std::string> overrides;
  std::optional<double> at;
  bool json = false, quiet = false, check_exactness = false;
};

int fail(const std::string& message) {
  ede::tools::report_error("ede-sim", message);
  return 1;
}

std::string mib(std::uint64_t bytes) { return std::to_string((bytes + (1u << 19)) >> 20) + " MiB"; }

// A scene whose run needs more memory than the process may have is refused before setup starts.
ede::Status check_memory(const ede::Scene& scene, bool with_log) {
  const std::uint64_t need = ede::estimated_memory_bytes(scene, with_log);
  const std::uint64_t have = ede::tools::memory_available_bytes();
  if (have == 0 || need <= have) return ede::Ok{};
  return ede::Error{scene.source_name + ": this run needs about " + mib(need) + " of memory (~" +
                    std::to_string(with_log ? ede::kBytesPerDiskWithLog : ede::kBytesPerDiskNoLog) +
                    " bytes per disk" + (with_log ? " with a log" : "") + "), more than the " + mib(have) +
                    " this process may use (the smaller of ulimit -v and the machine's available memory). Fix: "
                    "fewer disks, or more memory."};
}

ede::Result<ede::Simulation> start(const Options& opt, const ede::SimulationOptions& sim_options) {
  if (!opt.resume_path.empty()) return ede::Simulation::resume(opt.resume_path, sim_options);
  std::vector<ede::Override> overrides;
  for (const std::string& o : opt.overrides) overrides.push_back({o});
  auto scene = opt.continue_path.empty() ? ede::load_scene_file(opt.scene_path, overrides)
                                         : ede::continuation_scene(opt.continue_path, opt.at, overrides);
  if (!scene) return scene.error();
  for (const std::string& w : ede::scene_warnings(scene.value())) std::fprintf(stderr, "ede-sim: warning: %s\n", w.c_str());
  if (ede::Status m = check_memory(scene.value(), !opt.log_path.empty()); !m) return m.error();
  try {
    return ede::Simulation::create(scene.value(), sim_options);
  } catch (const std::bad_alloc&) {
    return ede::Error{ede::tools::out_of_memory_message(
        "setting up " + scene.value().source_name + " (estimated need " +
        mib(ede::estimated_memory_bytes(scene.value(), !opt.log_path.empty())) + ")")};
  }
}

int exit_status(ede::RunStatus status) {
  switch (status) {
    case ede::RunStatus::Stalled:
    case ede::RunStatus::Collapsed: return 3;
    case ede::RunStatus::NonFinite:
    case ede::RunStatus::Inexact: return 4;
    default: return 0;
  }
}

void print_log_line(const ede::LogKept& k) {
  std::printf("event log        %s: %llu events, %.4g MiB, %.3g bytes/event\n", k.path.c_str(),
              static_cast<unsigned long long>(k.events), double(k.bytes) / 1048576,
              k.events ? double(k.bytes) / double(k.events) : 0.0);
}

// After Ctrl-C: what the log holds and how to go on (on stderr, so --json output stays one object).
void print_kept(const ede::Simulation& sim) {
  auto kept = sim.log_kept();
  if (!kept) {
    std::fprintf(stderr, "ede-sim: interrupted at t = %.6g; no event log was written, nothing to resume\n",
                 double(sim.time()));
    return;
  }
  const ede::LogKept& k = kept.value();
  std::fprintf(stderr, "ede-sim: interrupted at t = %.6g; %s keeps %llu events up to t = %.6g\n", double(sim.time()),
               k.path.c_str(), static_cast<unsigned long long>(k.events), k.last_event_time);
  if (k.resumable)
    std::fprintf(stderr,
                 "ede-sim: continue with `ede-sim --resume %s`: it restarts from event %llu (t = %.6g), the last "
                 "resumable keyframe, and the finished log is identical to an uninterrupted run's\n",
                 k.path.c_str(), static_cast<unsigned long long>(k.resume_event), k.resume_time);
  else
    std::fprintf(stderr, "ede-sim: the log has no resumable keyframe yet: run the scene again to go on\n");
}

}  // namespace

int run(int argc, char** argv) {
  Options opt;
  CLI::App app{"ede-sim: run an event-driven hard-disk simulation from a scene file"};
  app.add_option("scene", opt.scene_path, "scene file (TOML); see docs/scene-format.md");
  app.add_option("-o,--output,--log", opt.log_path, "write every event to this log (any file name; see schema/FORMAT.md)");
  app.add_option("--resume", opt.resume_path, "continue the interrupted run logged in this file, in place");
  app.add_option("--continue", opt.continue_path,
                 "start a new run (-o) from the state of this log, with its scene changed by --set (e.g. "
                 "physics.restitution=0.9, start.reverse_velocities=true); the new log records where it came from");
  app.add_option("--at", opt.at, "with --continue: the time in that log to start from (default: its end)");
  app.add_option("--set", opt.overrides, "override a scene value, e.g. --set physics.restitution=0.9 (repeatable)");
  app.add_flag("--json", opt.json, "print the summary as one JSON object on stdout");
  app.add_option("--final-state", opt.final_state_path, "write the final state as CSV (exact numbers)");
  app.add_flag("-q,--quiet", opt.quiet, "no progress output");
  app.add_flag("--check-exactness", opt.check_exactness,
               "the log writer recomputes every prediction the engine vouches for and fails the run at the first "
               "that differs (slower; the same log)");
  ede::tools::add_version_flags(app, "ede-sim");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return *stop;
  if (int(!opt.resume_path.empty()) + int(!opt.scene_path.empty()) + int(!opt.continue_path.empty()) != 1)
    return std::fprintf(stderr, "ede-sim: give one of a scene file, --resume LOG or --continue LOG (see ede-sim --help)\n"), 2;
  if (opt.at && opt.continue_path.empty())
    return std::fprintf(stderr, "ede-sim: --at is the time to continue from: it goes with --continue LOG\n"), 2;
  if (!opt.resume_path.empty() && (!opt.log_path.empty() || !opt.overrides.empty()))
    return std::fprintf(stderr, "ede-sim: --resume continues the log in place: it takes no -o or --set\n"), 2;

  const ede::Status distinct = ede::tools::check_outputs_distinct(
      {{"the scene", opt.scene_path}, {"the log to resume", opt.resume_path}, {"the log to continue", opt.continue_path}},
      {{"-o", opt.log_path}, {"--final-state", opt.final_state_path}});
  if (!distinct) return fail(distinct.error().message);

  ede::tools::ProgressReporter progress(!opt.quiet, "ede-sim");
  ede::tools::PaceWatch pace("ede-sim");
  ede::SimulationOptions sim_options{opt.log_path, [&](const ede::Progress& p) {
                                       progress.update(p.fraction, p.events, p.time);
                                       pace.update(p.fraction, p.events, p.wall_seconds);
                                     }};
  sim_options.check_exactness = opt.check_exactness;
  auto made = start(opt, sim_options);
  if (!made) return fail(made.error().message);
  ede::Simulation& sim = made.value();
  ede::RunStatus status;
  {
    ede::tools::InterruptGuard guard(sim);
    try {
      status = sim.run();
    } catch (const std::bad_alloc&) {
      progress.finish();
      return fail(ede::tools::out_of_memory_message("running " + sim.scene().source_name + " at t = " +
                                                    ede::brief(double(sim.time()))));
    }
  }
  progress.finish();
  const ede::Status closed = sim.close();
  const ede::RunSummary summary = sim.summary();
  std::printf("%s", opt.json ? (ede::to_json(summary) + "\n").c_str() : ede::to_text(summary).c_str());
  if (!closed) {
    fail(closed.error().message);
    if (auto kept = sim.log_kept(); kept && kept.value().resumable)
      std::fprintf(stderr,
                   "ede-sim: the run stopped there; %s keeps %llu events. Free space and continue with `ede-sim "
                   "--resume %s` (from event %llu)\n",
                   kept.value().path.c_str(), static_cast<unsigned long long>(kept.value().events),
                   kept.value().path.c_str(), static_cast<unsigned long long>(kept.value().resume_event));
    return 1;
  }
  if (auto kept = sim.log_kept(); kept && !opt.json) print_log_line(kept.value());
  if (sim.interrupted()) {
    print_kept(sim);
    return ede::tools::InterruptGuard::exit_status();
  }
  const int code = exit_status(status);
  if (!opt.final_state_path.empty()) {
    if (status == ede::RunStatus::NonFinite)
      std::fprintf(stderr, "ede-sim: no final state was written to %s: the state holds non-finite numbers\n",
                   opt.final_state_path.c_str());
    else if (ede::Status s = sim.write_state_csv(opt.final_state_path); !s)
      return fail(s.error().message);
  }
  if (code != 0) ede::tools::report_error("ede-sim", std::string(ede::to_string(status)) + ": " + sim.message());
  return code;
}

int main(int argc, char** argv) { return ede::tools::run_tool("ede-sim", run, argc, argv); }
