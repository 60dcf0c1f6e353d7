// The shape of an engine's cell grid, chosen once at start (engine_grid.cpp).
#pragma once

#include <cstdint>

#include "core/initial_state.hpp"
#include "engine/big_disks.hpp"
#include "engine/engine.hpp"

namespace ede {

// Grid dimensions for a box and largest radius: cells at least one largest diameter wide (with a margin
// far above round-off), at most ~4 cells per disk (dilute scenes need no finer grid), at least 3 per side
// in a periodic box (so the 3 x 3 neighbourhood holds distinct cells and each has one image).
struct GridShape {
  std::int32_t nx = 1, ny = 1;
  DiskSizeSplit split;  // big disks (big_disks.hpp): the grid is sized by split.small_max_radius
};
GridShape grid_shape_for(double lx, double ly, double max_radius, std::size_t disks, bool periodic,
                         Algorithm algorithm);
// The grid for an initial state: big disks kept out of the cell lists when some stand out and the box
// allows it (periodic: n >= 2 reach + 3 on each side), else every disk in the grid.
GridShape engine_grid_for(const InitialState& init, bool periodic, Algorithm algorithm);

}  // namespace ede
