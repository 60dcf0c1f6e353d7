// ede-sim: scene -> run -> event log, summary (text or JSON), final state as CSV.
//
//   ede-sim SCENE.toml [-o LOG] [--set key=value]... [--json] [--final-state FILE.csv] [-q]
//   ede-sim --resume LOG [--json] [--final-state FILE.csv] [-q]
//
// Thin: parses the command line, hands the scene to ede::Simulation, prints. Exit status: 0 when the run
// ended on a stop condition or ran out of events, 3 when it stalled (inelastic collapse), 1 on bad input
// or an I/O error, 2 on a bad command line, 130 (143) when interrupted by Ctrl-C (SIGTERM): then the
// summary so far, what the log kept and how to resume are printed.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "ede/ede.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "report_error.hpp"

namespace {

struct Options {
  std::string scene_path, log_path, resume_path, final_state_path;
  std::vector<std::string> overrides;
  bool json = false, quiet = false;
};

int fail(const std::string& message) {
  ede::tools::report_error("ede-sim", message);
  return 1;
}

ede::Result<ede::Simulation> start(const Options& opt, const ede::SimulationOptions& sim_options) {
  if (!opt.resume_path.empty()) return ede::Simulation::resume(opt.resume_path, sim_options);
  std::vector<ede::Override> overrides;
  for (const std::string& o : opt.overrides) overrides.push_back({o});
  auto scene = ede::load_scene_file(opt.scene_path, overrides);
  if (!scene) return scene.error();
  return ede::Simulation::create(scene.value(), sim_options);
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

int main(int argc, char** argv) {
  Options opt;
  CLI::App app{"ede-sim: run an event-driven hard-disk simulation from a scene file"};
  app.add_option("scene", opt.scene_path, "scene file (TOML); see docs/scene-format.md");
  app.add_option("-o,--output,--log", opt.log_path, "write every event to this log (any file name; see schema/FORMAT.md)");
  app.add_option("--resume", opt.resume_path, "continue the interrupted run logged in this file, in place");
  app.add_option("--set", opt.overrides, "override a scene value, e.g. --set physics.restitution=0.9 (repeatable)");
  app.add_flag("--json", opt.json, "print the summary as one JSON object on stdout");
  app.add_option("--final-state", opt.final_state_path, "write the final state as CSV (exact numbers)");
  app.add_flag("-q,--quiet", opt.quiet, "no progress output");
  ede::tools::add_version_flags(app, "ede-sim");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return *stop;
  if (opt.resume_path.empty() == opt.scene_path.empty())
    return std::fprintf(stderr, "ede-sim: give either a scene file or --resume LOG (see ede-sim --help)\n"), 2;
  if (!opt.resume_path.empty() && (!opt.log_path.empty() || !opt.overrides.empty()))
    return std::fprintf(stderr, "ede-sim: --resume continues the log in place: it takes no -o or --set\n"), 2;

  ede::tools::ProgressReporter progress(!opt.quiet, "ede-sim");
  ede::SimulationOptions sim_options{
      opt.log_path, [&](const ede::Progress& p) { progress.update(p.fraction, p.events, p.time); }};
  auto made = start(opt, sim_options);
  if (!made) return fail(made.error().message);
  ede::Simulation& sim = made.value();
  ede::RunStatus status;
  {
    ede::tools::InterruptGuard guard(sim);
    status = sim.run();
  }
  progress.finish();
  const ede::Status closed = sim.close();
  const ede::RunSummary summary = sim.summary();
  std::printf("%s", opt.json ? (ede::to_json(summary) + "\n").c_str() : ede::to_text(summary).c_str());
  if (!closed) return fail(closed.error().message);
  if (auto kept = sim.log_kept(); kept && !opt.json) print_log_line(kept.value());
  if (sim.interrupted()) {
    print_kept(sim);
    return ede::tools::InterruptGuard::exit_status();
  }
  if (!opt.final_state_path.empty())
    if (ede::Status s = sim.write_state_csv(opt.final_state_path); !s) return fail(s.error().message);
  return status == ede::RunStatus::Stalled ? 3 : 0;
}
