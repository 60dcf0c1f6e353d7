// displaced_disks: the bed disks whose centre moved by more than a threshold between two states.
//
// The distance is the Euclidean one (std::hypot, so a move along one axis compares exactly), taken with
// the minimum image in a periodic box. "More than" is strict: a disk moved by exactly the threshold is not
// displaced. Rejected: counting disks whose path length exceeds the threshold, which needs every event
// and counts a grain that rattled in place; the net displacement is what the bed's final shape shows.
#include <algorithm>
#include <cmath>

#include "analysis/crater.hpp"

namespace ede {

namespace {

double minimum_image(double d, double length) { return d - length * std::round(d / length); }

}  // namespace

std::vector<std::uint32_t> displaced_disks(const DiskPositions& before, const DiskPositions& after,
                                           const std::vector<bool>& is_bed, const CraterBox& box, double threshold) {
  std::vector<std::uint32_t> out;
  const std::size_t n = std::min({before.size(), after.size(), is_bed.size()});
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_bed[i]) continue;
    double dx = after.x[i] - before.x[i], dy = after.y[i] - before.y[i];
    if (box.periodic) dx = minimum_image(dx, box.lx), dy = minimum_image(dy, box.ly);
    if (std::hypot(dx, dy) > threshold) out.push_back(std::uint32_t(i));
  }
  return out;
}

}  // namespace ede
