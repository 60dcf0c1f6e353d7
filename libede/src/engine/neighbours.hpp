// Which disks a disk can meet: the 3 x 3 cells around it (its neighbours), the block a big disk reaches,
// with the periodic image each lies in. Used by the pair room's scans and by the invariant checks.
#pragma once

#include <cstdint>

#include "engine/engine_state.hpp"

namespace ede {

// Cell index c wrapped into [0, n) in a periodic box, with the image shift it implies; false outside a
// walled box.
template <class S>
bool wrap_index(std::int32_t& c, std::int32_t n, typename S::Scalar length, typename S::Scalar& shift) {
  if (c >= 0 && c < n) return true;
  if constexpr (!S::Effects::kPeriodic) {
    return false;
  } else {
    shift = c < 0 ? -length : length;
    c = c < 0 ? c + n : c - n;
    return true;
  }
}

// f(k, shift_x, shift_y) for every disk k != i in cell (cx, cy), wrapped in a periodic box (else skipped if
// outside).
template <class S, class F>
[[gnu::always_inline]] inline void visit_cell(const S& s, std::int32_t i, std::int32_t cx, std::int32_t cy, F&& f) {
  using T = typename S::Scalar;
  T sx = 0, sy = 0;
  if (!wrap_index<S>(cx, s.grid.nx(), s.lx, sx) || !wrap_index<S>(cy, s.grid.ny(), s.ly, sy)) return;
  for (std::int32_t k = s.grid.head(s.grid.cell_at(cx, cy)); k != CellGrid<T>::kNone; k = s.grid.next(k))
    if (k != i) f(k, sx, sy);
}

// f(k, shift_x, shift_y) for every disk k != i in the 3 x 3 cells around `cell`.
template <class S, class F>
void for_each_neighbour(const S& s, std::int32_t i, std::int32_t cell, F&& f) {
  const std::int32_t cx = s.grid.cell_x(cell), cy = s.grid.cell_y(cell);
  for (std::int32_t dy = -1; dy <= 1; ++dy)
    for (std::int32_t dx = -1; dx <= 1; ++dx) visit_cell(s, i, cx + dx, cy + dy, f);
}

// f(k, shift_x, shift_y) for every small disk within a big disk's reach.
template <class S, class F>
void for_each_in_reach(const S& s, const BigDisk& b, F&& f) {
  const std::int32_t cell = s.grid.cell_of(b.id);
  const std::int32_t cx = s.grid.cell_x(cell), cy = s.grid.cell_y(cell);
  for (std::int32_t dy = -b.reach_y; dy <= b.reach_y; ++dy)
    for (std::int32_t dx = -b.reach_x; dx <= b.reach_x; ++dx) visit_cell(s, b.id, cx + dx, cy + dy, f);
}

// The big disks of an initial state: those above the split's radius, with the blocks they scan.
template <class S>
void find_big_disks(S& s, const InitialState& init, const DiskSizeSplit& split) {
  using T = typename S::Scalar;
  s.big_radius = T(split.big_radius);
  const double wx = double(s.lx) / s.grid.nx(), wy = double(s.ly) / s.grid.ny();
  for (std::size_t i = 0; i < init.size(); ++i)
    if (init.radius[i] > split.big_radius)
      s.big.push_back({std::int32_t(i), big_disk_reach(init.radius[i], split.small_max_radius, wx),
                       big_disk_reach(init.radius[i], split.small_max_radius, wy)});
}

}  // namespace ede
