// When a run stops and what happens between disk events: samples and actions by time or by collisions per
// disk, the stop conditions (time, events, collisions, energy), and the two ways an inelastic run can end
// on its own (stalled: time stops advancing; cooled below what the scalar type resolves), with the message
// that says what to do (a stall's words are in stall_text.hpp, which tells collapse from an elastic run's clock).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "core/energy.hpp"
#include "core/state_of.hpp"
#include "engine/engine_state.hpp"
#include "engine/room_action.hpp"
#include "engine/stall_text.hpp"

namespace ede {

template <class S>
typename S::Scalar next_sample_time(const S& s) {
  using T = typename S::Scalar;
  if (!s.opt.sample_interval) return kNever<T>;
  return T(double(s.schedule.next_sample_index + 1) * *s.opt.sample_interval);
}

template <class S>
typename S::Scalar next_action_time(const S& s) {
  using T = typename S::Scalar;
  const std::size_t k = s.schedule.next_action_index;
  if (k >= s.opt.actions.size() || s.opt.actions[k].collisions_per_disk) return kNever<T>;
  return T(s.opt.actions[k].time);
}

// Actions and samples by collisions per disk (Scene::actions, Scene::sample_collisions): one happens right
// after the pair collision that brings the pair count P to ceil(c N / 2) (c: its collisions per disk; the
// k-th sample's c is k times the interval), at that collision's time, before the next event. The loop
// compares P with schedule.next_pair_target, the nearest such count (never: the largest integer), so a
// scene without them pays one comparison per event.
template <class S>
std::uint64_t pairs_for(const S& s, double collisions_per_disk) {
  return static_cast<std::uint64_t>(std::ceil(collisions_per_disk * double(s.p.size()) / 2));
}

template <class S>
std::uint64_t pair_target(const S& s) {
  std::uint64_t target = std::numeric_limits<std::uint64_t>::max();
  const Schedule& sc = s.schedule;
  if (sc.next_action_index < s.opt.actions.size())
    if (const auto& c = s.opt.actions[sc.next_action_index].collisions_per_disk) target = pairs_for(s, *c);
  if (s.opt.sample_collisions)
    target = std::min(target, pairs_for(s, double(sc.next_sample_index + 1) * *s.opt.sample_collisions));
  return target;
}

// Every action, then every sample, whose target the pair count has reached; the events it processed.
template <class S>
std::uint64_t on_pair_target(S& s) {
  const std::uint64_t pairs = s.counts.of(EventKind::Pair);
  std::uint64_t done = 0;
  Schedule& sc = s.schedule;
  while (sc.next_action_index < s.opt.actions.size() && s.opt.actions[sc.next_action_index].collisions_per_disk &&
         pairs >= pairs_for(s, *s.opt.actions[sc.next_action_index].collisions_per_disk))
    reverse_velocities(s, s.now), ++done;
  while (s.opt.sample_collisions && pairs >= pairs_for(s, double(sc.next_sample_index + 1) * *s.opt.sample_collisions))
    take_sample(s, s.now), ++done;
  sc.next_pair_target = pair_target(s);
  return done;
}

// Nothing left to happen and no stop time: samples after now would observe the same state for ever
// (disks at rest with only an event-count stop, say), so the run ends with NoMoreEvents instead of
// sampling on. A sample at now itself (the time of the last action) is still taken.
template <class S, class T = typename S::Scalar>
bool frozen_after(const S& s, T t_sample, T t_event, T t_action, T t_stop) {
  return t_sample > s.now && t_event == kNever<T> && t_action == kNever<T> && t_stop == kNever<T>;
}

// Inelastic collapse shows as ever more events at one and the same time; past the limit the run stops.
template <class S>
void note_time(S& s, typename S::Scalar t) {
  if (t == s.now) {
    if (++s.stall.same_time_events > s.stall.limit) s.stall.stalled = true;
  } else {
    s.stall.same_time_events = 0;
  }
}

// Above this share of the initial energy, a disk too slow to resolve means collapse, not rest (a gas
// cooled to such speeds keeps ~1e-30 of its energy in float, ~1e-290 in double).
inline constexpr double kCollapseEnergyFraction = 1e-6;

// The stall's message: what happened and the fix that applies to this run's physics (stall_text.hpp).
template <class S>
std::string stall_message(const S& s) {
  using T = typename S::Scalar;
  return stall_text({double(s.now), s.stall.same_time_events, !S::Effects::kDissipative || s.opt.physics.elastic(),
                     S::Effects::kGravity, s.tc_model(), s.opt.physics.tc, to_string(scalar_kind_of<T>()),
                     double(scalar_limits<T>::epsilon())});
}

// A disk left a collision slower than the scalar type resolves (Restitution::note_if_too_slow): collapse
// while much energy remains, else the run has cooled to rest as far as it can tell.
template <class S>
RunStatus too_slow_status(S& s) {
  using T = typename S::Scalar;
  const std::int32_t i = s.dissipation.too_slow;
  const Disk<T>& slow = s.p.disk[i];  // its velocity is the one it left the collision with
  const double left = kinetic_energy(s.p) / s.ke0;
  std::ostringstream m;
  m << "disk " << i << " left a collision at t = " << double(s.now) << " with speed "
    << double(std::max(ede::abs(slow.vx), ede::abs(slow.vy))) << ", below " << double(Restitution<T>::kSlowestSpeed)
    << ", the slowest speed whose square the scalar type holds to full precision";
  // A gas cooled to rest has (almost) no energy left; a disk this slow beside a sizeable energy is one
  // caught in a cluster colliding ever more often: inelastic collapse, not rest.
  if (left > kCollapseEnergyFraction) {
    m << ", while " << 100 * left
      << "% of the initial kinetic energy remains: inelastic collapse (disks in a cluster colliding ever "
         "faster and ever slower at one place). ";
    if (s.tc_model())
      m << "Increase physics.tc (now " << s.opt.physics.tc << ").";
    else
      m << "Enable the TC model: physics.tc > 0, e.g. 1e-6, two orders of magnitude below the typical time "
           "between a disk's collisions (docs/crater.md), or raise the restitution.";
    s.stall.message = m.str();
    return RunStatus::Collapsed;
  }
  m << ": the run has cooled to rest as far as it can tell (kinetic energy " << left
    << " of the initial), and contact times would no longer be exact. Stop earlier with "
       "stop.energy_fraction or stop.time.";
  s.stall.message = m.str();
  return RunStatus::CameToRest;
}

// After each disk event: Running, or why the run ends.
template <class S>
RunStatus check_stops(S& s) {
  if (s.stall.stalled) {
    s.stall.message = stall_message(s);
    return RunStatus::Stalled;
  }
  if constexpr (S::Effects::kDissipative)
    if (s.dissipation.too_slow >= 0) return too_slow_status(s);
  if (s.opt.stop.events && s.events_done() >= *s.opt.stop.events) return RunStatus::ReachedEvents;
  if (s.opt.stop.collisions_per_particle && s.counts.of(EventKind::Pair) >= s.schedule.pairs_to_stop)
    return RunStatus::ReachedCollisions;
  if constexpr (S::Effects::kDissipative)
    if (s.opt.stop.energy_fraction && s.dissipation.ke <= *s.opt.stop.energy_fraction * s.ke0)
      return RunStatus::ReachedEnergy;
  return RunStatus::Running;
}

}  // namespace ede
