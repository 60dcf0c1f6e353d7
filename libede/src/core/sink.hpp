// Sinks: read-only observers of a run (log writer, live counters, progress, samplers). The interface lives on
// the ground floor so that the log writer (log/) can be one without including the engine.
//
// The engine calls every registered sink in registration order; sinks get const access and cannot change
// the run, so a run with sinks and one without produce the same events. One virtual call per event per
// sink; with no sink registered the engine skips the calls entirely.
#pragma once

#include <cstdint>

#include "core/event.hpp"
#include "core/particles.hpp"
#include "ede/events.hpp"

namespace ede {

struct EventCounts;

// A point where every prediction was rebuilt from the state alone: the state plus the engine's own
// bookkeeping is all a run needs to continue from here bit for bit (ede-sim --resume).
template <class T>
struct RebuildPoint {
  T time;
  const Particles<T>& particles;
  const EventCounts& counts;
  std::uint64_t next_sample_index;   // samples already taken
  std::uint64_t next_action_index;   // actions already done
  std::uint64_t same_time_events;    // the stall detector's count
  double initial_energy;             // the energy stop condition's reference
};

template <class T>
class Sink {
 public:
  virtual ~Sink() = default;
  // Once, before the first event, with the initial state at time `time`.
  virtual void on_start(T time, const Particles<T>& particles) { (void)time, (void)particles; }
  // After each processed event (Pair, Wall, Wrap, Action; Cell only if wants_cell_events()).
  virtual void on_event(const EventOutcome<T>& outcome, const Particles<T>& particles) = 0;
  // At each sampling time: the state is exact at `time` (positions by drift).
  virtual void on_sample(T time, const Particles<T>& particles) { (void)time, (void)particles; }
  // After the predictions were rebuilt from the state alone (start, actions, every rebuild interval):
  // the points from which a run can be resumed bit for bit.
  virtual void on_rebuild(const RebuildPoint<T>& point) { (void)point; }
  // Once, when the run stops, with the time the run reached and why it stopped.
  virtual void on_finish(T time, const Particles<T>& particles, RunStatus status) {
    (void)time, (void)particles, (void)status;
  }
  virtual bool wants_cell_events() const { return false; }
};

}  // namespace ede
