// Choosing which disks are big: see big_disks.hpp.
#include "engine/big_disks.hpp"

#include <algorithm>
#include <functional>

namespace ede {

DiskSizeSplit split_disk_sizes(const std::vector<double>& radii) {
  DiskSizeSplit split;
  const std::size_t n = radii.size();
  const std::size_t most = std::min<std::size_t>(64, n / 64);
  if (most == 0) {
    for (double r : radii) split.small_max_radius = std::max(split.small_max_radius, r);
    return split;
  }
  // The most + 1 largest radii, in descending order: the (most+1)-th is the reference.
  std::vector<double> top(radii);
  std::partial_sort(top.begin(), top.begin() + std::ptrdiff_t(most + 1), top.end(), std::greater<double>());
  const double reference = top[most];
  double smallest_big = std::numeric_limits<double>::infinity();
  double largest_small = 0;
  for (double r : radii) {
    if (r > 2 * reference)
      smallest_big = std::min(smallest_big, r);
    else
      largest_small = std::max(largest_small, r);
  }
  split.small_max_radius = largest_small;
  // The threshold sits between the two groups (a ratio of at least 2 apart), far from any radius, so
  // converting radii to float or long double cannot move a disk across it.
  if (smallest_big != std::numeric_limits<double>::infinity()) split.big_radius = std::sqrt(smallest_big * largest_small);
  return split;
}

}  // namespace ede
