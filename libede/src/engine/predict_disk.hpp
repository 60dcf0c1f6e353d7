// Predictions: one disk's next event (every room's candidate, the earliest wins: its walls, its segments,
// the disks of the 3 x 3 cells around it, the big disks, and its cell crossing), and every disk's at once
// when the predictions are rebuilt from the state alone (start, actions, the rebuild interval).
#pragma once

#include <cstdint>

#include "core/energy.hpp"
#include "engine/engine_state.hpp"
#include "engine/room_crossing.hpp"
#include "engine/room_pair.hpp"
#include "engine/room_segment.hpp"
#include "engine/room_shear.hpp"
#include "engine/room_thermostat.hpp"
#include "engine/room_wall.hpp"

namespace ede {

// Full prediction for disk i at now: walls, segments, pairs in the 3 x 3 cells (a big disk: its reach
// block), big disks, cell crossing.
template <class S>
void predict_disk(S& s, std::int32_t i) {
  using T = typename S::Scalar;
  const Disk<T>& d = s.p.disk[i];
  Candidate<T> best = wall_candidate(s, d);
  const Position2<T> pi = s.pos_at(d), vi = s.vel_at(d);
  const std::int32_t cell = s.grid.cell_of(i);
  const std::int32_t cx = s.grid.cell_x(cell), cy = s.grid.cell_y(cell);
  const bool big = !s.big.empty() && s.is_big(d);
  if constexpr (S::Effects::kSegments) scan_segments(s, d, cell, big, best);
  if (!big) {
    scan_3x3(s, i, pi, vi, cx, cy, best);
  } else {
    const BigDisk& b = s.big_entry(i);
    for (std::int32_t dy = -b.reach_y; dy <= b.reach_y; ++dy)
      for (std::int32_t dx = -b.reach_x; dx <= b.reach_x; ++dx) scan_cell(s, i, pi, vi, cx + dx, cy + dy, best);
  }
  if (!s.big.empty()) scan_big(s, i, pi, vi, big, best);
  Prediction<T>& pr = s.pred[i];
  const Crossing<T> cross = crossing(s, d, cell);
  pr.set(best, s.counter_of(best), cross.dir, s.now == d.t);
  push_key(s, i, cross.time, best.kind);
}

// Rebuilds cells and every prediction from the state alone (positions at now, last partners): the same
// state always gives the same queue, which is what makes a resumed run identical to an uninterrupted one.
// `notify`: the sinks see the point (a resumed run rebuilds silently where the original run told them).
template <class S>
void rebuild_predictions(S& s, bool notify) {
  using T = typename S::Scalar;
  s.grid.reset(s.grid.nx(), s.grid.ny(), s.lx, s.ly, s.p.disk);
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    const Position2<T> pos = s.pos_at(s.p.disk[i]);
    const std::int32_t cell = s.grid.cell_containing(pos.x, pos.y);
    if (s.is_big(s.p.disk[i]))
      s.grid.set_home(std::int32_t(i), cell);
    else
      s.grid.insert(std::int32_t(i), cell);
  }
  if constexpr (S::Effects::kSteps)
    if (!s.steps.depths_known) init_depths(s);  // the start, or a resumed run's rebuild point
  for (std::size_t i = 0; i < s.p.size(); ++i) predict_disk(s, std::int32_t(i));
  if constexpr (S::Effects::kDissipative) s.dissipation.ke = kinetic_energy(s.p);
  restart_thermostat_clock(s);
  restart_realign_clock(s);
  if (!notify) return;
  const RebuildPoint<T> point{s.now,
                              s.p,
                              s.counts,
                              s.schedule.next_sample_index,
                              s.schedule.next_action_index,
                              s.stall.same_time_events,
                              s.ke0};
  for (Sink<T>* k : s.sinks) k->on_rebuild(point);
}

}  // namespace ede
