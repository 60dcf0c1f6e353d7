// Crater geometry (crater_*.cpp) on hand-made states with known answers.
//
// The bed is a square stack of touching disks, r = 1/64, 32 columns x 16 rows in the unit box: column c
// has its centres at x = (2c + 1) r, so with the default bin width 2r every column is exactly one bin,
// and the surface is at h = 32 r = 0.5. Holes are carved by moving disks away; every length is a dyadic
// fraction, so the expected depths, widths and areas are exact.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "analysis/crater.hpp"

using namespace ede;

namespace {

constexpr double kR = 1.0 / 64;
constexpr int kColumns = 32, kRows = 16;

struct Bed {
  DiskPositions state;
  std::vector<bool> is_bed;
  std::size_t at(int column, int row) const { return std::size_t(row * kColumns + column); }
};

// The stack, plus (optionally) a projectile that is not bed.
Bed stack(bool with_projectile = false) {
  Bed b;
  for (int row = 0; row < kRows; ++row)
    for (int c = 0; c < kColumns; ++c) {
      b.state.x.push_back((2 * c + 1) * kR);
      b.state.y.push_back((2 * row + 1) * kR);
      b.state.r.push_back(kR);
      b.is_bed.push_back(true);
    }
  if (with_projectile) {
    b.state.x.push_back(0.5), b.state.y.push_back(0.75), b.state.r.push_back(5 * kR);
    b.is_bed.push_back(false);
  }
  return b;
}

// Moves disk i far above the bed, to the k-th ejecta slot: two rows at y = 0.8 and 0.95, slots 6r apart
// (rim gap 4r, more than the default link gap 2r), so no two ejecta link and none links to the bed.
void eject(DiskPositions& s, std::size_t i, int k) {
  s.x[i] = (6 * (k % 8) + 1) * kR;
  s.y[i] = k < 8 ? 0.8 : 0.95;
}

// Removes the top `depth[c]` rows of each column c (in column order), ejecting the disks; returns how many.
int carve(const Bed& b, DiskPositions& after, const std::vector<int>& depth) {
  int k = 0;
  for (int c = 0; c < kColumns; ++c)
    for (int m = 0; m < depth[std::size_t(c)]; ++m) eject(after, b.at(c, kRows - 1 - m), k++);
  return k;
}

const CraterBox kBox{1, 1, false};

}  // namespace

TEST_CASE("crater: a box-shaped hole has its exact depth, width, area and count", "[analysis][crater]") {
  const Bed b = stack(true);
  DiskPositions after = b.state;
  std::vector<int> depth(kColumns, 0);
  for (int c = 10; c <= 14; ++c) depth[std::size_t(c)] = 3;  // 5 columns, 3 rows deep: 15 disks
  REQUIRE(carve(b, after, depth) == 15);
  after.y.back() = 0.25;  // the projectile moved too: it is not bed, so it does not count

  auto r = analyze_crater(b.state, after, b.is_bed, kBox, CraterSettings{});
  REQUIRE(r);
  const CraterReport& rep = r.value();
  CHECK(rep.lengths.bed_radius == kR);
  CHECK(rep.lengths.bins == 32);
  CHECK(rep.lengths.bin_width == 2 * kR);
  CHECK(rep.bed_disks == 512);
  CHECK(rep.displaced.size() == 15);
  CHECK(rep.before.detached == 0);
  CHECK(rep.after.detached == 15);
  for (std::size_t k = 0; k < 32; ++k) {
    CHECK(rep.before.height[k] == 0.5);
    CHECK(rep.after.height[k] == (k >= 10 && k <= 14 ? 0.5 - 6 * kR : 0.5));
  }
  const CraterMetrics& m = rep.metrics;
  CHECK(m.has_crater);
  CHECK(m.depth == 6 * kR);
  CHECK(m.deepest_bin == 10);  // the leftmost of equal maxima
  CHECK(m.deepest_x == 21 * kR);
  CHECK(m.depth_below_mean == 6 * kR);
  CHECK(m.first_bin == 10);
  CHECK(m.last_bin == 14);
  CHECK(m.left == 10.0 / 32);
  CHECK(m.right == 15.0 / 32);
  CHECK(m.width == 5.0 / 32);
  CHECK(m.area == 5.0 / 32 * 6 * kR);
  CHECK(m.removed_area == m.area);
  CHECK(m.raised_area == 0);
}

TEST_CASE("crater: a V-shaped hole, a drop equal to the threshold is not crater", "[analysis][crater]") {
  const Bed b = stack();
  DiskPositions after = b.state;
  std::vector<int> depth(kColumns, 0);
  for (int c = 9; c <= 15; ++c) depth[std::size_t(c)] = 4 - std::abs(c - 12);  // 1 2 3 4 3 2 1
  REQUIRE(carve(b, after, depth) == 16);

  SECTION("default drop threshold r: every carved column is crater") {
    auto r = analyze_crater(b.state, after, b.is_bed, kBox, CraterSettings{});
    REQUIRE(r);
    const CraterMetrics& m = r.value().metrics;
    CHECK(r.value().displaced.size() == 16);
    CHECK(m.depth == 8 * kR);
    CHECK(m.deepest_bin == 12);
    CHECK(m.first_bin == 9);
    CHECK(m.last_bin == 15);
    CHECK(m.width == 7.0 / 32);
    CHECK(m.area == 16 * 2 * kR / 32);  // 16 disks' worth of column height, times the bin width
  }
  SECTION("drop threshold 2r exactly: the columns that fell by exactly 2r are left out") {
    CraterSettings s;
    s.drop_threshold = {2, true};
    auto r = analyze_crater(b.state, after, b.is_bed, kBox, s);
    REQUIRE(r);
    const CraterMetrics& m = r.value().metrics;
    CHECK(m.first_bin == 10);
    CHECK(m.last_bin == 14);
    CHECK(m.width == 5.0 / 32);
    CHECK(m.area == (2 + 3 + 4 + 3 + 2) * 2 * kR / 32);
    CHECK(m.removed_area == 16 * 2 * kR / 32);  // the whole-box sum still has them
  }
  SECTION("drop threshold 8r: nothing fell by more: no crater, width and area 0, depth still 8r") {
    CraterSettings s;
    s.drop_threshold = {8 * kR, false};
    auto r = analyze_crater(b.state, after, b.is_bed, kBox, s);
    REQUIRE(r);
    const CraterMetrics& m = r.value().metrics;
    CHECK_FALSE(m.has_crater);
    CHECK(m.depth == 8 * kR);
    CHECK(m.width == 0);
    CHECK(m.area == 0);
    CHECK(m.left == m.right);
  }
}

TEST_CASE("crater: ejecta count as surface only with the detached filter off", "[analysis][crater]") {
  const Bed b = stack();
  DiskPositions after = b.state;
  std::vector<int> depth(kColumns, 0);
  depth[20] = 2;
  REQUIRE(carve(b, after, depth) == 2);  // ejecta slots 0 and 1: x = r and 7r, y = 0.8
  CraterSettings keep;
  keep.exclude_detached = false;
  auto r = analyze_crater(b.state, after, b.is_bed, kBox, keep);
  REQUIRE(r);
  CHECK(r.value().after.detached == 0);
  CHECK(r.value().after.height[0] == 0.8 + kR);  // the ejecta raise bins 0 and 3
  CHECK(r.value().after.height[3] == 0.8 + kR);
  CHECK(r.value().metrics.raised_area == 2 * (0.8 + kR - 0.5) / 32);
  CHECK(r.value().metrics.depth == 4 * kR);
  CHECK(r.value().metrics.deepest_bin == 20);
}

TEST_CASE("crater: an emptied column is at the floor, h = 0", "[analysis][crater]") {
  const Bed b = stack();
  DiskPositions after = b.state;
  for (int row = 0; row < kRows; ++row) {  // column 7 moved sideways onto the surface of columns 24..31
    const std::size_t i = b.at(7, row);
    after.x[i] = (2 * (24 + row % 8) + 1) * kR;
    after.y[i] = 0.5 + kR + (row / 8) * 2 * kR;
  }
  auto r = analyze_crater(b.state, after, b.is_bed, kBox, CraterSettings{});
  REQUIRE(r);
  const CraterReport& rep = r.value();
  CHECK(rep.after.disks[7] == 0);
  CHECK(rep.after.height[7] == 0);
  CHECK(rep.metrics.depth == 0.5);
  CHECK(rep.metrics.depth_below_mean == 0.5);
  CHECK(rep.metrics.width == 1.0 / 32);
  CHECK(rep.after.height[24] == 0.5 + 4 * kR);  // the moved grains lie on the bed: linked, part of the surface
  CHECK(rep.after.detached == 0);
  CHECK(rep.metrics.raised_area == 8 * 4 * kR / 32);
}

TEST_CASE("crater: displacement thresholds are strict and use the Euclidean distance", "[analysis][crater]") {
  const Bed b = stack();
  DiskPositions after = b.state;
  after.x[0] += kR / 2;                                           // exactly 0.5 r: not displaced
  after.x[1] = std::nextafter(after.x[1] + kR / 2, 1.0);          // just over: displaced
  after.x[2] += 3.0 / 512, after.y[2] += 4.0 / 512;               // 5/512 along a diagonal
  CHECK(displaced_disks(b.state, after, b.is_bed, kBox, kR / 2) == std::vector<std::uint32_t>{1, 2});
  CHECK(displaced_disks(b.state, after, b.is_bed, kBox, 5.0 / 512).empty());
  CHECK(displaced_disks(b.state, after, b.is_bed, kBox, std::nextafter(5.0 / 512, 0.0)) == std::vector<std::uint32_t>{2});
  CHECK(displaced_disks(b.state, after, b.is_bed, kBox, 0).size() == 3);  // 0: any move at all
  std::vector<bool> only_first(b.is_bed.size(), false);
  only_first[1] = true;  // non-bed disks never count
  CHECK(displaced_disks(b.state, after, only_first, kBox, 0) == std::vector<std::uint32_t>{1});
}

TEST_CASE("crater: a periodic box measures displacement with the minimum image", "[analysis][crater]") {
  DiskPositions before{{0.01}, {0.5}, {0.01}}, after{{0.99}, {0.5}, {0.01}};
  CHECK(displaced_disks(before, after, {true}, CraterBox{1, 1, true}, 0.05).empty());
  CHECK(displaced_disks(before, after, {true}, CraterBox{1, 1, false}, 0.05).size() == 1);
}

TEST_CASE("crater: the bed's body is what links to the floor, both halves of a split bed", "[analysis][crater]") {
  const Bed b = stack();
  DiskPositions s = b.state;
  for (int row = 0; row < kRows; ++row) s.y[b.at(15, row)] = 0.9, s.x[b.at(15, row)] = 0.05 * row;  // cut
  const std::vector<bool> body = bed_body(s, b.is_bed, kBox, 2 * kR);
  std::size_t in = 0;
  for (std::size_t i = 0; i < body.size(); ++i) in += body[i] ? 1 : 0;
  CHECK(in == 512 - 16);  // both halves touch the floor; the moved column is a loose row high above
  CHECK_FALSE(body[b.at(15, 3)]);
  CHECK(body[b.at(0, 15)]);
  CHECK(body[b.at(31, 15)]);

  SECTION("a rim gap of exactly the link gap still links; a hair more does not") {
    DiskPositions t{{0.5, 0.5}, {kR, 4 * kR}, {kR, kR}};  // centre distance 3r: rim gap r
    CHECK(bed_body(t, {true, true}, kBox, kR) == std::vector<bool>{true, true});
    t.y[1] += 1e-12;
    CHECK(bed_body(t, {true, true}, kBox, kR) == std::vector<bool>{true, false});
  }
}

TEST_CASE("crater: bins tile the box, edges and out-of-box centres go to the end bins", "[analysis][crater]") {
  const Bed b = stack();
  CraterSettings s;
  s.bin_width = {0.03, false};  // 1 / 0.03 = 33.3 -> 33 bins of width 1/33
  auto l = resolve_crater_lengths(b.state, b.is_bed, kBox, s);
  REQUIRE(l);
  CHECK(l.value().bins == 33);
  CHECK(l.value().bin_width == 1.0 / 33);
  s.bin_width = {5, false};  // wider than the box: one bin
  CHECK(resolve_crater_lengths(b.state, b.is_bed, kBox, s).value().bins == 1);

  DiskPositions edge{{0.0, 1.0, -0.1, 1.2}, {0.1, 0.2, 0.3, 0.4}, {0.01, 0.01, 0.01, 0.01}};
  const SurfaceProfile p = surface_profile(edge, {true, true, true, true}, 1.0, 4);
  CHECK(p.disks == std::vector<std::uint32_t>{2, 0, 0, 2});
  CHECK(p.height[0] == 0.3 + 0.01);
  CHECK(p.height[3] == 0.4 + 0.01);
  CHECK(p.height[1] == 0);  // empty: the floor
}

TEST_CASE("crater: bad input gives messages, not crashes", "[analysis][crater]") {
  const Bed b = stack();
  const std::vector<bool> none(b.is_bed.size(), false);
  auto r = analyze_crater(b.state, b.state, none, kBox, CraterSettings{});
  REQUIRE_FALSE(r);
  CHECK(r.error().message.find("no disk is marked as bed") != std::string::npos);

  DiskPositions shorter = b.state;
  shorter.x.pop_back(), shorter.y.pop_back(), shorter.r.pop_back();
  CHECK_FALSE(analyze_crater(b.state, shorter, b.is_bed, kBox, CraterSettings{}));

  CraterSettings s;
  s.bin_width = {0, false};
  auto z = analyze_crater(b.state, b.state, b.is_bed, kBox, s);
  REQUIRE_FALSE(z);
  CHECK(z.error().message.find("bin width") != std::string::npos);
  s = CraterSettings{};
  s.drop_threshold = {-1, false};
  CHECK_FALSE(analyze_crater(b.state, b.state, b.is_bed, kBox, s));
  s = CraterSettings{};
  s.bin_width = {1e-9, false};
  auto fine = analyze_crater(b.state, b.state, b.is_bed, kBox, s);
  REQUIRE_FALSE(fine);
  CHECK(fine.error().message.find("10^7 bins") != std::string::npos);

  SurfaceProfile p1, p2;
  p1.bin_width = p2.bin_width = 0.5;
  p1.height = {1, 1};
  p2.height = {1};
  CHECK_FALSE(crater_metrics(p1, p2, 0.1));
}

TEST_CASE("crater: an unchanged bed has no crater", "[analysis][crater]") {
  const Bed b = stack();
  auto r = analyze_crater(b.state, b.state, b.is_bed, kBox, CraterSettings{});
  REQUIRE(r);
  CHECK(r.value().displaced.empty());
  CHECK(r.value().metrics.depth == 0);
  CHECK_FALSE(r.value().metrics.has_crater);
  CHECK(r.value().metrics.removed_area == 0);
  CHECK(r.value().metrics.raised_area == 0);
}
