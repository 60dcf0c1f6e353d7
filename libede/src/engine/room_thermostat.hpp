// The thermostat room: the Andersen thermostat's events (thermostat.hpp holds its clock and groups). At
// the clock's time one disk, picked at random, is brought to now and given a velocity drawn afresh from
// Maxwell-Boltzmann at its group's kT: each component sigma z with sigma = sqrt(kT / m) and z standard
// normal (Rng::normal_pair_exact: the polar method with the libm-free exact_log). The loop takes these
// events by time, like actions (engine_core.hpp), never from the queue.
// In a Lees-Edwards box the draw is about the shear flow at the disk's height (ShearClock::flow): the
// thermostat holds the temperature of the velocities relative to the flow and leaves the flow itself, the
// profile-biased thermostat of non-equilibrium simulations (Evans and Morriss, "Statistical Mechanics of
// Nonequilibrium Liquids", 2008, ch. 6). About rest, it would pull every disk back to zero x-velocity and
// damp the flow it is meant to hold.
// Every draw of the m-th event (m = thermostat events before it) comes from its own stream,
// Rng::for_stream(seed, kThermostatStreams + 2 m), in this order: the group (only with several), the
// disk, the normal pair, then the exponential that sets the next event's time. The clock is drawn again
// at every rebuild (restart_thermostat_clock), from stream kThermostatStreams + 2 c + 1, c the events so
// far. So everything is a function of the seed and the counts a resumable keyframe stores.
// Rejected: one generator carried along the run (its state would have to be stored in every resumable
// keyframe, a new field in the log for what the counts already determine).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/rng.hpp"
#include "engine/engine_state.hpp"

namespace ede {

// The thermostat's next event time (never, in an engine without it).
template <class S>
typename S::Scalar thermostat_time(const S& s) {
  if constexpr (S::Effects::kThermostat)
    return s.thermostat.next;
  else
    return kNever<typename S::Scalar>;
}

// At a rebuild of the predictions (start, resume, actions, the rebuild interval).
template <class S>
void restart_thermostat_clock(S& s) {
  if constexpr (S::Effects::kThermostat) {
    Rng rng = Rng::for_stream(s.thermostat.seed, kThermostatStreams + 2 * s.events_done() + 1);
    s.thermostat.next = s.thermostat.draw_next(s.now, rng);
  }
}

template <class S>
void redraw_velocity(S& s, typename S::Scalar t) {
  using T = typename S::Scalar;
  if constexpr (S::Effects::kThermostat) {
    auto& clock = s.thermostat;
    s.now = t;
    Rng rng = Rng::for_stream(clock.seed, kThermostatStreams + 2 * s.counts.of(EventKind::Thermostat));
    const typename AndersenClock<T>::Group* group = nullptr;
    const std::int32_t i = clock.pick(rng, group);
    double z0 = 0, z1 = 0;
    rng.normal_pair_exact(z0, z1);
    const double sigma = std::sqrt(group->temperature / double(s.p.mass(std::size_t(i))));
    const RecordBefore<T> before = record_before(s.p.disk[i]);
    s.advance(i);
    Disk<T>& d = s.p.disk[i];
    const T vx0 = d.vx, vy0 = d.vy;
    const double ke_before = s.disk_energy(i);
    d.vx = T(sigma * z0);
    d.vy = T(sigma * z1);
    if constexpr (S::Effects::kSheared) d.vx += s.shear.flow(d.y);  // about the shear flow, not about rest
    s.dissipation.ke += s.disk_energy(i) - ke_before;
    ++d.counter;
    d.last_partner = -1;
    ++s.counts.by_kind[int(EventKind::Thermostat)];
    clock.next = clock.draw_next(s.now, rng);
    if (!s.sinks.empty())
      s.emit({s.now, EventKind::Thermostat, false, i, -1, d.vx, d.vy, T(0), T(0), vx0, vy0, T(0), T(0), T(0), T(0), T(0),
              T(0), before, before, false, false});
    predict_disk(s, i);
  }
}

}  // namespace ede
