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

// A Lees-Edwards box (lees_edwards.hpp): f(k, shift_x, shift_y, shift_vx) for every disk k != i that disk i
// in cell (cx, cy) can meet before the boundary rows are next realigned: the 3 x 3 cells within the box's
// rows (wrapped in x), and beyond the top (bottom) edge the bottom (top) row slid by +offset (-offset) and
// moving at +u (-u): there the six columns whose slid images overlap columns cx - 1 .. cx + 1 for any
// alignment from one cell before the offset's column to two after it (the realignment comes after half a
// cell). shift_x places k's image, shift_vx is its velocity less k's own.
template <class S, class F>
void for_each_sheared_neighbour(const S& s, std::int32_t i, std::int32_t cx, std::int32_t cy, F&& f) {
  using T = typename S::Scalar;
  const std::int32_t nx = s.grid.nx(), ny = s.grid.ny();
  for (std::int32_t row = cy - 1; row <= cy + 1; ++row) {
    if (row >= 0 && row < ny) {
      for (std::int32_t c = cx - 1; c <= cx + 1; ++c)
        visit_cell(s, i, c, row, [&](std::int32_t k, T sx, T sy) { f(k, sx, sy, T(0)); });
      continue;
    }
    const bool above = row == ny;
    const T offset = s.shear.offset(s.now, s.lx);
    const std::int32_t q = s.shear.column_of(offset, nx);
    const std::int32_t first = above ? cx - q - 3 : cx + q - 2;
    const T sy = above ? s.ly : -s.ly, svx = above ? s.shear.slide : -s.shear.slide;
    for (std::int32_t u = first; u < first + 6; ++u) {
      const std::int32_t m = u >= 0 ? u / nx : -((nx - 1 - u) / nx);  // floor(u / nx)
      const T sx = (above ? offset : -offset) + T(m) * s.lx;
      for (std::int32_t k = s.grid.head(s.grid.cell_at(u - m * nx, above ? 0 : ny - 1)); k != CellGrid<T>::kNone;
           k = s.grid.next(k))
        if (k != i) f(k, sx, sy, svx);
    }
  }
}

// f(k, shift_x, shift_y) for every disk k != i in the 3 x 3 cells around `cell` (in a Lees-Edwards box, the
// cells for_each_sheared_neighbour visits).
template <class S, class F>
void for_each_neighbour(const S& s, std::int32_t i, std::int32_t cell, F&& f) {
  const std::int32_t cx = s.grid.cell_x(cell), cy = s.grid.cell_y(cell);
  if constexpr (S::Effects::kSheared) {
    using T = typename S::Scalar;
    return for_each_sheared_neighbour(s, i, cx, cy, [&](std::int32_t k, T sx, T sy, T) { f(k, sx, sy); });
  }
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
