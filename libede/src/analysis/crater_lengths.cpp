// resolve_crater_lengths: the analysis lengths with their defaults filled in from the bed's mean radius.
//
// Every default is a multiple of r_bed, the mean bed radius before the impact, so the same settings mean
// the same thing for a bed of any grain size. The bin count is lx / w rounded to the nearest integer and the
// width then lx / bins exactly, so the bins tile the box with no partial bin at the right edge.
// Rejected: a fixed bin width in box units, which would make a scan over bed size change its resolution.
#include <cmath>
#include <string>

#include "analysis/crater.hpp"
#include "ede/number_text.hpp"

namespace ede {

namespace {

// A very fine profile is a mistake (a typo in --bin-width), not a request for 10^9 bins.
constexpr double kMaxBins = 1e7;

Status check_length(const char* what, double v, bool zero_allowed) {
  if (!std::isfinite(v) || v < 0 || (!zero_allowed && v == 0))
    return Error{std::string(what) + " must be a finite number " + (zero_allowed ? ">= 0" : "> 0") + ", got " +
                 brief(v)};
  return Ok{};
}

}  // namespace

Result<CraterLengths> resolve_crater_lengths(const DiskPositions& before, const std::vector<bool>& is_bed,
                                             const CraterBox& box, const CraterSettings& s) {
  const std::size_t n = before.size();
  if (before.y.size() != n || before.r.size() != n || is_bed.size() != n)
    return Error{"the positions, radii and bed flags do not have one entry per disk"};
  if (!(box.lx > 0) || !(box.ly > 0) || !std::isfinite(box.lx) || !std::isfinite(box.ly))
    return Error{"the box must have finite sizes > 0"};
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (is_bed[i]) sum += before.r[i], ++count;
  if (count == 0) return Error{"no disk is marked as bed"};
  CraterLengths l;
  l.bed_radius = sum / double(count);
  const auto length = [&](const CraterLength& v) { return v.in_bed_radii ? v.value * l.bed_radius : v.value; };
  l.displacement_threshold = length(s.displacement_threshold);
  l.bin_width = length(s.bin_width);
  l.drop_threshold = length(s.drop_threshold);
  l.link_gap = length(s.link_gap);
  l.exclude_detached = s.exclude_detached;
  if (Status c = check_length("the displacement threshold", l.displacement_threshold, true); !c) return c.error();
  if (Status c = check_length("the bin width", l.bin_width, false); !c) return c.error();
  if (Status c = check_length("the drop threshold", l.drop_threshold, true); !c) return c.error();
  if (Status c = check_length("the link gap", l.link_gap, true); !c) return c.error();
  const double bins = std::round(box.lx / l.bin_width);
  if (bins > kMaxBins)
    return Error{"a bin width of " + brief(l.bin_width) +
                 " gives more than 10^7 bins across the box; use a wider one"};
  l.bins = bins < 1 ? 1 : std::size_t(bins);
  l.bin_width = box.lx / double(l.bins);
  return l;
}

}  // namespace ede
