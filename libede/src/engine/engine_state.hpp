// EngineState: what every room of the engine works on (the rooms are free functions over it: room_*.hpp,
// neighbours.hpp, predict_disk.hpp, stops.hpp, invariants.hpp; the loop is Engine, engine_core.hpp).
//
// Plain data, public: the disks (Particles: the 64-byte hot records, cold data apart), each disk's
// prediction, the cell grid and the queue, the sinks, the counts, the box and the clock, the big disks,
// the schedule of stops, samples and actions, the stall watch, and the state each effect policy asks for
// (effects.hpp: an empty struct, taking no room, where the engine's instantiation lacks the effect).
// Rejected: one class with ~45 member fields and every event kind as a member function (the engine before
// issue 34: every instantiation carried every table, and adding an event kind meant editing the class).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/drift.hpp"
#include "core/event.hpp"
#include "core/particles.hpp"
#include "core/sink.hpp"
#include "core/state_update.hpp"
#include "engine/big_disks.hpp"
#include "engine/candidate.hpp"
#include "engine/cell_grid.hpp"
#include "engine/effects.hpp"
#include "engine/engine.hpp"
#include "engine/event_queue.hpp"
#include "engine/grid_shape.hpp"
#include "engine/predict_pair.hpp"
#include "engine/prediction.hpp"

namespace ede {

// The eight effect axes of an instantiation as one type (effects.hpp).
template <class BoundaryP, class DissipationP, class FieldP, class ContactP, class WallsP, class SpinP,
          class PotentialP = HardCore, class HeatP = NoThermostat>
struct EffectSet {
  using Boundary = BoundaryP;
  using Dissipation = DissipationP;
  using Field = FieldP;
  using Contact = ContactP;
  using Walls = WallsP;
  using Spin = SpinP;
  using Potential = PotentialP;
  using Heat = HeatP;
  static constexpr bool kPeriodic = Boundary::kPeriodic;
  static constexpr bool kDissipative = Dissipation::kDissipative;
  static constexpr bool kGravity = Field::kGravity;
  static constexpr bool kSegments = Walls::kSegments;
  static constexpr bool kRough = Spin::kRough;
  static constexpr bool kSteps = Potential::kSteps;
  static constexpr bool kThermostat = Heat::kThermostat;
  static constexpr bool kSheared = Boundary::kSheared;
  static_assert(!kRough || (kDissipative && !kGravity && !kSegments),
                "rough disks run in a dissipative engine without gravity or segments");
  static_assert(!kSegments || (!kPeriodic && !kGravity), "segments need walls and no gravity");
  static_assert(!kSteps || (kDissipative && !kRough && !kSegments),
                "stepped potentials run in a dissipative engine without rough disks or segments");
  static_assert(!kThermostat || (kDissipative && !kGravity && !kSegments && !kRough && !kSteps),
                "the thermostat runs in a dissipative engine without gravity, segments, rotation or steps");
  static_assert(!kSheared || (kDissipative && !kGravity && !kSegments && !kRough && !kSteps && kThermostat),
                "a Lees-Edwards box runs in a dissipative engine with the thermostat's clock and without gravity, "
                "segments, rotation or steps");
};

// When the run stops, and what happens at times other than disk events (stops.hpp).
struct Schedule {
  std::uint64_t pairs_to_stop = 0;
  std::uint64_t next_pair_target = std::numeric_limits<std::uint64_t>::max();  // pair_target()
  std::uint64_t next_sample_index = 0;
  std::size_t next_action_index = 0;
};

// Inelastic collapse shows as ever more events at one and the same time (stops.hpp).
struct StallWatch {
  std::uint64_t same_time_events = 0, limit = 0;
  bool stalled = false;
  std::string message;
};

template <class T, class Fx>
struct EngineState {
  using Scalar = T;
  using Effects = Fx;

  EngineOptions opt;
  Particles<T> p;
  std::vector<Prediction<T>> pred;
  CellGrid<T> grid;
  EventQueue<T> queue;
  std::vector<Sink<T>*> sinks;
  EventCounts counts;
  T lx = 1, ly = 1, half_lx = 0.5, half_ly = 0.5;
  T b_noise2 = 0;  // round-off floor of b, geometry.hpp
  T now = 0;
  T stop_time = kNever<T>;
  double ke0 = 0;  // the initial kinetic energy (stop.energy_fraction's reference)
  std::vector<BigDisk> big;  // disks outside the cell lists (big_disks.hpp), by id
  T big_radius = kNever<T>;
  bool select_pairs = false;          // the pair test without branches (room_pair.hpp, EngineOptions)
  bool pair_times_vouchable = false;  // pair_time_exact_v2's conditions that hold for the whole run
  bool prefetch_ahead = false;        // prefetch_upcoming() (EngineOptions::prefetch_upcoming_from)
  Schedule schedule;
  StallWatch stall;
  [[no_unique_address]] typename Fx::Dissipation::template State<T> dissipation;
  [[no_unique_address]] typename Fx::Field::template State<T> field;
  [[no_unique_address]] typename Fx::Walls::template State<T> walls;
  [[no_unique_address]] typename Fx::Spin::template State<T> spin;
  [[no_unique_address]] typename Fx::Potential::template State<T> steps;
  [[no_unique_address]] typename Fx::Heat::template State<T> thermostat;
  [[no_unique_address]] typename Fx::Boundary::template State<T> shear;

  // Position and velocity of a disk at now: straight lines, or parabolas under gravity.
  Position2<T> pos_at(const Disk<T>& d) const {
    if constexpr (Fx::kGravity)
      return {position_along(d.x, d.vx, field.gx, d.t, now), position_along(d.y, d.vy, field.gy, d.t, now)};
    else
      return position_at(d, now);
  }
  Position2<T> vel_at(const Disk<T>& d) const {
    if constexpr (Fx::kGravity)
      return {velocity_along(d.vx, field.gx, d.t, now), velocity_along(d.vy, field.gy, d.t, now)};
    else
      return {d.vx, d.vy};
  }
  // Brings disk i's record to now.
  void advance(std::int32_t i) {
    if constexpr (Fx::kGravity)
      advance_disk(p.disk[i], now, field.gx, field.gy);
    else
      advance_disk(p.disk[i], now);
  }

  // The TC model: a compile-time false in an Elastic engine, a value in a Dissipative one.
  bool tc_model() const {
    if constexpr (Fx::kDissipative)
      return dissipation.tc_model;
    else
      return false;
  }
  bool tc_elastic(std::int32_t i, std::int32_t j) const {
    if constexpr (Fx::kDissipative)
      return dissipation.tc_elastic(p, now, i, j);
    else
      return false;
  }

  // counts.events(), without the thermostat's and the shear's always-zero terms where the engine has neither.
  std::uint64_t events_done() const {
    if constexpr (Fx::kThermostat || Fx::kSheared)
      return counts.events();
    else
      return counts.events_but_redraws();
  }

  bool is_big(const Disk<T>& d) const { return d.r > big_radius; }
  const BigDisk& big_entry(std::int32_t i) const {
    return *std::find_if(big.begin(), big.end(), [&](const BigDisk& b) { return b.id == i; });
  }

  // A disk's kinetic energy (with its rotation's in a rough engine), in double: the energy stop's account.
  double disk_energy(std::int32_t i) const {
    const double vx = double(p.disk[i].vx), vy = double(p.disk[i].vy);
    if constexpr (Fx::kRough) {
      const double w = double(p.omega[i]);
      return 0.5 * double(p.mass(i)) * (vx * vx + vy * vy) + 0.5 * double(p.inertia[i]) * (w * w);
    }
    return 0.5 * double(p.mass(i)) * (vx * vx + vy * vy);
  }

  // The partner's counter a pair prediction is checked against (0 for the others).
  std::uint32_t counter_of(const Candidate<T>& c) const {
    const bool with_disk = c.kind == EventKind::Pair || (Fx::kSteps && c.kind == EventKind::Step);
    return with_disk && c.partner >= 0 ? p.disk[c.partner].counter : 0;
  }

  void emit(const EventOutcome<T>& outcome) const {
    for (Sink<T>* s : sinks) s->on_event(outcome, p);
  }
};

// Every room's full prediction for disk i at now (predict_disk.hpp): its earliest collision and cell
// crossing, into its Prediction and the queue. Declared here for the rooms that re-predict after an event.
template <class S>
void predict_disk(S& s, std::int32_t i);
// From disk a's stored position to disk b's, through the nearest periodic image (both brought to the same
// time by the caller): what a pair or step collision resolves along.
template <class S, class T = typename S::Scalar>
[[gnu::always_inline]] inline void separation(const S& s, const Disk<T>& a, const Disk<T>& b, T& dx, T& dy) {
  dx = b.x - a.x, dy = b.y - a.y;
  if constexpr (S::Effects::kPeriodic) {
    if (dx > s.half_lx) dx -= s.lx; else if (dx < -s.half_lx) dx += s.lx;
    if (dy > s.half_ly) dy -= s.ly; else if (dy < -s.half_ly) dy += s.ly;
  }
}

// The same in a Lees-Edwards box, where the nearest image of b across the top or bottom edge is slid by
// the images' offset now and moves at +-u: svx is that image's x-velocity less b's own (0 within the box).
// Returns whether b's image lies across that edge. Without the crossing it computes what separation does.
template <class S, class T = typename S::Scalar>
inline bool sheared_separation(const S& s, const Disk<T>& a, const Disk<T>& b, T& dx, T& dy, T& svx) {
  dx = b.x - a.x, dy = b.y - a.y, svx = 0;
  bool across = false;
  if (dy > s.half_ly) {  // b's image below: shifted by (-offset, -ly), moving at -u
    dy -= s.ly, dx -= s.shear.offset(s.now, s.lx), svx = -s.shear.slide, across = true;
  } else if (dy < -s.half_ly) {
    dy += s.ly, dx += s.shear.offset(s.now, s.lx), svx = s.shear.slide, across = true;
  }
  for (int k = 0; k < 2; ++k)  // dx within (-2 lx, 2 lx)
    if (dx > s.half_lx) dx -= s.lx; else if (dx < -s.half_lx) dx += s.lx;
  return across;
}

// Every disk's prediction rebuilt from the state alone (predict_disk.hpp); `notify`: the sinks see the point.
template <class S>
void rebuild_predictions(S& s, bool notify = true);

}  // namespace ede
