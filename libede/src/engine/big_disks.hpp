// Big disks: the few disks much larger than the rest stay out of the cell lists.
//
// Cells must be one largest diameter wide, so a grid sized by a crater's projectile (5 bed radii) has cells
// 25 times the area the bed needs, and every bed prediction scans 25 times the disks. Instead, disks with a
// radius above big_radius (twice that of the (K+1)-th largest disk, K = min(64, N/64): at most K disks,
// and only ones that stand out) are "big": the grid is sized by the others; every small disk checks every
// big disk whenever it predicts or crosses a cell; a big disk has a home cell and crossing events like any
// disk, and scans the block of cells it can reach, (2k+1) x (2k+1) with k = reach(r), when it predicts,
// and the newly reachable strip of that block when it crosses. Any pair is then checked at the last event
// of either before they could touch, as with the 3 x 3 rule. In a periodic box the block must hold
// distinct cells and a small disk's nearest image of a big disk must be the one it can hit: n >= 2k + 3.
// Rejected: a hierarchy of grids (general, but much more code for a case with a handful of large disks)
// and neighbour lists (their size grows with the radius ratio as well).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace ede {

struct DiskSizeSplit {
  double big_radius = std::numeric_limits<double>::infinity();  // radius > big_radius: big
  double small_max_radius = 0;                                  // the largest radius of the others
};

// A big disk and the block of cells it scans: (2 reach + 1) on each side.
struct BigDisk {
  std::int32_t id, reach_x, reach_y;
};

// The split for a set of radii (no big disks if none stands out).
DiskSizeSplit split_disk_sizes(const std::vector<double>& radii);

// How many cells of width `width` a big disk of radius r must look across to see every small disk it can
// touch (with the cell margin, so a disk a hair outside its cell is still seen).
inline std::int32_t big_disk_reach(double r, double small_max_radius, double width) {
  return std::int32_t(std::ceil((r + small_max_radius) * (1 + 4e-6) / width));
}

}  // namespace ede
