// FiniteGuard<T>: the sink that stands between the engine and the run's other sinks (the log writer) and
// stops a run at the first event that produced a NaN or an infinity, naming that event.
//
// An overflow (masses near 1e308, speeds that grow without bound in a float run) turns a velocity or a
// time non-finite; every later event is meaningless, and a log holding such numbers is one no tool reads.
// The guard checks each outcome (time, the post-event velocities, the positions of the disks involved)
// before passing it on. On the first non-finite one it passes nothing more, closes the log with status
// NonFinite at the last good event (so the log up to there is complete and readable), and records the
// event number and what went wrong; the Simulation stops at the end of its slice and reports it.
// Checking x - x == 0 is true exactly for finite x in every scalar type (float128 too) without fast-math.
// At the end of a run it also asks the end check (run/end_check.hpp) whether the run may be reported as it
// ended; if not, the log is closed with status Inexact and the check's message is the run's.
// Rejected: a check in the engine's loop (the engine stays free of run policy; a sink sees every outcome
// anyway), and scanning the whole state between slices (O(N) per slice, and the event number is lost).
#pragma once

#include <cstdint>
#include <functional>
#include <sstream>
#include <string>

#include "core/sink.hpp"

namespace ede {

template <class T>
class FiniteGuard final : public Sink<T> {
 public:
  // `next`: the sink to protect (nullptr: none, the guard only detects); `first_event`: the number of the
  // first event this run will pass on (a resumed run's logged events before it).
  // `end_check`: empty when the run may end as it did, else the message of an Inexact stop.
  using EndCheck = std::function<std::string(T time, const Particles<T>& p, RunStatus status)>;
  FiniteGuard(Sink<T>* next, std::uint64_t first_event, EndCheck end_check = {})
      : next_(next), event_(first_event), end_check_(std::move(end_check)) {}

  bool tripped() const { return tripped_; }
  RunStatus stop_status() const { return stop_status_; }  // NonFinite or Inexact, once tripped
  const std::string& message() const { return message_; }

  void on_start(T time, const Particles<T>& p) override {
    if (next_) next_->on_start(time, p);
  }

  void on_event(const EventOutcome<T>& e, const Particles<T>& p) override {
    if (tripped_) return;
    if (const char* what = first_non_finite(e, p)) return trip(e, p, what);
    last_good_time_ = e.time;
    if (e.kind != EventKind::Cell) ++event_;
    if (next_) next_->on_event(e, p);
  }

  void on_sample(T time, const Particles<T>& p) override {
    if (!tripped_ && next_) next_->on_sample(time, p);
  }
  void on_rebuild(const RebuildPoint<T>& point) override {
    if (!tripped_ && next_) next_->on_rebuild(point);
  }
  void on_finish(T time, const Particles<T>& p, RunStatus status) override {
    if (tripped_) return;
    if (end_check_) {
      std::string problem = end_check_(time, p, status);
      if (!problem.empty()) {
        tripped_ = true;
        stop_status_ = RunStatus::Inexact;
        message_ = std::move(problem);
        if (next_) message_ += " The log holds every event of the run and is complete.";
        status = RunStatus::Inexact;
      }
    }
    if (next_) next_->on_finish(time, p, status);
  }
  bool wants_cell_events() const override { return next_ && next_->wants_cell_events(); }

 private:
  static bool finite(T v) { return v - v == T(0); }

  static const char* first_non_finite(const EventOutcome<T>& e, const Particles<T>& p) {
    if (!finite(e.time)) return "the event's time";
    if (!finite(e.vix) || !finite(e.viy) || !finite(e.vjx) || !finite(e.vjy)) return "a velocity after the event";
    for (const std::int32_t d : {e.i, e.kind == EventKind::Pair ? e.j : -1})
      if (d >= 0 && (!finite(p.disk[std::size_t(d)].x) || !finite(p.disk[std::size_t(d)].y)))
        return "a position";
    return nullptr;
  }

  void trip(const EventOutcome<T>& e, const Particles<T>& p, const char* what) {
    tripped_ = true;
    std::ostringstream m;
    m << "event " << event_ << " (" << to_string(e.kind);
    if (e.i >= 0) m << ", disk " << e.i;
    if (e.kind == EventKind::Pair) m << " and disk " << e.j;
    m << ", after t = " << double(last_good_time_) << ") produced a non-finite number (NaN or infinity) in "
      << what << ": the numbers overflowed the scalar type. The run stopped there";
    if (next_) m << "; the log holds every event before it and is complete";
    m << ". Fix: keep masses, speeds and the box within a few orders of magnitude of 1 (scale the units), or "
         "use a wider scalar (scalar = \"double\" or \"long double\").";
    message_ = m.str();
    if (next_) next_->on_finish(last_good_time_, p, RunStatus::NonFinite);
  }

  Sink<T>* next_;
  std::uint64_t event_;
  EndCheck end_check_;
  T last_good_time_{};
  bool tripped_ = false;
  RunStatus stop_status_ = RunStatus::NonFinite;
  std::string message_;
};

}  // namespace ede
