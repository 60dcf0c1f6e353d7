// Predicting when a disk leaves its cell, and through which side.
//
// From the stored state, like walls. In a walled box the outer sides of the grid are never crossed (the
// wall is hit first); in a periodic box crossing them is a wrap. Ties go to x before y, then to the
// positive direction, so the choice is a function of the state alone.
#pragma once

#include <cstdint>

#include "engine/cell_grid.hpp"
#include "core/particles.hpp"
#include "core/geometry.hpp"

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

// Under constant gravity a disk may leave its cell through either side of an axis (thrown up, it can fall
// back through the bottom), so both sides are considered; the outer sides of a walled box are never
// crossed. Ties as above.
template <class T>
inline Crossing<T> predict_crossing_accelerated(const Disk<T>& d, const CellGrid<T>& grid, std::int32_t cell, T gx,
                                                T gy, T now) {
  const std::int32_t cx = grid.cell_x(cell);
  const std::int32_t cy = grid.cell_y(cell);
  Crossing<T> best;
  const auto consider = [&](bool open, T s, T u, T a, CrossDir dir) {
    if (!open) return;
    const T dt = time_to_reach_accelerated(s, u, a, now - d.t);
    if (dt == kNever<T>) return;
    T t = d.t + dt;
    if (t < now) t = now;
    if (t < best.time) best = {t, dir};
  };
  consider(cx + 1 < grid.nx(), grid.boundary_x(cx + 1) - d.x, -d.vx, -gx, kCrossRight);
  consider(cx > 0, d.x - grid.boundary_x(cx), d.vx, gx, kCrossLeft);
  consider(cy + 1 < grid.ny(), grid.boundary_y(cy + 1) - d.y, -d.vy, -gy, kCrossUp);
  consider(cy > 0, d.y - grid.boundary_y(cy), d.vy, gy, kCrossDown);
  return best;
}

}  // namespace ede
