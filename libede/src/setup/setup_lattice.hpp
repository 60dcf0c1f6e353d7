// Lattice placement: `count` disks on a hexagonal or square lattice in a region, whole disks inside.
//
// Block layout: nx sites per row, ny = ceil(count / nx) rows (hexagonal: rows a*sqrt(3)/2 apart, odd rows
// shifted by a/2), filled row by row; of all nx the one allowing the largest spacing a wins, and the used
// sites are centred in the region. In a periodic box with the region the whole box, a layout that tiles
// the box (nx * ny == count, ny even for hexagonal, spacings lx/nx and ly/ny, so slightly stretched when
// the box does not match the lattice) is used instead when its nearest-neighbour distance, images
// included, is at least the block's: the block leaves a seam at the boundary where disks nearly touch
// their images.
// Rejected: a lattice with the exact spacing 2r (leaves the region's far side empty) and rows of
// alternating length (a little denser when the region is tight, but the count of sites is no longer
// nx * ny and the error message's "at most k fit" harder to state).
#pragma once

#include <cstdint>
#include <vector>

#include "ede/error.hpp"
#include "ede/scene.hpp"

namespace ede::setup_detail {

struct LatticePlacement {
  LatticeKind kind = LatticeKind::Hexagonal;
  Region region;
  double lx = 1, ly = 1;
  bool periodic_box = false;
};

// Centres of `count` disks of radius r, row by row; an error if the spacing would be below 2r.
Status place_lattice(const LatticePlacement& where, double r, std::int64_t count, std::vector<double>& x,
                     std::vector<double>& y);

}  // namespace ede::setup_detail
