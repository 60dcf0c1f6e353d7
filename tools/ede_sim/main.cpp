// ede-sim: scene -> run -> event log, summary (text or JSON), final state as CSV.
//
//   ede-sim SCENE.toml [-o LOG] [--set key=value]... [--json] [--final-state FILE.csv] [--quiet]
//   ede-sim --resume LOG [--json] [--final-state FILE.csv] [--quiet]
//
// Thin: parses the command line, loads and sets up the scene through libede, runs the engine in slices
// so it can report progress, prints the summary. --resume reads the scene from the log's header, cuts the
// log at its last resumable keyframe and continues the run from there: the resumed log holds exactly the
// events an uninterrupted run writes. Exit status: 0 when the run ended on a stop condition or ran out of
// events, 3 when it stalled (inelastic collapse), 1 on bad input or an I/O error, 2 on a bad command line.
// engine.scalar = "float128" (where built with EDE_HAVE_FLOAT128) runs the __float128 engine for the
// accuracy study: the log format holds float, double and long double only, so such a run takes no -o (it
// still prints its summary and writes --final-state with 36 significant digits).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/engine.hpp"
#include "report_error.hpp"
#include "log/log_reader.hpp"
#include "log/log_writer.hpp"
#include "replay/replay.hpp"
#include "run/run_summary.hpp"
#include "scene/scene_loader.hpp"
#include "setup/setup.hpp"
#include "command_line.hpp"
#include "core/state_csv.hpp"
#include "progress.hpp"
#include "scalar_dispatch.hpp"

namespace {

struct Options {
  std::string scene_path;
  std::string log_path;
  std::string resume_path;
  std::vector<std::string> overrides;
  std::string final_state_path;
  bool json = false;
  bool quiet = false;
};

int fail(const std::string& message) {
  ede::tools::report_error("ede-sim", message);
  return 1;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Everything a run needs, from a scene file or from a log being resumed.
struct Prepared {
  ede::Scene scene;
  ede::InitialState initial;
  ede::EngineOptions options;
  std::shared_ptr<ede::LogReader> resumed_log;  // set when resuming
};

template <class T>
struct Resumption {
  ede::ResumePoint<T> point;
  ede::LogContinuation continuation;
};

template <class T>
ede::Result<Resumption<T>> prepare_resumption(const ede::LogReader& log) {
  auto k = log.last_resumable_keyframe();
  if (!k) return k.error();
  auto replay = ede::Replay<T>::create(std::shared_ptr<const ede::LogReader>(&log, [](const ede::LogReader*) {}));
  if (!replay) return replay.error();
  auto point = replay.value()->resume_point(k.value());
  if (!point) return point.error();
  Resumption<T> r{std::move(point).value(), {}};
  const ede::LogRecordRef& kf = log.keyframes()[k.value()];
  r.continuation.cut_offset = kf.offset + 56 + kf.payload_size;
  r.continuation.events_before = kf.first_event;
  for (const auto* list : {&log.chunks(), &log.keyframes()})
    for (const ede::LogRecordRef& e : *list)
      if (e.offset <= kf.offset)
        r.continuation.entries.push_back({e.kind, e.offset, e.first_event, e.count, e.time_first, e.time_last, e.resumable});
  std::sort(r.continuation.entries.begin(), r.continuation.entries.end(),
            [](const auto& a, const auto& b) { return a.offset < b.offset; });
  return r;
}

// The log sink of a run in T: none for __float128, which the log format does not hold.
template <class T>
using LogFor = std::conditional_t<ede::tools::kLogScalar<T>, std::unique_ptr<ede::LogWriter<T>>, std::nullptr_t>;

template <class T>
int run(const Options& opt, const Prepared& prep, double setup_seconds) {
  const auto setup_start = std::chrono::steady_clock::now();
  const ede::Scene& scene = prep.scene;
  std::unique_ptr<Resumption<T>> resumption;
  if constexpr (ede::tools::kLogScalar<T>) {
    if (prep.resumed_log) {
      auto r = prepare_resumption<T>(*prep.resumed_log);
      if (!r) return fail(r.error().message);
      resumption = std::make_unique<Resumption<T>>(std::move(r).value());
    }
  }
  auto made = ede::make_engine<T>(prep.initial, prep.options, resumption ? &resumption->point : nullptr);
  if (!made) return fail(scene.source_name + ": " + made.error().message);
  ede::EngineApi<T>& engine = *made.value();

  LogFor<T> log;
  const std::string log_path = prep.resumed_log ? opt.resume_path : opt.log_path;
  if constexpr (ede::tools::kLogScalar<T>) {
    if (!log_path.empty()) {
      auto w = ede::LogWriter<T>::create(log_path,
                                         ede::LogRunInfo::from(scene, prep.options, prep.initial.species_names),
                                         ede::LogSettings::from(scene.log),
                                         resumption ? &resumption->continuation : nullptr);
      if (!w) return fail(w.error().message);
      log = std::move(w).value();
      engine.add_sink(log.get());  // first, as DESIGN.md orders the sinks
    }
  }

  double px0 = 0, py0 = 0;
  for (std::size_t i = 0; i < prep.initial.size(); ++i) {
    px0 += prep.initial.mass[i] * prep.initial.vx[i];
    py0 += prep.initial.mass[i] * prep.initial.vy[i];
  }
  ede::tools::ProgressReporter progress(!opt.quiet, "ede-sim");
  const auto start = std::chrono::steady_clock::now();
  ede::RunStatus status;
  // Slices of 2^18 events: progress a few times a second at ~1 M events/s, no measurable overhead.
  while ((status = engine.run(1u << 18)) == ede::RunStatus::Running) {
    const auto& c = engine.counts();
    const double ratio = engine.initial_kinetic_energy() > 0
                             ? ede::kinetic_energy(engine.particles()) / engine.initial_kinetic_energy()
                             : 1;
    const ede::tools::ProgressInputs now{double(engine.time()), c.events(), c.of(ede::EventKind::Pair),
                                         scene.stop.energy_fraction ? ratio : 1.0};
    progress.update(ede::tools::progress_fraction(scene.stop, prep.initial.size(), now), c.events(),
                    double(engine.time()));
  }
  const double wall = seconds_since(start);
  progress.finish();

  ede::RunSummary summary = ede::summarize(engine, px0, py0);
  summary.scene = scene.source_name;
  summary.seed = scene.seed;
  summary.status = ede::to_string(status);
  summary.wall_seconds = wall;
  summary.setup_seconds = setup_seconds + seconds_since(setup_start) - wall;
  if (opt.json)
    std::printf("%s\n", ede::to_json(summary).c_str());
  else
    std::printf("%s", ede::to_text(summary).c_str());
  if constexpr (ede::tools::kLogScalar<T>) {
    if (log) {
      if (const std::string e = log->error(); !e.empty()) return fail("the event log is incomplete: " + e);
      if (!opt.json)
        std::printf("event log        %s: %llu events, %.4g MiB, %.3g bytes/event\n", log_path.c_str(),
                    static_cast<unsigned long long>(log->events_logged()), double(log->bytes_written()) / 1048576,
                    log->events_logged() ? double(log->bytes_written()) / double(log->events_logged()) : 0.0);
    }
  }
  if (!opt.final_state_path.empty()) {
    if (auto s = ede::write_state_csv_file(opt.final_state_path, engine.particles(), engine.time(),
                                           prep.initial.species_names);
        !s)
      return fail(s.error().message);
  }
  return status == ede::RunStatus::Stalled ? 3 : 0;
}

// The scene and initial state of a log being resumed: the effective scene stored in its header, set up
// again (setup is deterministic), and checked against the header's per-disk data.
ede::Result<Prepared> prepare_resume(const std::string& path) {
  auto log = ede::LogReader::open(path);
  if (!log) return log.error();
  const ede::LogHeaderInfo& h = log.value()->header();
  if (log.value()->complete())
    return ede::Error{path + ": the run already finished (" + log.value()->final_status() + "); nothing to resume"};
  auto scene = ede::parse_scene_text(h.scene_text, h.scene_name);
  if (!scene) return ede::Error{path + ": the scene in the log's header no longer loads: " + scene.error().message};
  auto initial = ede::build_initial_state(scene.value());
  if (!initial) return initial.error();
  if (initial.value().size() != h.disks)
    return ede::Error{path + ": setting the scene up again gives " + std::to_string(initial.value().size()) +
                      " disks, the log has " + std::to_string(h.disks) + " (a different ede version?)"};
  Prepared p{scene.value(), std::move(initial).value(), {}, log.value()};
  p.options = ede::engine_options_from(p.scene, p.initial.size());
  if (p.options.rebuild_interval != h.rebuild_interval)
    return ede::Error{path + ": the rebuild interval differs from the log's (a different ede version?)"};
  return p;
}

ede::Result<Prepared> prepare_new(const Options& opt) {
  std::vector<ede::Override> overrides;
  for (const std::string& o : opt.overrides) overrides.push_back({o});
  auto scene = ede::load_scene_file(opt.scene_path, overrides);
  if (!scene) return scene.error();
  auto initial = ede::build_initial_state(scene.value());
  if (!initial) return initial.error();
  Prepared p{scene.value(), std::move(initial).value(), {}, nullptr};
  p.options = ede::engine_options_from(p.scene, p.initial.size());
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  CLI::App app{"ede-sim: run an event-driven hard-disk simulation from a scene file"};
  app.add_option("scene", opt.scene_path, "scene file (TOML); see docs/scene-format.md");
  app.add_option("-o,--log", opt.log_path, "write every event to this log (any file name; see schema/FORMAT.md)");
  app.add_option("--resume", opt.resume_path, "continue the interrupted run logged in this file, in place");
  app.add_option("--set", opt.overrides, "override a scene value, e.g. --set physics.restitution=0.9 (repeatable)");
  app.add_flag("--json", opt.json, "print the summary as one JSON object on stdout");
  app.add_option("--final-state", opt.final_state_path, "write the final state as CSV (exact numbers)");
  app.add_flag("-q,--quiet", opt.quiet, "no progress output");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return *stop;
  if (opt.resume_path.empty() == opt.scene_path.empty())
    return std::fprintf(stderr, "ede-sim: give either a scene file or --resume LOG\n"), 2;
  if (!opt.resume_path.empty() && (!opt.log_path.empty() || !opt.overrides.empty()))
    return std::fprintf(stderr, "ede-sim: --resume continues the log in place: it takes no -o or --set\n"), 2;

  const auto start = std::chrono::steady_clock::now();
  auto prepared = opt.resume_path.empty() ? prepare_new(opt) : prepare_resume(opt.resume_path);
  if (!prepared) return fail(prepared.error().message);
  const double setup_seconds = seconds_since(start);
  if (prepared.value().scene.scalar == ede::ScalarKind::Float128 && !opt.log_path.empty())
    return fail("float128 runs are for the accuracy study and write no event log (the log format holds float, "
                "double and long double): run without -o");
  return ede::tools::with_engine_scalar(prepared.value().scene.scalar, [&]<class T>() {
    return run<T>(opt, prepared.value(), setup_seconds);
  });
}
