// Predicting when a disk leaves its cell, and through which side.
//
// From the stored state, like walls. In a walled box the outer sides of the grid are never crossed (the
// wall is hit first); in a periodic box crossing them is a wrap. Ties go to x before y, then to the
// positive direction, so the choice is a function of the state alone.
#pragma once

#include <cstdint>

#include "cell_grid.hpp"
#include "ede/particles.hpp"
#include "geometry.hpp"

namespace ede {

enum CrossDir : std::uint8_t { kCrossRight = 0, kCrossLeft = 1, kCrossUp = 2, kCrossDown = 3 };

template <class T>
struct Crossing {
  T time = kNever<T>;
  CrossDir dir = kCrossRight;
};

template <class T>
inline Crossing<T> predict_crossing(const Disk<T>& d, const CellGrid<T>& grid, std::int32_t cell, bool periodic,
                                    T now) {
  const std::int32_t cx = grid.cell_x(cell);
  const std::int32_t cy = grid.cell_y(cell);
  Crossing<T> best;
  const auto consider = [&](bool open, T x, T v, T boundary, CrossDir dir) {
    if (!open) return;
    T t = d.t + time_to_reach(x, v, boundary);
    if (t < now) t = now;
    if (t < best.time) best = {t, dir};
  };
  if (d.vx > 0) consider(periodic || cx + 1 < grid.nx(), d.x, d.vx, grid.boundary_x(cx + 1), kCrossRight);
  if (d.vx < 0) consider(periodic || cx > 0, d.x, d.vx, grid.boundary_x(cx), kCrossLeft);
  if (d.vy > 0) consider(periodic || cy + 1 < grid.ny(), d.y, d.vy, grid.boundary_y(cy + 1), kCrossUp);
  if (d.vy < 0) consider(periodic || cy > 0, d.y, d.vy, grid.boundary_y(cy), kCrossDown);
  return best;
}

}  // namespace ede
