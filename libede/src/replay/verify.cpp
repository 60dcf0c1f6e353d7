// Log::verify: re-run the scene a log records and compare every event with the log, bit for bit.
//
// The scene comes from the header (the effective TOML, after overrides), set up and run again exactly as
// ede-sim does. A sink compares each event the engine emits with the log's next one (Replay::next_event):
// time, kind, disks, and the post-event velocities the kind has; at the start it compares the initial
// state with the log's first keyframe, and at the end the event total, the final time and the status.
// The keyframes are checked too, where the writer took them: a keyframe that disagrees with the run would
// make seeks (ede-replay --at) or a resume (ede-sim --resume) wrong even when every event is right.
// The first difference stops the run (checked between slices of the run, so a long run is not finished
// for nothing). A log cut short (killed run) is verified as far as it goes and says so.
#include <memory>
#include <string>

#include "core/scalar_dispatch.hpp"
#include "ede/log.hpp"
#include "core/engine_revision.hpp"
#include "engine/engine.hpp"
#include "replay/event_compare.hpp"
#include "replay/log_impl.hpp"
#include "setup/setup.hpp"

namespace ede {

namespace {

template <class T>
ReplayedEvent<T> as_replayed(const EventOutcome<T>& o, std::uint64_t index) {
  ReplayedEvent<T> r{index, o.time, o.kind, o.i, o.j, o.vix, o.viy, o.vjx, o.vjy};
  r.wi = o.wi, r.wj = o.wj;
  return r;
}

// The first field in which two disk records differ, or "".
template <class T>
std::string record_difference(const Disk<T>& a, const Disk<T>& b) {
  if (!same_bits(a.x, b.x)) return "x";
  if (!same_bits(a.y, b.y)) return "y";
  if (!same_bits(a.vx, b.vx)) return "vx";
  if (!same_bits(a.vy, b.vy)) return "vy";
  if (!same_bits(a.t, b.t)) return "t";
  return "";
}

template <class T>
std::string record_text(const Disk<T>& d) {
  return "x = (" + exact(d.x) + ", " + exact(d.y) + "), v = (" + exact(d.vx) + ", " + exact(d.vy) +
         "), t = " + exact(d.t);
}

// Compares the engine's events with the log's as they happen, and the log's keyframes with the engine's
// state where the writer took them: the state of the keyframe a seek uses at each event index (read with
// a second Replay, `probe`), and everything a resume reads from each resumable keyframe (resume_point,
// checked at the engine's rebuilds, where the writer wrote them). The first difference ends it all.
template <class T>
class Comparer final : public Sink<T> {
 public:
  Comparer(Replay<T>& replay, Replay<T>& probe, const LogReader& log) : replay_(replay), probe_(probe), log_(log) {}

  void on_start(T, const Particles<T>& p) override {
    const Particles<T>& q = replay_.particles();
    for (std::size_t i = 0; i < p.size() && difference_.empty(); ++i) {
      const Disk<T>&a = p.disk[i], &b = q.disk[i];
      if (!same_bits(a.x, b.x) || !same_bits(a.y, b.y) || !same_bits(a.vx, b.vx) || !same_bits(a.vy, b.vy) ||
          !same_bits(a.r, b.r) || !same_bits(p.mass(i), q.mass(i)) || p.species_of(i) != q.species_of(i))
        difference_ = "the initial state differs at disk " + std::to_string(i) + ":\n  re-run: " + disk_text(p, i) +
                      "\n  log:    " + disk_text(q, i);
    }
  }

  void on_event(const EventOutcome<T>& o, const Particles<T>& p) override {
    if (stopped() || o.kind == EventKind::Cell) return;
    if (replay_.events_applied() >= log_.total_events()) {
      log_ended_ = true;
      return;
    }
    auto logged = replay_.next_event();
    if (!logged) {
      unreadable_ = "the log cannot be read at event " + std::to_string(compared_) + ": " + logged.error().message;
      return;
    }
    const ReplayedEvent<T> engine = as_replayed(o, compared_);
    if (const std::string field = first_difference(engine, logged.value()); !field.empty()) {
      difference_ = "event " + std::to_string(compared_) + " differs (" + field + "):\n  re-run: " + describe(engine) +
                    "\n  log:    " + describe(logged.value());
      return;
    }
    ++compared_;
    check_keyframe_state(p, &o.time);
  }

  void on_rebuild(const RebuildPoint<T>& point) override {
    if (stopped()) return;
    check_keyframe_state(point.particles, nullptr);
    if (!stopped()) check_resumable(point);
  }

  bool stopped() const { return log_ended_ || !difference_.empty() || !unreadable_.empty(); }
  bool log_ended() const { return log_ended_; }
  const std::string& difference() const { return difference_; }
  const std::string& unreadable() const { return unreadable_; }
  std::uint64_t compared() const { return compared_; }
  std::size_t keyframes_checked() const { return keyframes_checked_; }
  std::size_t resumable_checked() const { return resumable_checked_; }

 private:
  static std::string disk_text(const Particles<T>& p, std::size_t i) {
    const Disk<T>& d = p.disk[i];
    return "x = (" + exact(d.x) + ", " + exact(d.y) + "), v = (" + exact(d.vx) + ", " + exact(d.vy) +
           "), r = " + exact(d.r) + ", m = " + exact(p.mass(i)) + ", species " + std::to_string(p.species_of(i));
  }

  std::string keyframe_name(std::size_t k) const {
    return "keyframe " + std::to_string(k) + " (at event " + std::to_string(log_.keyframes()[k].first_event) +
           ", byte " + std::to_string(log_.keyframes()[k].offset) + ")";
  }

  // The keyframes at event compared_, if not checked yet: the last of them is the one seeks load; its
  // disk records must be the engine's (and, unless it was taken at a rebuild, its time the event's).
  void check_keyframe_state(const Particles<T>& p, const T* event_time) {
    const auto& kfs = log_.keyframes();
    if (next_state_ >= kfs.size() || kfs[next_state_].first_event != compared_) return;
    std::size_t k = next_state_;
    while (k + 1 < kfs.size() && kfs[k + 1].first_event == compared_) ++k;
    next_state_ = k + 1;
    if (Status s = probe_.seek_event(compared_); !s) {
      unreadable_ = s.error().message;
      return;
    }
    const Particles<T>& q = probe_.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (const std::string field = record_difference(p.disk[i], q.disk[i]); !field.empty()) {
        difference_ = keyframe_name(k) + " differs from the re-run's state at disk " + std::to_string(i) + " (" +
                      field + "):\n  re-run: " + record_text(p.disk[i]) + "\n  log:    " + record_text(q.disk[i]);
        return;
      }
    if (event_time && !kfs[k].resumable && !same_bits(*event_time, probe_.time())) {
      difference_ =
          keyframe_name(k) + " has time " + exact(probe_.time()) + ", the event before it " + exact(*event_time);
      return;
    }
    ++keyframes_checked_;
  }

  // The engine rebuilt its predictions: the writer wrote the next resumable keyframe here.
  void check_resumable(const RebuildPoint<T>& point) {
    const auto& kfs = log_.keyframes();
    while (next_resumable_ < kfs.size() && !kfs[next_resumable_].resumable) ++next_resumable_;
    if (next_resumable_ >= kfs.size()) {
      if (log_.complete())
        difference_ = "the re-run rebuilt its predictions at event " + std::to_string(compared_) +
                      " (t = " + exact(point.time) + "), but the log has no resumable keyframe there";
      return;
    }
    const std::size_t k = next_resumable_++;
    if (kfs[k].first_event != compared_) {
      difference_ = "the re-run rebuilt its predictions at event " + std::to_string(compared_) + ", but the next " +
                    "resumable keyframe is " + keyframe_name(k);
      return;
    }
    auto stored = replay_.resume_point(k);
    if (!stored) {
      unreadable_ = stored.error().message;
      return;
    }
    if (const std::string field = resume_difference(stored.value(), point); !field.empty()) {
      difference_ = keyframe_name(k) + " would not resume the run: its " + field + " differs from the re-run's";
      return;
    }
    ++resumable_checked_;
  }

  static std::string resume_difference(const ResumePoint<T>& r, const RebuildPoint<T>& point) {
    const Particles<T>& p = point.particles;
    if (!same_bits(r.time, point.time)) return "time";
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (const std::string field = record_difference(r.disks[i], p.disk[i]); !field.empty())
        return field + " of disk " + std::to_string(i);
      if (r.disks[i].last_partner != p.disk[i].last_partner) return "last partner of disk " + std::to_string(i);
    }
    if (r.last_collision.size() != p.last_collision.size()) return "TC times";
    for (std::size_t i = 0; i < p.last_collision.size(); ++i)
      if (!same_bits(r.last_collision[i], p.last_collision[i])) return "TC time of disk " + std::to_string(i);
    for (int c = 0; c < kEventKindCount; ++c)
      if (r.counts.by_kind[c] != point.counts.by_kind[c]) return std::string("count of ") + to_string(EventKind(c));
    if (r.counts.stale != point.counts.stale || r.counts.tc_elastic != point.counts.tc_elastic) return "counters";
    if (r.next_sample_index != point.next_sample_index) return "sample count";
    if (r.next_action_index != point.next_action_index) return "action count";
    if (r.same_time_events != point.same_time_events) return "stall counter";
    return "";
  }

  Replay<T>& replay_;
  Replay<T>& probe_;
  const LogReader& log_;
  std::uint64_t compared_ = 0;
  std::size_t next_state_ = 0, next_resumable_ = 0;
  std::size_t keyframes_checked_ = 0, resumable_checked_ = 0;
  bool log_ended_ = false;
  std::string difference_, unreadable_;
};

struct Rerun {
  Scene scene;
  InitialState initial;
  EngineOptions options;
};

Result<InitialState> initial_state_from_log(const std::string& path) {
  auto log = Log::open(path);
  if (!log) return log.error();
  auto s = log.value().state_at_event(0);
  if (!s) return s.error();
  const State& st = s.value();
  InitialState init;
  init.lx = st.lx, init.ly = st.ly;
  init.species_names = st.species_names;
  for (std::size_t i = 0; i < st.size(); ++i)
    init.add(st.x[i], st.y[i], st.vx[i], st.vy[i], st.radius[i], st.mass[i], st.species[i]);
  return init;
}

// The run the header describes, set up again; refused if it cannot be the logged run.
Result<Rerun> prepare_rerun(const LogReader& log) {
  const LogHeaderInfo& h = log.header();
  auto scene = parse_scene_text(h.scene_text, h.scene_name);
  if (!scene) return Error{log.path() + ": the scene in the log's header does not load: " + scene.error().message};
  // A run that started from a state ([start]) is rerun from the state its log starts with (the header's
  // disks and first keyframe): the source log or CSV is not needed to verify the log.
  auto initial = scene.value().start ? initial_state_from_log(log.path()) : build_initial_state(scene.value());
  if (!initial)
    return Error{log.path() + ": the scene in the log's header cannot be set up: " + initial.error().message};
  Rerun r{scene.value(), std::move(initial).value(), {}};
  if (r.initial.size() != h.disks)
    return Error{log.path() + ": setting the scene up again gives " + std::to_string(r.initial.size()) +
                 " disks, the log has " + std::to_string(h.disks)};
  if (r.scene.scalar != h.scalar)
    return Error{log.path() + ": the header's scene asks for " + to_string(r.scene.scalar) + ", the log is " +
                 to_string(h.scalar)};
  r.options = engine_options_from(r.scene, r.initial.size());
  if (r.options.rebuild_interval != h.rebuild_interval)
    return Error{log.path() + ": the scene's rebuild interval (" + std::to_string(r.options.rebuild_interval) +
                 ") differs from the log's (" + std::to_string(h.rebuild_interval) + ")"};
  return r;
}

// After a run that ended on its own: the totals, the final time and the status must match too.
template <class T>
std::string compare_end(const Comparer<T>& cmp, const EngineApi<T>& engine, RunStatus status, const Replay<T>& replay,
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
Result<VerifyReport> verify_in(const std::shared_ptr<LogReader>& log, const Rerun& rerun, const VerifyOptions& opt) {
  auto made_replay = Replay<T>::create(log);
  if (!made_replay) return made_replay.error();
  Replay<T>& replay = *made_replay.value();
  auto made_probe = Replay<T>::create(log);
  if (!made_probe) return made_probe.error();
  auto made_engine = make_engine<T>(rerun.initial, rerun.options);
  if (!made_engine) return Error{log->path() + ": " + made_engine.error().message};
  EngineApi<T>& engine = *made_engine.value();
  Comparer<T> cmp(replay, *made_probe.value(), *log);
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
  const std::shared_ptr<LogReader>& log = impl_->reader;
  auto rerun = prepare_rerun(*log);
  if (!rerun) return rerun.error();
  return with_scalar(log->header().scalar,
                     [&]<class T>() { return verify_in<T>(log, rerun.value(), options); });
}

}  // namespace ede
