// Lattice placement: search over the number of sites per row, then lay the sites out.
//
// The search is O(count) arithmetic (no allocation), the same order as writing the positions. Spacings are
// accepted down to 2r (1 - 1e-12): a region that fits the lattice exactly would otherwise fail by one ulp
// of the division; centres are then clamped into the region (and nudged by an ulp where x + r would round
// above the region's edge) by at most that round-off, far inside the overlap check's tolerance.
#include "setup/setup_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "setup/placement_grid.hpp"

namespace ede::setup_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kRowFactorHex = 0.86602540378443864676;  // sqrt(3) / 2
constexpr double kFitTolerance = 1e-12;

const char* kind_name(LatticeKind k) { return k == LatticeKind::Hexagonal ? "hexagonal" : "square"; }
double row_factor(LatticeKind k) { return k == LatticeKind::Hexagonal ? kRowFactorHex : 1.0; }

// The layout: spacing a along rows, row spacing a * row_factor (block) or given spacings (tiling).
struct Layout {
  std::int64_t nx = 1, ny = 1;
  double ax = kInf, ay = kInf;  // site spacing along a row, spacing between rows
  bool shift_odd_rows = false;
  double nearest = 0;  // nearest-neighbour distance, periodic images included for a tiling
};

// The largest spacing with which nx sites per row and ceil(count / nx) rows fit in w x h (centres inside
// [r, w - r]); infinite when a single site.
double block_spacing(LatticeKind kind, std::int64_t nx, std::int64_t ny, double w, double h, double r) {
  const bool shift = kind == LatticeKind::Hexagonal && ny > 1;
  const double span_x = double(nx - 1) + (shift ? 0.5 : 0.0);
  const double span_y = double(ny - 1) * row_factor(kind);
  const double ax = span_x > 0 ? (w - 2 * r) / span_x : kInf;
  const double ay = span_y > 0 ? (h - 2 * r) / span_y : kInf;
  return std::min(ax, ay);
}

Layout best_block(const LatticePlacement& where, double r, std::int64_t count) {
  Layout best;
  double best_a = -kInf;
  const double w = where.region.width(), h = where.region.height();
  for (std::int64_t nx = 1; nx <= count; ++nx) {
    const std::int64_t ny = (count + nx - 1) / nx;
    if (nx > 1 && (count + nx - 2) / (nx - 1) == ny) continue;  // same rows, fewer sites per row is wider
    const double a = block_spacing(where.kind, nx, ny, w, h, r);
    if (a > best_a) {
      best_a = a;
      best.nx = nx;
      best.ny = ny;
    }
  }
  best.ax = best_a;
  best.ay = best_a * row_factor(where.kind);
  best.shift_odd_rows = where.kind == LatticeKind::Hexagonal && best.ny > 1;
  best.nearest = best_a;
  return best;
}

// The nearest-neighbour distance of a tiling with spacings ax, ay (images included): along a row, to the
// next row (shifted by ax/2 if hexagonal), and for hexagonal to the row after, straight above.
double tiling_nearest(LatticeKind kind, double ax, double ay) {
  if (kind == LatticeKind::Square) return std::min(ax, ay);
  return std::min({ax, std::sqrt(0.25 * ax * ax + ay * ay), 2 * ay});
}

// The best tiling of the whole periodic box with exactly `count` sites; nearest = 0 if there is none.
Layout best_tiling(const LatticePlacement& where, std::int64_t count) {
  Layout best;
  for (std::int64_t ny = 1; ny <= count; ++ny) {
    if (count % ny != 0 || (where.kind == LatticeKind::Hexagonal && ny % 2 != 0)) continue;
    const std::int64_t nx = count / ny;
    const double ax = where.lx / double(nx), ay = where.ly / double(ny);
    const double nearest = tiling_nearest(where.kind, ax, ay);
    if (nearest > best.nearest) best = {nx, ny, ax, ay, where.kind == LatticeKind::Hexagonal, nearest};
  }
  return best;
}

// The block's nearest-neighbour distance in a periodic box: a, or the seam to the images if narrower.
double block_nearest_periodic(const Layout& b, const LatticePlacement& where, std::int64_t count) {
  const double units_x = double(std::min(b.nx, count) - 1) + (b.shift_odd_rows ? 0.5 : 0.0);
  const double ext_x = units_x > 0 ? units_x * b.ax : 0.0;
  const double ext_y = b.ny > 1 ? double(b.ny - 1) * b.ay : 0.0;
  return std::min({b.nearest, where.lx - ext_x, where.ly - ext_y});
}

// How many disks fit in the block layout with spacing exactly 2r: for the error message.
std::int64_t max_fit(LatticeKind kind, double w, double h, double r) {
  if (w < 2 * r || h < 2 * r) return 0;
  const double d = 2 * r;
  const std::int64_t rows = std::int64_t(std::floor((h - d) / (d * row_factor(kind)))) + 1;
  const std::int64_t single_row = std::int64_t(std::floor((w - d) / d)) + 1;
  if (kind == LatticeKind::Square || rows == 1) return rows * single_row;
  const double shifted_span = (w - d) / d - 0.5;
  const std::int64_t shifted_row = shifted_span < 0 ? 0 : std::int64_t(std::floor(shifted_span)) + 1;
  return std::max(single_row, rows * shifted_row);
}

Error does_not_fit(const LatticePlacement& where, double r, std::int64_t count) {
  const Region& g = where.region;
  return Error{std::to_string(count) + " disks of radius " + number_text(r) + " do not fit on a " +
               kind_name(where.kind) + " lattice in region [" + number_text(g.x0) + ", " + number_text(g.x1) +
               "] x [" + number_text(g.y0) + ", " + number_text(g.y1) + "]: at most " +
               std::to_string(max_fit(where.kind, g.width(), g.height(), r)) + " fit"};
}

// Sites row by row, relative to the first site; odd rows shifted by half a spacing.
void lay_out(const Layout& b, std::int64_t count, std::vector<double>& x, std::vector<double>& y) {
  x.resize(std::size_t(count));
  y.resize(std::size_t(count));
  for (std::int64_t k = 0; k < count; ++k) {
    const std::int64_t row = k / b.nx, col = k % b.nx;
    const bool shifted = b.shift_odd_rows && row % 2 == 1;
    const double units_x = double(col) + (shifted ? 0.5 : 0.0);
    x[std::size_t(k)] = units_x > 0 ? units_x * b.ax : 0.0;  // the spacing is infinite along a single site
    y[std::size_t(k)] = row > 0 ? double(row) * b.ay : 0.0;
  }
}

// c clamped to [a0 + r, a1 - r], then nudged by ulps until c - r >= a0 and c + r <= a1 also hold in
// floating point (a1 - r + r can round above a1). Bounded: a region exactly 2r wide may allow only one.
double inside(double c, double a0, double a1, double r) {
  c = std::clamp(c, a0 + r, a1 - r);
  for (int k = 0; k < 4 && c + r > a1; ++k) c = std::nextafter(c, -kInf);
  for (int k = 0; k < 4 && c - r < a0; ++k) c = std::nextafter(c, kInf);
  return c;
}

// Moves the sites so their bounding box is centred in [a0, a1], and keeps each disk inside it.
void centre(std::vector<double>& v, double a0, double a1, double r) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  const double offset = 0.5 * (a0 + a1) - 0.5 * (*lo + *hi);
  for (double& c : v) c = inside(c + offset, a0, a1, r);
}

// A tiling starts a quarter spacing in, so the shifted rows end at (nx - 1/4) * ax < lx: centres in [0, L).
void place_tiling(const Layout& t, std::int64_t count, std::vector<double>& x, std::vector<double>& y) {
  lay_out(t, count, x, y);
  for (double& c : x) c += 0.25 * t.ax;
  for (double& c : y) c += 0.5 * t.ay;
}

}  // namespace

Status place_lattice(const LatticePlacement& where, double r, std::int64_t count, std::vector<double>& x,
                     std::vector<double>& y) {
  const Region& g = where.region;
  if (count <= 0) return Ok{};
  const bool whole_box = g.x0 <= 0 && g.x1 >= where.lx && g.y0 <= 0 && g.y1 >= where.ly;
  const Layout block = best_block(where, r, count);
  const bool block_fits =
      g.width() >= 2 * r && g.height() >= 2 * r && block.nearest >= 2 * r * (1 - kFitTolerance);
  if (where.periodic_box && whole_box) {
    const Layout tiling = best_tiling(where, count);
    const double block_nearest = block_fits ? block_nearest_periodic(block, where, count) : 0;
    if (tiling.nearest >= 2 * r * (1 - kFitTolerance) && tiling.nearest >= block_nearest) {
      place_tiling(tiling, count, x, y);
      return Ok{};
    }
  }
  if (!block_fits) return does_not_fit(where, r, count);
  lay_out(block, count, x, y);
  centre(x, g.x0, g.x1, r);
  centre(y, g.y0, g.y1, r);
  return Ok{};
}

}  // namespace ede::setup_detail
