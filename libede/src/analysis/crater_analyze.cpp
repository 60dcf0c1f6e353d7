// analyze_crater: the geometric analysis in one call: lengths, displaced disks, profiles, metrics.
//
// Only composition: each step is its own pure function (crater_*.cpp) and can be called alone. The same
// lengths are used before and after, taken from the state before, so both profiles share their bins.
// Rejected: resolving the defaults from the state after, whose radii are the same but whose body (and so
// nothing else) could differ; one source for the lengths keeps the two profiles comparable by construction.
#include "analysis/crater.hpp"

namespace ede {

Result<CraterReport> analyze_crater(const DiskPositions& before, const DiskPositions& after,
                                    const std::vector<bool>& is_bed, const CraterBox& box,
                                    const CraterSettings& settings) {
  const std::size_t n = before.size();
  if (after.size() != n || after.y.size() != n || after.r.size() != n)
    return Error{"the states before and after do not hold the same number of disks"};
  auto lengths = resolve_crater_lengths(before, is_bed, box, settings);
  if (!lengths) return lengths.error();
  CraterReport r;
  r.lengths = lengths.value();
  const CraterLengths& l = r.lengths;
  for (std::size_t i = 0; i < n; ++i) r.bed_disks += is_bed[i] ? 1 : 0;
  r.displaced = displaced_disks(before, after, is_bed, box, l.displacement_threshold);

  const auto profile = [&](const DiskPositions& s) {
    const std::vector<bool> counted = l.exclude_detached ? bed_body(s, is_bed, box, l.link_gap) : is_bed;
    SurfaceProfile p = surface_profile(s, counted, box.lx, l.bins);
    for (std::size_t i = 0; i < n; ++i) p.detached += is_bed[i] && !counted[i] ? 1 : 0;
    return p;
  };
  r.before = profile(before);
  r.after = profile(after);
  auto metrics = crater_metrics(r.before, r.after, l.drop_threshold);
  if (!metrics) return metrics.error();
  r.metrics = metrics.value();
  return r;
}

}  // namespace ede
