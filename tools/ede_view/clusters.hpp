// Bonded clusters of a square-well state, for the view's "clusters" colouring. Two disks are bonded when
// their centres are closer than their species pair's outermost well: the largest radius among the pair's
// steps with a negative energy ([[physics.steps]]; a pair with shoulders only never bonds), measured to the
// nearest periodic image in a periodic box. A cluster is a connected set of bonded disks; a disk bonded to
// none is alone. Clusters are ranked by size, largest first, ties by their lowest disk id, so that the
// same state always gets the same ranks (and the page the same colours).
// Found with a grid of cells at least the largest bond radius wide and union-find: O(N). Rejected: the
// library's analysis room (an analysis over a log is a public function there, but nothing else asks for
// clusters yet, and the view is the one place that draws them; it moves there when ede-stats wants them),
// and the engine's own depths (they are not in a State or a log).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/scene.hpp"
#include "ede/state.hpp"

namespace ede::view {

// The bond radius of every pair of species (by the state's species index, a * species + b; 0: no well).
struct BondRadii {
  std::size_t species = 0;
  std::vector<double> radius;
  double largest = 0;  // 0: the scene has no well at all
};
// From the scene's steps, the default entry (no species named) first and named pairs over it, as the
// engine reads them; `names` are the state's species names.
BondRadii bond_radii(const std::vector<PairSteps>& steps, const std::vector<std::string>& names);

struct Clusters {
  std::vector<std::uint32_t> rank;  // per disk: 0 alone, else its cluster's rank (1 = the largest)
  std::size_t count = 0;            // clusters of two or more disks
  std::size_t largest = 0;          // disks in the largest cluster (1 when every disk is alone, 0 without disks)
  std::size_t alone = 0;            // disks bonded to none
};
Clusters find_clusters(const State& s, const BondRadii& bonds);

// Why a scene's states cannot be coloured by clusters ("" when they can).
std::string clusters_unavailable(const BondRadii& bonds);

}  // namespace ede::view
