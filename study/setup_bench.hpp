// The setup benchmark (ede-bench setup): how long a run takes to start at N disks, and what the blocked-voxel
// test (setup/blocked_voxels.hpp) saves in random placement near jamming.
//
// For each N, in its own child process (clean heap, its own peak RSS), N equal disks at packing fraction phi
// in a periodic unit box: random placement with the blocked voxels (today's path) and with the grid alone
// (the path before it, kept selectable as the naive baseline), both from the same seed, their CPU times and
// a digest of the placed positions (they must be equal: same draws, same decisions); then the whole start
// of a run: scene text -> setup (placement, curve order, velocities, overlap check) -> engine with its first
// predictions. Beside them, for comparison: placement and setup with sampling = "free-voxels" (other positions,
// the same law), and setup from a hexagonal lattice (the peers' start). CPU time of the measuring thread, which
// another job on the machine disturbs less than wall.
// Rejected: timing `ede-sim` from outside (scene loading, log header and process start mixed in).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ede::study {

struct SetupPlan {
  std::vector<std::uint64_t> disks = {10000, 100000, 1000000};
  double packing_fraction = 0.5;
  bool naive = true;  // also time the grid-only placement
  std::uint64_t seed = 1;
};

struct SetupRow {
  bool ok = false;
  std::string failure;
  double disks = 0;
  double placement = 0, naive_placement = 0;  // CPU s of place_random with and without blocked voxels
  bool same_positions = false;                // the two placements' digests agree (true if naive skipped)
  double voxel_bytes = 0;                     // the bitmap's size
  double setup = 0, engine_start = 0;         // CPU s: build_initial_state; make_engine + first predictions
  double free_voxel_placement = 0;            // CPU s of place_random with sampling = "free-voxels"
  double setup_free_voxels = 0, setup_lattice = 0;  // CPU s of build_initial_state for those starts
  double peak_rss = 0;                        // bytes, the child's
};

std::vector<SetupRow> measure_setup(const SetupPlan& plan);

}  // namespace ede::study
