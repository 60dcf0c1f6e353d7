// surface_profile: the height of the bed's surface in bins across the box.
//
// A bin's height is the highest top (y + r) of the counted disks whose centre lies in it: the surface a
// probe lowered into that column would touch first, and exact for hand-made states. Empty bins are 0, the
// box's floor. Bins are assigned by centre only, so a disk straddling two bins raises one of them.
// Rejected: a fill height from the area of grains per column (area / (width * packing)), which smooths the
// surface but needs the packing fraction, which an impact changes (compaction under the crater, dilation
// at the rim), and so would report a crater where the bed merely compacted.
#include <algorithm>
#include <cmath>

#include "analysis/crater.hpp"

namespace ede {

SurfaceProfile surface_profile(const DiskPositions& s, const std::vector<bool>& counted, double lx,
                               std::size_t bins) {
  SurfaceProfile p;
  if (bins == 0) return p;
  p.bin_width = lx / double(bins);
  p.height.assign(bins, 0.0);
  p.disks.assign(bins, 0);
  const std::size_t n = std::min(s.size(), counted.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!counted[i]) continue;
    const double k = std::floor(s.x[i] / p.bin_width);
    const std::size_t bin = !(k > 0) ? 0 : std::min(std::size_t(k), bins - 1);
    p.height[bin] = std::max(p.height[bin], s.y[i] + s.r[i]);
    ++p.disks[bin];
  }
  return p;
}

}  // namespace ede
