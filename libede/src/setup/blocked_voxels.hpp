// BlockedVoxels: a bitmap over the box of voxels that lie wholly inside some placed disk's exclusion zone,
// a cheap first test for random sequential addition near jamming, where most candidates are rejected.
//
// A voxel is marked when every point of it (widened by a margin) is closer than r_j + r_floor to a placed
// disk j, r_floor being the smallest radius any later candidate can have. A candidate of radius r >= r_floor
// whose centre falls in a marked voxel therefore overlaps disk j in PlacementGrid::overlaps too: the mark is
// only a faster way to the same "reject", so the rng draws and every accept/reject decision (and the placed
// positions) are exactly those of the grid test alone. The margins (1e-6 of the exclusion radius and of the
// voxel side) dwarf the round-off of the grid test's minimum-image differences and of the voxel index, so a
// mark is never wrong; they only leave a few boundary voxels unmarked, which then fall through to the grid.
// Voxels are an eighth of the exclusion radius wide (at most 128 per expected disk: 16 bytes per disk
// while placing, freed with the grid; 12.6 B/disk for equal disks at phi = 0.5).
// Sampling only from free voxels cannot keep the default's positions (every candidate must be drawn and judged
// to repeat its rng draws); it is offered as a scene's choice instead (free_voxel_list.hpp).
// Rejected: a byte per voxel (8x the memory, more cache misses at 10^6 disks).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ede::setup_detail {

class BlockedVoxels {
 public:
  BlockedVoxels() = default;

  // Voxels over [0, lx] x [0, ly] for candidates of radius >= r_floor among disks of typical radius r_typical.
  // r_floor <= 0 (or a degenerate box) leaves the map disabled: blocked() is then always false.
  BlockedVoxels(double lx, double ly, bool periodic, double r_floor, double r_typical, std::size_t expected_disks)
      : lx_(lx), ly_(ly), periodic_(periodic), r_floor_(r_floor) {
    if (!(r_floor > 0) || !(r_typical > 0) || !(lx > 0) || !(ly > 0) || !std::isfinite(lx * ly)) return;
    const double cap = 128.0 * double(std::max<std::size_t>(expected_disks, 1)) + 4096;
    double side = 0.125 * (r_floor + r_typical);
    if (lx / side * (ly / side) > cap) side = std::sqrt(lx * ly / cap);
    const double nx = std::floor(lx / side), ny = std::floor(ly / side);
    if (!(nx >= 3 && ny >= 3 && nx < 2e9 && ny < 2e9)) return;  // too coarse to help, or absurd
    nx_ = std::int64_t(nx);
    ny_ = std::int64_t(ny);
    wx_ = lx / nx;
    wy_ = ly / ny;
    inv_wx_ = nx / lx;
    inv_wy_ = ny / ly;
    bits_.assign(std::size_t((nx_ * ny_ + 63) / 64), 0);
  }

  bool enabled() const { return !bits_.empty(); }

  // Whether every candidate of radius >= r_floor centred at (x, y) overlaps a marked disk.
  bool blocked(double x, double y) const {
    if (bits_.empty()) return false;
    const std::int64_t ix = index(x, inv_wx_, nx_), iy = index(y, inv_wy_, ny_);
    if ((ix | iy) < 0) return false;
    return marked(code(ix, iy));
  }

  // Marks the voxels wholly inside the exclusion zone of a disk at (x, y) of radius r.
  void mark(double x, double y, double r) {
    if (bits_.empty() || !(r > 0)) return;
    // A disk outside the box (a bad explicit position, refused later) marks nothing: in a periodic box the
    // grid's minimum image of it is then not the image marked here.
    if (!(x >= 0 && x <= lx_ && y >= 0 && y <= ly_)) return;
    const double reach = (r + r_floor_) * (1 - kMargin);
    const double dx_margin = kMargin * wx_, dy_margin = kMargin * wy_;
    const std::int64_t iy0 = std::int64_t(std::floor((y - reach) * inv_wy_));
    const std::int64_t iy1 = std::int64_t(std::floor((y + reach) * inv_wy_));
    for (std::int64_t iy = iy0; iy <= iy1; ++iy) {
      // The voxel row's farthest y from the centre, widened by the margin.
      const double lo = double(iy) * wy_ - dy_margin, hi = double(iy + 1) * wy_ + dy_margin;
      const double fy = std::max(std::abs(y - lo), std::abs(hi - y));
      if (fy >= reach) continue;
      const double half = std::sqrt(reach * reach - fy * fy);  // voxels wholly within [x - half, x + half]
      const std::int64_t ix0 = std::int64_t(std::ceil((x - half + dx_margin) * inv_wx_));
      const std::int64_t ix1 = std::int64_t(std::floor((x + half - dx_margin) * inv_wx_)) - 1;
      if (ix0 <= ix1) set_run(iy, ix0, ix1);
    }
  }

  std::size_t bytes() const { return bits_.capacity() * sizeof(std::uint64_t); }

  // The voxel grid and its marks, read by FreeVoxelList (free_voxel_list.hpp). Voxel (ix, iy) covers
  // [ix * wx, (ix + 1) * wx) x [iy * wy, (iy + 1) * wy); its code iy * nx + ix is its bit's index in the map,
  // so word w holds codes 64 w to 64 w + 63.
  std::int64_t voxels_x() const { return nx_; }
  std::int64_t voxels_y() const { return ny_; }
  double inverse_voxel_width() const { return inv_wx_; }
  double inverse_voxel_height() const { return inv_wy_; }
  std::size_t words() const { return bits_.size(); }
  std::uint64_t word(std::size_t w) const { return bits_[w]; }
  std::int64_t code(std::int64_t ix, std::int64_t iy) const { return iy * nx_ + ix; }
  void voxel_of(std::int64_t code, std::int64_t& ix, std::int64_t& iy) const {
    ix = code % nx_;
    iy = code / nx_;
  }
  bool marked(std::int64_t code) const { return (bits_[std::size_t(code >> 6)] >> (code & 63)) & 1; }
  // A point uniform in voxel (ix, iy) from two uniform01 values.
  double voxel_x(std::int64_t ix, double u) const { return (double(ix) + u) * wx_; }
  double voxel_y(std::int64_t iy, double u) const { return (double(iy) + u) * wy_; }

 private:
  static constexpr double kMargin = 1e-6;

  // The voxel of a coordinate, or -1 outside [0, n) voxels (also NaN): such a point is never blocked.
  static std::int64_t index(double v, double inv_w, std::int64_t n) {
    const double c = v * inv_w;
    return c >= 0 && c < double(n) ? std::int64_t(c) : -1;
  }

  // Sets voxels ix0..ix1 of row iy (indices may lie outside the box: wrapped in a periodic box, else cut).
  void set_run(std::int64_t iy, std::int64_t ix0, std::int64_t ix1) {
    if (periodic_) {
      iy = wrapped(iy, ny_);
      if (ix1 - ix0 + 1 >= nx_) return set_bits(iy * nx_, iy * nx_ + nx_ - 1);  // the whole row
      ix0 = wrapped(ix0, nx_);
      ix1 = wrapped(ix1, nx_);
      if (ix0 > ix1) {  // the run crosses the box's edge
        set_bits(iy * nx_ + ix0, iy * nx_ + nx_ - 1);
        ix0 = 0;
      }
    } else {
      if (iy < 0 || iy >= ny_) return;
      ix0 = std::max<std::int64_t>(ix0, 0);
      ix1 = std::min<std::int64_t>(ix1, nx_ - 1);
      if (ix0 > ix1) return;
    }
    set_bits(iy * nx_ + ix0, iy * nx_ + ix1);
  }

  static std::int64_t wrapped(std::int64_t i, std::int64_t n) {
    if (i < 0) i += n;
    if (i >= n) i -= n;
    return i >= 0 && i < n ? i : ((i % n) + n) % n;  // far outside only in a box a few voxels wide
  }

  // Sets bits a..b (inclusive) of the map, a word at a time.
  void set_bits(std::int64_t a, std::int64_t b) {
    std::size_t wa = std::size_t(a >> 6), wb = std::size_t(b >> 6);
    const std::uint64_t first = ~std::uint64_t(0) << (a & 63), last = ~std::uint64_t(0) >> (63 - (b & 63));
    if (wa == wb) {
      bits_[wa] |= first & last;
      return;
    }
    bits_[wa] |= first;
    for (std::size_t w = wa + 1; w < wb; ++w) bits_[w] = ~std::uint64_t(0);
    bits_[wb] |= last;
  }

  double lx_ = 0, ly_ = 0;
  bool periodic_ = false;
  double r_floor_ = 0;
  std::int64_t nx_ = 0, ny_ = 0;
  double wx_ = 0, wy_ = 0, inv_wx_ = 0, inv_wy_ = 0;
  std::vector<std::uint64_t> bits_;
};

}  // namespace ede::setup_detail
