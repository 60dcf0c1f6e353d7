// Random sequential addition with a uniform grid: each candidate costs one 3 x 3 cell query, whatever N.
//
// Draw order (part of the reproducibility contract): per attempt, x then y, each one uniform01().
// The attempt budget is per species and counts every candidate, accepted or not, so a jammed placement
// fails in bounded time with a message saying how far it got.
// Rejected: sampling only from "free" voxels (exact and faster near jamming, but the exclusion zones change
// with the candidate's radius in a polydisperse species, and the bookkeeping is far larger than this file).
#include "setup/setup_random_placement.hpp"

#include <algorithm>
#include <functional>

namespace ede::setup_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Where a centre may go along one dimension: [lo, hi] keeps the disk inside, or [0, L) if wrapping.
struct Axis {
  bool wraps;
  double lo, hi, length;
};

Axis axis(double a0, double a1, double length, bool periodic_box, double r) {
  if (periodic_box && a0 <= 0 && a1 >= length) return {true, 0, length, length};
  return {false, a0 + r, a1 - r, length};
}

// A candidate centre, or false if round-off put the disk a hair outside [lo - r, hi + r].
bool draw(const Axis& ax, double a0, double a1, double r, Rng& rng, double& out) {
  if (ax.wraps) {
    out = rng.uniform(0, ax.length);
    if (out >= ax.length) out = 0;  // unreachable for lx * (1 - 2^-53); kept as the [0, L) guarantee
    return true;
  }
  out = rng.uniform(ax.lo, ax.hi);
  return out - r >= a0 && out + r <= a1;
}

double disk_area(const std::vector<double>& radii, std::size_t n) {
  double area = 0;
  for (std::size_t k = 0; k < n; ++k) area += kPi * radii[k] * radii[k];
  return area;
}

Error jammed(const RandomPlacement& where, const std::vector<double>& radii, std::size_t placed,
             std::int64_t attempts) {
  const double fraction = disk_area(radii, placed) / where.region.area();
  return Error{"random placement stopped after " + std::to_string(attempts) + " attempts with " +
               std::to_string(placed) + " of " + std::to_string(radii.size()) +
               " disks placed (packing fraction " + number_text(fraction, 3) +
               " of the region). Random placement jams near 0.547; use placement.kind = \"lattice\" for "
               "dense packings, or fewer/smaller disks."};
}

bool clear_of_segments(const RandomPlacement& where, double x, double y, double r) {
  for (const Segment<double>& s : where.segments)
    if (segment_distance(s, x, y) < r) return false;
  return true;
}

}  // namespace

std::int64_t random_attempt_budget(std::int64_t count) { return std::max<std::int64_t>(1000000, 2000 * count); }

Status place_random(const RandomPlacement& where, std::vector<double>& radii, PlacementGrid& grid, Rng& rng,
                    std::vector<double>& x, std::vector<double>& y) {
  std::sort(radii.begin(), radii.end(), std::greater<double>());
  const Region& g = where.region;
  x.assign(radii.size(), 0);
  y.assign(radii.size(), 0);
  const std::int64_t budget = random_attempt_budget(std::int64_t(radii.size()));
  std::int64_t attempts = 0;
  for (std::size_t k = 0; k < radii.size(); ++k) {
    const double r = radii[k];
    const Axis ax = axis(g.x0, g.x1, where.lx, where.periodic_box, r);
    const Axis ay = axis(g.y0, g.y1, where.ly, where.periodic_box, r);
    if ((!ax.wraps && ax.lo > ax.hi) || (!ay.wraps && ay.lo > ay.hi)) {
      return Error{"a disk of radius " + number_text(r) + " does not fit in the region [" + number_text(g.x0) +
                   ", " + number_text(g.x1) + "] x [" + number_text(g.y0) + ", " + number_text(g.y1) +
                   "]; enlarge the region or reduce the radius"};
    }
    for (;;) {
      if (attempts == budget) return jammed(where, radii, k, attempts);
      ++attempts;
      double cx, cy;
      const bool inside_x = draw(ax, g.x0, g.x1, r, rng, cx);
      const bool inside_y = draw(ay, g.y0, g.y1, r, rng, cy);
      if (inside_x && inside_y && !grid.overlaps(cx, cy, r) && clear_of_segments(where, cx, cy, r)) {
        grid.insert(cx, cy, r);
        x[k] = cx;
        y[k] = cy;
        break;
      }
    }
  }
  return Ok{};
}

}  // namespace ede::setup_detail
