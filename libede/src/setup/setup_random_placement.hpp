// Random sequential addition (RSA): disks placed one at a time at uniform random positions, a candidate
// rejected if it overlaps any disk placed before (this species' or an earlier one's), never moved after.
//
// Candidates are uniform over the centres that keep the whole disk in the region; along a dimension in
// which the box is periodic and the region spans the whole box, centres are uniform in [0, L) and the disk
// may straddle the boundary (overlap checks always use the periodic image in a periodic box). Disks of
// different radii are placed largest first: big disks find room while the region is empty. RSA jams near
// a packing fraction of 0.547 (monodisperse); denser packings need a lattice.
// Denser disordered starts: [grow] (setup/grow.hpp) places with this at a low density, then grows the disks.
// Rejected: placing on a lattice and melting it with a short simulation (needs the engine in setup).
#pragma once

#include <cstdint>
#include <vector>

#include "core/segment.hpp"
#include "ede/error.hpp"
#include "core/rng.hpp"
#include "ede/scene.hpp"
#include "setup/placement_grid.hpp"

namespace ede::setup_detail {

struct RandomPlacement {
  Region region;
  double lx = 1, ly = 1;
  bool periodic_box = false;
  // Wall segments: a candidate touching one is rejected like one overlapping a disk (an attempt spent, no
  // extra draws, so scenes without segments draw exactly what they did before segments existed).
  std::vector<Segment<double>> segments;
  // Candidates from the voxels not yet wholly blocked once most of the region is (free_voxel_list.hpp): the
  // same law of positions, other positions than the default's draws over the whole region.
  RandomSampling sampling = RandomSampling::Region;
};

// The attempt budget for `count` disks: max(10^6, 2000 * count).
std::int64_t random_attempt_budget(std::int64_t count);

// Places disks of the given radii. On success `radii` is sorted largest first, x and y hold the centres in
// that order, and every disk has been inserted into `grid`. On failure the message says how far it got.
Status place_random(const RandomPlacement& where, std::vector<double>& radii, PlacementGrid& grid, Rng& rng,
                    std::vector<double>& x, std::vector<double>& y);

}  // namespace ede::setup_detail
