// Choosing the cell grid for a box: see grid_shape_for in engine_core.hpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/engine_core.hpp"

namespace ede {

namespace {
// Cells must be wider than a largest diameter by a relative margin far above round-off in any scalar
// type we offer (float: 6e-8), so a disk a hair outside its tracked cell never hides a contact.
constexpr double kCellMargin = 1e-6;
}  // namespace

GridShape grid_shape_for(double lx, double ly, double max_radius, std::size_t disks, bool periodic,
                         Algorithm algorithm) {
  const std::int32_t min_cells = periodic ? 3 : 1;
  if (algorithm == Algorithm::AllPairs) return {min_cells, min_cells, {}};  // every disk neighbours every other
  const double width = 2 * max_radius * (1 + kCellMargin);
  double nx = std::max(1.0, std::floor(lx / width));
  double ny = std::max(1.0, std::floor(ly / width));
  // Dilute scenes: at most ~4 cells per disk; finer cells only add crossing events.
  const double max_cells = 4.0 * double(std::max<std::size_t>(disks, 1)) + 16;
  if (nx * ny > max_cells) {
    const double scale = std::sqrt(nx * ny / max_cells);
    nx = std::max(1.0, std::floor(nx / scale));
    ny = std::max(1.0, std::floor(ny / scale));
  }
  // A very elongated box clamps one side at one cell while the other grows: cap the product too (cells
  // only get wider, which is always correct), and keep each side well inside int32.
  const double least = double(min_cells);
  nx = std::max(least, nx);
  ny = std::max(least, std::min(ny, std::floor(max_cells / nx)));
  nx = std::max(least, std::min(nx, std::floor(max_cells / ny)));
  nx = std::min(nx, 65536.0);
  ny = std::min(ny, 65536.0);
  return {std::int32_t(nx), std::int32_t(ny), {}};
}

GridShape engine_grid_for(const InitialState& init, bool periodic, Algorithm algorithm) {
  double max_radius = 0;
  for (double r : init.radius) max_radius = std::max(max_radius, r);
  const GridShape plain = grid_shape_for(init.lx, init.ly, max_radius, init.size(), periodic, algorithm);
  if (algorithm == Algorithm::AllPairs) return plain;
  const DiskSizeSplit split = split_disk_sizes(init.radius);
  if (split.big_radius == std::numeric_limits<double>::infinity()) return plain;
  GridShape shape = grid_shape_for(init.lx, init.ly, split.small_max_radius, init.size(), periodic, algorithm);
  shape.split = split;
  if (periodic) {
    const double wx = init.lx / shape.nx, wy = init.ly / shape.ny;
    for (double r : init.radius) {
      if (r <= split.big_radius) continue;
      if (2 * big_disk_reach(r, split.small_max_radius, wx) + 3 > shape.nx ||
          2 * big_disk_reach(r, split.small_max_radius, wy) + 3 > shape.ny)
        return plain;  // a big disk that spans a good part of a periodic box: one grid for all
    }
  }
  return shape;
}

}  // namespace ede
