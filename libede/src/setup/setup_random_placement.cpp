// Random sequential addition with a uniform grid: each candidate costs one 3 x 3 cell query, whatever N.
//
// Draw order (part of the reproducibility contract): per attempt, x then y, each one uniform01().
// The attempt budget is per species and counts every candidate, accepted or not, so a jammed placement
// fails in bounded time with a message saying how far it got.
// With sampling = "free-voxels" the draws switch, once most candidates are rejected, to voxels not yet wholly
// blocked (free_voxel_list.hpp): per attempt below(list size), then x and y in the voxel. The switch is taken
// when the last 64 disks needed more than 16 attempts each on average (then roughly a tenth of the voxels are
// free: the list costs a few bytes per disk while placing).
#include "setup/setup_random_placement.hpp"

#include <algorithm>
#include <functional>

#include "setup/free_voxel_list.hpp"

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

// Whether a centre from a free voxel is one that draw() could have returned and accepted: in [lo, hi) with the
// whole disk inside [a0, a1], or in [0, L) along a wrapping axis.
bool within(const Axis& ax, double a0, double a1, double r, double c) {
  if (ax.wraps) return c >= 0 && c < ax.length;
  return c >= ax.lo && c < ax.hi && c - r >= a0 && c + r <= a1;
}

// The voxel columns (or rows) whose centres a disk of radius r_min may take, one voxel wider on each side
// (round-off): all of them along a wrapping axis.
void voxel_span(const Axis& ax, double r_min, double a0, double a1, double inv_w, std::int64_t n, std::int64_t& i0,
                std::int64_t& i1) {
  if (ax.wraps) {
    i0 = 0;
    i1 = n - 1;
    return;
  }
  i0 = std::int64_t(std::floor((a0 + r_min) * inv_w)) - 1;
  i1 = std::int64_t(std::floor((a1 - r_min) * inv_w)) + 1;
}

// Random sampling's switch from the whole region to the free-voxel list (sampling = "free-voxels").
class Sampler {
 public:
  explicit Sampler(RandomSampling mode) : mode_(mode) {}
  bool listing() const { return listing_; }

  // After each placed disk: `attempts` is the species' running total. Decides the switch every 64 disks.
  void placed(std::int64_t attempts, const BlockedVoxels& map, const RandomPlacement& where, double r_min) {
    if (mode_ != RandomSampling::FreeVoxels || listing_ || ++window_disks_ < kWindow) return;
    const bool slow = attempts - window_start_ > kWindow * kSwitchAttempts;
    window_disks_ = 0;
    window_start_ = attempts;
    if (!slow || !map.enabled()) return;
    const Region& g = where.region;
    std::int64_t ix0, ix1, iy0, iy1;
    voxel_span(axis(g.x0, g.x1, where.lx, where.periodic_box, r_min), r_min, g.x0, g.x1, map.inverse_voxel_width(),
               map.voxels_x(), ix0, ix1);
    voxel_span(axis(g.y0, g.y1, where.ly, where.periodic_box, r_min), r_min, g.y0, g.y1,
               map.inverse_voxel_height(), map.voxels_y(), iy0, iy1);
    listing_ = list.build(map, ix0, ix1, iy0, iy1);
  }

  FreeVoxelList list;

 private:
  static constexpr std::int64_t kWindow = 64, kSwitchAttempts = 16;
  RandomSampling mode_;
  bool listing_ = false;
  std::int64_t window_disks_ = 0, window_start_ = 0;
};

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
  Sampler sampler(where.sampling);
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
      bool inside;
      if (sampler.listing()) {
        if (sampler.list.size() == 0) return jammed(where, radii, k, attempts);  // no free point anywhere
        inside = sampler.list.draw(rng, cx, cy) && within(ax, g.x0, g.x1, r, cx) && within(ay, g.y0, g.y1, r, cy);
        sampler.list.compact_if_stale();
      } else {
        const bool inside_x = draw(ax, g.x0, g.x1, r, rng, cx);
        const bool inside_y = draw(ay, g.y0, g.y1, r, rng, cy);
        inside = inside_x && inside_y;
      }
      if (inside && !grid.overlaps(cx, cy, r) && clear_of_segments(where, cx, cy, r)) {
        grid.insert(cx, cy, r);
        x[k] = cx;
        y[k] = cy;
        break;
      }
    }
    sampler.placed(attempts, grid.blocked_voxels(), where, radii.back());
  }
  return Ok{};
}

}  // namespace ede::setup_detail
