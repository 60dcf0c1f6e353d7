// VerifySink: the comparing sink of Log::verify (run/verify.cpp). Added to the re-run's engine, it compares
// each event the engine emits with the log's next one (Replay::next_event): time, kind, disks, and the
// post-event velocities the kind has; at the start the initial state with the log's first keyframe. The
// keyframes are checked too, where the writer took them: a keyframe that disagrees with the run would make
// seeks (ede-replay --at) or a resume (ede-sim --resume) wrong even when every event is right. The first
// difference (or an unreadable record) stops the comparison; verify stops the run at its next slice.
// A sink, like the log writer it checks: it reads the outcomes and never changes the run.
#pragma once

#include <string>

#include "core/sink.hpp"
#include "log/log_reader.hpp"
#include "replay/event_compare.hpp"
#include "replay/replay.hpp"
#include "run/run_resume.hpp"

namespace ede {

namespace verify_detail {

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
class VerifySink final : public Sink<T> {
 public:
  VerifySink(Replay<T>& replay, Replay<T>& probe, const LogReader& log) : replay_(replay), probe_(probe), log_(log) {}

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
    auto stored = resume_point_at(replay_, k);
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

}  // namespace verify_detail

using verify_detail::VerifySink;

}  // namespace ede
