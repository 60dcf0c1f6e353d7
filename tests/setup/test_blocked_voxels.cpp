// Tests of the blocked-voxel bitmap (setup/blocked_voxels.hpp) and of random placement with it: the same
// positions, bit for bit, as the grid alone and as an all-pairs reference drawing the same candidates.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "setup/placement_grid.hpp"
#include "setup/setup_random_placement.hpp"

using namespace ede;
using namespace ede::setup_detail;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Placed {
  std::vector<double> x, y, r;
  std::array<std::uint64_t, 4> rng_after{};
  bool ok = false;
};

std::vector<double> radii_for(std::size_t n, double phi, double spread, std::uint64_t seed) {
  // Radii r0 * (1 - spread/2 .. 1 + spread/2), scaled so the disks cover phi of the unit box.
  Rng rng(seed ^ 0x5151);
  std::vector<double> r(n);
  double area = 0;
  for (double& v : r) {
    v = 1 + spread * (rng.uniform01() - 0.5);
    area += kPi * v * v;
  }
  const double scale = std::sqrt(phi / area);
  for (double& v : r) v *= scale;
  return r;
}

Placed place(std::vector<double> radii, bool periodic, bool voxels, std::uint64_t seed) {
  double r_max = 0, r_min = radii.empty() ? 0 : radii[0], r_sum = 0;
  for (double r : radii) r_max = std::max(r_max, r), r_min = std::min(r_min, r), r_sum += r;
  PlacementGrid grid(1, 1, periodic, 2 * r_max, radii.size());
  if (voxels) grid.enable_blocked_voxels(r_min, r_sum / double(radii.size()));
  Rng rng(seed);
  Placed p;
  p.ok = bool(place_random({{0, 0, 1, 1}, 1, 1, periodic, {}, RandomSampling::Region}, radii, grid, rng, p.x, p.y));
  p.r = radii;
  p.rng_after = rng.state();
  return p;
}

double wrap(double d, bool periodic) {
  if (!periodic) return d;
  if (d > 0.5) return d - 1;
  if (d < -0.5) return d + 1;
  return d;
}

// Random sequential addition written out plainly: the same draws as place_random in the unit box, every
// candidate compared with every placed disk, with the grid's minimum-image difference and test.
Placed place_all_pairs(std::vector<double> radii, bool periodic, std::uint64_t seed) {
  std::sort(radii.begin(), radii.end(), std::greater<double>());
  Rng rng(seed);
  Placed p;
  for (double r : radii) {
    for (;;) {
      double cx, cy;
      bool inside = true;
      if (periodic) {
        cx = rng.uniform(0, 1);
        cy = rng.uniform(0, 1);
      } else {
        cx = rng.uniform(r, 1 - r);
        cy = rng.uniform(r, 1 - r);
        inside = cx - r >= 0 && cx + r <= 1 && cy - r >= 0 && cy + r <= 1;
      }
      bool free = inside;
      for (std::size_t j = 0; free && j < p.x.size(); ++j) {
        const double dx = wrap(p.x[j] - cx, periodic), dy = wrap(p.y[j] - cy, periodic), s = r + p.r[j];
        if (dx * dx + dy * dy < s * s) free = false;
      }
      if (free) {
        p.x.push_back(cx);
        p.y.push_back(cy);
        p.r.push_back(r);
        break;
      }
    }
  }
  p.ok = true;
  p.rng_after = rng.state();
  return p;
}

void require_same(const Placed& a, const Placed& b) {
  REQUIRE(a.ok);
  REQUIRE(b.ok);
  REQUIRE(a.x.size() == b.x.size());
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    INFO("disk " << i);
    REQUIRE(a.x[i] == b.x[i]);
    REQUIRE(a.y[i] == b.y[i]);
  }
  CHECK(a.rng_after == b.rng_after);  // the same number of draws: every candidate judged alike
}

}  // namespace

TEST_CASE("random placement with blocked voxels places exactly what the grid alone places", "[setup][placement]") {
  for (bool periodic : {true, false}) {
    for (double spread : {0.0, 0.6}) {
      for (std::uint64_t seed : {1u, 7u, 2026u}) {
        INFO("periodic " << periodic << ", radius spread " << spread << ", seed " << seed);
        const std::vector<double> radii = radii_for(3000, 0.5, spread, seed);
        const Placed with = place(radii, periodic, true, seed);
        const Placed without = place(radii, periodic, false, seed);
        require_same(with, without);
      }
    }
  }
}

TEST_CASE("random placement with blocked voxels matches an all-pairs reference", "[setup][placement]") {
  for (bool periodic : {true, false}) {
    for (std::uint64_t seed : {3u, 11u}) {
      INFO("periodic " << periodic << ", seed " << seed);
      const std::vector<double> radii = radii_for(400, 0.48, 0.3, seed);
      require_same(place(radii, periodic, true, seed), place_all_pairs(radii, periodic, seed));
    }
  }
}

TEST_CASE("a blocked voxel is wholly inside an exclusion zone, and the deep inside of every zone is blocked", "[setup][placement][slow]") {
  for (bool periodic : {true, false}) {
    INFO("periodic " << periodic);
    const std::vector<double> radii = radii_for(2000, 0.5, 0.4, 5);
    const double r_floor = *std::min_element(radii.begin(), radii.end());
    const double r_max = *std::max_element(radii.begin(), radii.end());
    const Placed p = place(radii, periodic, false, 5);
    REQUIRE(p.ok);
    PlacementGrid grid(1, 1, periodic, 2 * r_max, radii.size());
    grid.enable_blocked_voxels(r_floor, 0.5 * (r_floor + r_max));
    for (std::size_t i = 0; i < p.x.size(); ++i) grid.insert(p.x[i], p.y[i], p.r[i]);
    REQUIRE(grid.blocked_voxels().enabled());
    // Random points: a blocked one must be closer than r_floor + r_j to some disk j (exactly, in long
    // double); one deeper than r_floor inside a zone is deeper than a voxel's diagonal (about half of
    // r_floor + the mean radius), so its whole voxel is in that zone and must be blocked.
    Rng rng(99);
    int blocked = 0, deep = 0, deep_blocked = 0;
    for (int k = 0; k < 20000; ++k) {
      const double x = rng.uniform01(), y = rng.uniform01();
      long double nearest = 1e9L;
      for (std::size_t j = 0; j < p.x.size(); ++j) {
        long double dx = (long double)p.x[j] - x, dy = (long double)p.y[j] - y;
        if (periodic) dx -= std::round(dx), dy -= std::round(dy);
        nearest = std::min(nearest, std::sqrt(dx * dx + dy * dy) - (long double)(r_floor + p.r[j]));
      }
      const bool b = grid.blocked_voxels().blocked(x, y);
      if (b) {
        ++blocked;
        REQUIRE(nearest < 0);
      }
      if (nearest < -(long double)r_floor) ++deep, deep_blocked += b;
    }
    CHECK(deep > 1000);
    CHECK(deep_blocked == deep);
    CHECK(blocked > deep);
  }
}
