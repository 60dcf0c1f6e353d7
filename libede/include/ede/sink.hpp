// Sinks: read-only observers of a run (log writer, live counters, progress, samplers).
//
// The engine calls every registered sink in registration order; sinks get const access and cannot change
// the run, so a run with sinks and one without produce the same events. One virtual call per event per
// sink; with no sink registered the engine skips the calls entirely.
#pragma once

#include "ede/event.hpp"
#include "ede/particles.hpp"

namespace ede {

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
  virtual void on_rebuild(T time, const Particles<T>& particles) { (void)time, (void)particles; }
  // Once, when the run stops, with the time the run reached.
  virtual void on_finish(T time, const Particles<T>& particles) { (void)time, (void)particles; }
  virtual bool wants_cell_events() const { return false; }
};

}  // namespace ede
