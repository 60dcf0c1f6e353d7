// The action room: what happens to the whole system at a scheduled time or collision count (the scene's
// [[actions]]: reverse every velocity), and the samples an observer asked for (no state change: the sinks
// see the state at the sample's time). When they are due is stops.hpp's business.
#pragma once

#include "engine/engine_state.hpp"

namespace ede {

template <class S>
void take_sample(S& s, typename S::Scalar t) {
  s.now = t;
  ++s.schedule.next_sample_index;
  ++s.counts.by_kind[int(EventKind::Sample)];
  for (Sink<typename S::Scalar>* k : s.sinks) k->on_sample(t, s.p);
}

// The time-reversal action: every disk is brought to now and its velocity negated (exact in floating
// point), then every prediction is rebuilt.
template <class S>
void reverse_velocities(S& s, typename S::Scalar t) {
  using T = typename S::Scalar;
  s.now = t;
  ++s.schedule.next_action_index;
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    if constexpr (S::Effects::kGravity)
      reverse_disk(s.p.disk[i], s.now, s.field.gx, s.field.gy);
    else
      reverse_disk(s.p.disk[i], s.now);
    ++s.p.disk[i].counter;
    s.p.disk[i].last_partner = -1;
  }
  if constexpr (S::Effects::kRough)
    for (T& w : s.p.omega) w = -w;  // the reversed motion spins the other way
  ++s.counts.by_kind[int(EventKind::Action)];
  if (!s.sinks.empty())
    s.emit({s.now, EventKind::Action, false, -1, -1, T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0),
            T(0), {}, {}, false, false});
  rebuild_predictions(s);
}

}  // namespace ede
