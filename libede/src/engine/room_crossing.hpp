// The cell-crossing room: a disk leaving its cell of the grid. No state changes (the record is not
// touched, nothing is logged); the disk moves to the neighbouring cell's list, and only the cells that
// became neighbours (for a big disk, the strip of its reach block), the big disks and the segments are
// searched: predictions against the others are still valid. The crossing's own prediction
// (predict_crossing.hpp) chooses, with the collision, the disk's queue key.
#pragma once

#include <cstdint>

#include "engine/engine_state.hpp"
#include "engine/predict_crossing.hpp"
#include "engine/room_pair.hpp"
#include "engine/room_segment.hpp"

namespace ede {

template <class S, class T = typename S::Scalar>
Crossing<T> crossing(const S& s, const Disk<T>& d, std::int32_t cell) {
  if constexpr (S::Effects::kGravity)
    return predict_crossing_accelerated(d, s.grid, cell, s.field.gx, s.field.gy, s.now);
  else
    return predict_crossing(d, s.grid, cell, S::Effects::kPeriodic, s.now);
}

// Whether disk i's crossing `dir` leaves the grid: a periodic wrap.
template <class S>
bool is_wrap(const S& s, std::int32_t i, CrossDir dir) {
  if constexpr (!S::Effects::kPeriodic) {
    return false;
  } else {
    const std::int32_t cell = s.grid.cell_of(i);
    switch (dir) {
      case kCrossRight: return s.grid.cell_x(cell) == s.grid.nx() - 1;
      case kCrossLeft: return s.grid.cell_x(cell) == 0;
      case kCrossUp: return s.grid.cell_y(cell) == s.grid.ny() - 1;
      case kCrossDown: return s.grid.cell_y(cell) == 0;
    }
    return false;
  }
}

// The disk's queue key: its collision (of kind coll_kind) or its crossing, whichever comes first.
template <class S>
[[gnu::always_inline]] inline void push_key(S& s, std::int32_t i, typename S::Scalar t_cross, EventKind coll_kind) {
  const Prediction<typename S::Scalar>& pr = s.pred[i];
  if (pr.t_coll <= t_cross)
    s.queue.set(std::uint32_t(i), pr.t_coll, coll_kind);
  else
    s.queue.set(std::uint32_t(i), t_cross, is_wrap(s, i, pr.cross_dir()) ? EventKind::Wrap : EventKind::Cell);
}

// Moves disk i into the neighbouring cell through side `dir` (a wrap has moved its record first:
// room_wrap.hpp) and searches what became reachable.
template <class S>
void cross_cell(S& s, std::int32_t i, CrossDir dir, EventKind kind) {
  using T = typename S::Scalar;
  const std::int32_t cell = s.grid.cell_of(i);
  std::int32_t cx = s.grid.cell_x(cell), cy = s.grid.cell_y(cell);
  const std::int32_t step_x = dir == kCrossRight ? 1 : dir == kCrossLeft ? -1 : 0;
  const std::int32_t step_y = dir == kCrossUp ? 1 : dir == kCrossDown ? -1 : 0;
  cx += step_x;
  cy += step_y;
  if constexpr (S::Effects::kPeriodic) {
    cx = (cx + s.grid.nx()) % s.grid.nx();
    cy = (cy + s.grid.ny()) % s.grid.ny();
  }
  const bool big = !s.big.empty() && s.is_big(s.p.disk[i]);
  std::int32_t reach_x = 1, reach_y = 1;
  if (big) {
    const BigDisk& b = s.big_entry(i);
    reach_x = b.reach_x, reach_y = b.reach_y;
    s.grid.set_home(i, s.grid.cell_at(cx, cy));
  } else {
    s.grid.move(i, s.grid.cell_at(cx, cy));
  }
  ++s.counts.by_kind[int(kind)];
  if constexpr (S::Effects::kSheared)
    if (cy == 0 || cy == s.grid.ny() - 1) return predict_disk(s, i);  // the slid row: no strip of new cells

  Prediction<T>& pr = s.pred[i];
  Candidate<T> best{pr.t_coll, pr.coll_kind(), pr.partner()};
  const Position2<T> pi = s.pos_at(s.p.disk[i]), vi = s.vel_at(s.p.disk[i]);
  if (step_x != 0)
    for (std::int32_t k = -reach_y; k <= reach_y; ++k) scan_cell(s, i, pi, vi, cx + step_x * reach_x, cy + k, best);
  else
    for (std::int32_t k = -reach_x; k <= reach_x; ++k) scan_cell(s, i, pi, vi, cx + k, cy + step_y * reach_y, best);
  if (!s.big.empty()) scan_big(s, i, pi, vi, big, best);
  if constexpr (S::Effects::kSegments) scan_segments(s, s.p.disk[i], s.grid.cell_of(i), big, best);
  if (best.time != pr.t_coll || best.kind != pr.coll_kind() || best.partner != pr.partner())
    pr.set_coll(best, s.counter_of(best), s.now == s.p.disk[i].t);
  const Crossing<T> cross = crossing(s, s.p.disk[i], s.grid.cell_of(i));
  pr.set_cross(cross.dir);
  push_key(s, i, cross.time, best.kind);
}

}  // namespace ede
