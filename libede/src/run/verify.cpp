// Log::verify: re-run the scene a log records and compare every event with the log, bit for bit.
//
// The scene comes from the header (the effective TOML, after overrides), planned and started again as
// ede-sim does (run_plan.hpp); a comparing sink (verify_sink.hpp) checks every event and keyframe as the
// engine emits them, and at the end the event total, the final time and the status are compared. The first
// difference stops the run (checked between slices of the run, so a long run is not finished for nothing).
// A log cut short (killed run) is verified as far as it goes and says so. Here in run/, beside the run it
// repeats: replay/ reads logs and never runs the engine.
#include <memory>
#include <string>

#include "core/engine_revision.hpp"
#include "core/scalar_dispatch.hpp"
#include "ede/log.hpp"
#include "replay/log_impl.hpp"
#include "run/run_plan.hpp"
#include "run/run_start.hpp"
#include "run/verify_sink.hpp"

namespace ede {

namespace {

// The run the header describes, planned again; refused if it cannot be the logged run. A run that started
// from a state ([start]) is rerun from the state its log starts with (the header's disks and first
// keyframe): the source log or CSV is not needed to verify the log.
Result<RunPlan> plan_rerun(const Log& log_face, const LogReader& log) {
  const LogHeaderInfo& h = log.header();
  auto scene = parse_scene_text(h.scene_text, h.scene_name);
  if (!scene) return Error{log.path() + ": the scene in the log's header does not load: " + scene.error().message};
  Result<RunPlan> plan = Error{""};
  if (scene.value().start) {
    auto first = log_face.state_at_event(0);
    if (!first) return first.error();
    plan = plan_run_from(scene.value(), initial_state_of(first.value()));
  } else {
    plan = plan_run(scene.value());
  }
  if (!plan) return Error{log.path() + ": the scene in the log's header cannot be set up: " + plan.error().message};
  const RunPlan& r = plan.value();
  if (r.initial.size() != h.disks)
    return Error{log.path() + ": setting the scene up again gives " + std::to_string(r.initial.size()) +
                 " disks, the log has " + std::to_string(h.disks)};
  if (r.scene.scalar != h.scalar)
    return Error{log.path() + ": the header's scene asks for " + to_string(r.scene.scalar) + ", the log is " +
                 to_string(h.scalar)};
  if (r.options.rebuild_interval != h.rebuild_interval)
    return Error{log.path() + ": the scene's rebuild interval (" + std::to_string(r.options.rebuild_interval) +
                 ") differs from the log's (" + std::to_string(h.rebuild_interval) + ")"};
  return plan;
}

// After a run that ended on its own: the totals, the final time and the status must match too.
template <class T>
std::string compare_end(const VerifySink<T>& cmp, const EngineApi<T>& engine, RunStatus status, const Replay<T>& replay,
                        const LogReader& log) {
  if (cmp.compared() != log.total_events())
    return "the re-run ended (" + std::string(to_string(status)) + ") after " + std::to_string(cmp.compared()) +
           " events; the log has " + std::to_string(log.total_events());
  if (!log.complete()) return "";
  if (!same_bits(engine.time(), replay.final_time()))
    return "the final time differs: re-run " + exact(engine.time()) + ", log " + exact(replay.final_time());
  // A run the end check refused (Inexact: overlapping disks, an overflowed clock) ended for the engine as
  // any run does: the re-run's own end (the engine has no end check) is the one the log's status replaced.
  const RunStatus logged = status_from_text(log.final_status());
  const bool refused_at_end = logged == RunStatus::Inexact && status != RunStatus::Stalled &&
                              status != RunStatus::Collapsed && status != RunStatus::NonFinite;
  if (logged != status && !refused_at_end)
    return "the run ended differently: re-run '" + std::string(to_string(status)) + "', log '" + log.final_status() +
           "'";
  return "";
}

template <class T>
Result<VerifyReport> verify_in(const std::shared_ptr<LogReader>& log, RunPlan& plan, const VerifyOptions& opt) {
  auto made_replay = Replay<T>::create(log);
  if (!made_replay) return made_replay.error();
  Replay<T>& replay = *made_replay.value();
  auto made_probe = Replay<T>::create(log);
  if (!made_probe) return made_probe.error();
  auto run = start_run<T>(plan);
  if (!run) return run.error();
  EngineApi<T>& engine = *run.value().engine;
  VerifySink<T> cmp(replay, *made_probe.value(), *log);
  engine.add_sink(&cmp);

  const double total = double(std::max<std::uint64_t>(log->total_events(), 1));
  RunStatus status;
  // A complete log whose status is EndedByProgram was ended by Simulation::finish at its final time, with
  // every event up to that time: the re-run stops there too, as advance_to does. ("running" is what
  // finish wrote before that status existed, in logs of 2026-11-26.)
  const bool finished_early = log->complete() && (log->final_status() == to_string(RunStatus::EndedByProgram) ||
                                                  log->final_status() == to_string(RunStatus::Running));
  const T stop_at = finished_early ? replay.final_time() : T(0);
  bool paused = false;  // finished_early: the re-run has processed every event up to stop_at
  const auto slice = [&] {
    if (!finished_early) return engine.run(1u << 16);
    const std::uint64_t before = engine.counts().events() + engine.counts().of(EventKind::Sample);
    const RunStatus s = engine.run_until(stop_at, 1u << 16);
    paused = s == RunStatus::Running &&
             engine.counts().events() + engine.counts().of(EventKind::Sample) - before < (1u << 16);
    return s;
  };
  // Slices of 2^16 events: a difference stops the run within a few milliseconds of being found.
  while ((status = slice()) == RunStatus::Running && !paused && !cmp.stopped())
    if (opt.progress) opt.progress(double(cmp.compared()) / total, cmp.compared());
  // Paused at the finished log's final time: the re-run ended as Simulation::finish ends a run (a log of
  // the old spelling, "running", compares as written).
  if (finished_early && paused && status == RunStatus::Running &&
      log->final_status() == to_string(RunStatus::EndedByProgram))
    status = RunStatus::EndedByProgram;

  VerifyReport r;
  r.events_compared = cmp.compared();
  r.keyframes_checked = cmp.keyframes_checked();
  r.resumable_checked = cmp.resumable_checked();
  const std::string events = std::to_string(cmp.compared()) + " events";
  const std::string keyframes = ", " + std::to_string(cmp.keyframes_checked()) + " keyframes (" +
                                std::to_string(cmp.resumable_checked()) + " resumable) match the re-run's state";
  if (!cmp.unreadable().empty())
    return Error{cmp.unreadable() + " (the " + events + " before it are identical)", ErrorKind::Corrupt};
  // A log of another engine revision may take another trajectory: a difference is then expected, and said so.
  const std::string revision = revision_note(log->header().engine_version);
  const auto different = [&](const std::string& what, const std::string& identical_part) {
    r.difference = what;
    r.text = "DIFFERENT: " + what + "\n(" + identical_part + ")\n";
    if (!revision.empty()) r.text += "note: " + revision + "\n";
    return r;
  };
  if (!cmp.difference().empty()) return different(cmp.difference(), "the " + events + " before it are identical");
  if (log->damaged())
    return Error{log->path() + " is damaged: " + log->incomplete_reason() + " (the " + events +
                     " before the damage are identical)",
                 ErrorKind::Corrupt};
  if (!log->complete() && (cmp.log_ended() || cmp.compared() == log->total_events())) {
    r.identical = r.partial = true;
    r.text = "verified: " + events + " identical" + keyframes + "; the log is incomplete (" +
             log->incomplete_reason() + "), so the rest of the run was not compared\n";
    return r;
  }
  if (cmp.log_ended())
    return different("the log ends after " + events + " (" + log->final_status() + "), the re-run goes on",
                     "the " + events + " are identical");
  if (const std::string d = compare_end(cmp, engine, status, replay, *log); !d.empty())
    return different(d, "the first " + events + " are identical");
  r.identical = true;
  r.text = "verified: " + events + " identical" + keyframes + " (final time " + exact(engine.time()) + ", " +
           log->final_status() + ")\n";
  return r;
}

}  // namespace

Result<VerifyReport> Log::verify(const VerifyOptions& options) const {
  const std::shared_ptr<LogReader>& log = reader_of(*this);
  auto plan = plan_rerun(*this, *log);
  if (!plan) return plan.error();
  return with_scalar(log->header().scalar, [&]<class T>() { return verify_in<T>(log, plan.value(), options); });
}

}  // namespace ede
