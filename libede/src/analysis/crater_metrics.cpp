// crater_metrics: depth, width and area of the crater from the surface before and after.
//
// Everything is read off drop(k) = h_before(k) - h_after(k) per bin, so a surface that was rough to begin
// with does not count its own roughness as crater. The crater region grows from the deepest bin outwards
// while the drop stays above the threshold: one crater, contiguous, around the deepest point.
// Rejected: every bin above the threshold wherever it lies, which would add up unrelated dips (a grain
// knocked off far from the impact) into one "width".
#include <algorithm>
#include <string>

#include "analysis/crater.hpp"

namespace ede {

Result<CraterMetrics> crater_metrics(const SurfaceProfile& before, const SurfaceProfile& after,
                                     double drop_threshold) {
  const std::size_t n = before.height.size();
  if (n == 0 || after.height.size() != n || before.bin_width != after.bin_width)
    return Error{"the surface profiles before and after must have the same bins (and at least one)"};
  const double w = before.bin_width;
  std::vector<double> drop(n);
  double sum_before = 0, min_after = after.height[0];
  CraterMetrics m;
  for (std::size_t k = 0; k < n; ++k) {
    drop[k] = before.height[k] - after.height[k];
    sum_before += before.height[k];
    min_after = std::min(min_after, after.height[k]);
    if (drop[k] > drop[m.deepest_bin]) m.deepest_bin = k;
    if (drop[k] > 0) m.removed_area += drop[k];
    if (drop[k] < 0) m.raised_area -= drop[k];
  }
  m.removed_area *= w;
  m.raised_area *= w;
  m.depth = drop[m.deepest_bin];
  m.deepest_x = before.centre(m.deepest_bin);
  m.depth_below_mean = sum_before / double(n) - min_after;
  m.has_crater = m.depth > drop_threshold;
  m.first_bin = m.last_bin = m.deepest_bin;
  m.left = m.right = m.deepest_x;
  if (!m.has_crater) return m;
  while (m.first_bin > 0 && drop[m.first_bin - 1] > drop_threshold) --m.first_bin;
  while (m.last_bin + 1 < n && drop[m.last_bin + 1] > drop_threshold) ++m.last_bin;
  double sum_drop = 0;
  for (std::size_t k = m.first_bin; k <= m.last_bin; ++k) sum_drop += drop[k];
  m.left = double(m.first_bin) * w;
  m.right = double(m.last_bin + 1) * w;
  m.width = double(m.last_bin - m.first_bin + 1) * w;
  m.area = sum_drop * w;
  return m;
}

}  // namespace ede
