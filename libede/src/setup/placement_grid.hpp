// PlacementGrid: a uniform grid over the box for "does this disk overlap any disk placed so far?".
//
// Used by random placement (one query per candidate, one insert per accepted disk) and by
// check_initial_state (one query per disk). Cells are at least one largest diameter wide, so a disk can
// only overlap disks in its own and the 8 neighbouring cells (wrapped in a periodic box); the own cell is
// scanned first, where a rejected candidate usually finds its obstacle. Cells are about one mean spacing
// wide (most hold zero or one disk). Storage: a head per cell and an intrusive singly linked list through a
// node array holding each disk's x, y and r, so a query reads the nodes and nothing else. Disks are never
// removed. Random placement also switches on a bitmap of wholly blocked voxels (blocked_voxels.hpp): a
// candidate in a marked voxel is rejected without touching the cells, with the same answer.
// Rejected: fixed-capacity cells (a polydisperse species overflows them), storing each cell's first disk
// inline and prefetching the cells of upcoming candidates (both measured: no gain beyond noise at 10^6
// disks) and a k-d tree (rebalanced as disks arrive, and slower per query than 9 cells).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "ede/number_text.hpp"
#include "setup/blocked_voxels.hpp"

namespace ede::setup_detail {

class PlacementGrid {
 public:
  // Cells of side >= min_cell over [0, lx] x [0, ly], and about `expected_disks` cells or fewer (cells much
  // smaller than the mean spacing only cost memory).
  PlacementGrid(double lx, double ly, bool periodic, double min_cell, std::size_t expected_disks)
      : lx_(lx), ly_(ly), half_lx_(0.5 * lx), half_ly_(0.5 * ly), periodic_(periodic) {
    const double mean_spacing = std::sqrt(lx * ly / double(std::max<std::size_t>(expected_disks, 1)));
    const double side = std::max(min_cell * (1 + 1e-9), mean_spacing);  // margin: round-off in cell_of
    nx_ = cells_along(lx, side);
    ny_ = cells_along(ly, side);
    // A very elongated box clamps one side to a single cell while the other grows without bound (a box
    // 1 x 10^16 asked for 10^9 cells): cap the total; cells only get wider, which is always correct.
    const std::size_t cap = 4 * std::max<std::size_t>(expected_disks, 1) + 16;
    ny_ = std::int32_t(std::min<std::size_t>(std::size_t(ny_), std::max<std::size_t>(1, cap / std::size_t(nx_))));
    nx_ = std::int32_t(std::min<std::size_t>(std::size_t(nx_), std::max<std::size_t>(1, cap / std::size_t(ny_))));
    inv_wx_ = double(nx_) / lx;
    inv_wy_ = double(ny_) / ly;
    head_.assign(std::size_t(nx_) * std::size_t(ny_), kNone);
    nodes_.reserve(expected_disks);
  }

  // Disks are numbered 0, 1, ... in the order inserted; any_near reports them by that number.
  std::size_t size() const { return nodes_.size(); }

  // Switches on the blocked-voxel bitmap for queries of radius >= r_floor (the disks inserted so far and all
  // later ones are marked in it). overlaps() gives the same answers with or without it.
  void enable_blocked_voxels(double r_floor, double r_typical) {
    blocked_ = BlockedVoxels(lx_, ly_, periodic_, r_floor, r_typical, nodes_.capacity());
    r_floor_ = r_floor;
    for (const Node& n : nodes_) blocked_.mark(n.x, n.y, n.r);
  }
  const BlockedVoxels& blocked_voxels() const { return blocked_; }

  void insert(double x, double y, double r) {
    const std::size_t c = cell_index(x, y);
    nodes_.push_back({x, y, r, head_[c]});
    head_[c] = std::int32_t(nodes_.size() - 1);
    blocked_.mark(x, y, r);
  }

  // Calls f(j, dx, dy, rj) for every inserted disk j in the 3 x 3 cells around (x, y), with (dx, dy) the
  // minimum-image vector from (x, y) to disk j. Stops early when f returns true; returns whether it did.
  template <class F>
  bool any_near(double x, double y, F&& f) const {
    std::int32_t xs[3], ys[3];
    const int nxs = neighbour_cells(cell_of(x, inv_wx_, nx_), nx_, xs);
    const int nys = neighbour_cells(cell_of(y, inv_wy_, ny_), ny_, ys);
    for (int b = 0; b < nys; ++b) {
      const std::size_t row = std::size_t(ys[b]) * std::size_t(nx_);
      for (int a = 0; a < nxs; ++a) {
        for (std::int32_t j = head_[row + std::size_t(xs[a])]; j != kNone; j = nodes_[std::size_t(j)].next) {
          const Node& n = nodes_[std::size_t(j)];
          if (f(j, wrap(n.x - x, lx_, half_lx_), wrap(n.y - y, ly_, half_ly_), n.r)) return true;
        }
      }
    }
    return false;
  }

  // Whether a disk of radius r at (x, y) would overlap an inserted disk: distance < r + rj (touching is fine).
  bool overlaps(double x, double y, double r) const {
    if (r >= r_floor_ && blocked_.blocked(x, y)) return true;  // a shortcut to the same answer
    return any_near(x, y, [r](std::int32_t, double dx, double dy, double rj) {
      const double s = r + rj;
      return dx * dx + dy * dy < s * s;
    });
  }

 private:
  static constexpr std::int32_t kNone = -1;
  struct Node {
    double x, y, r;
    std::int32_t next;  // the next disk in the same cell, or kNone
  };

  static std::int32_t cells_along(double length, double side) {
    const double n = std::floor(length / side);
    return n < 1 ? 1 : n > double(1 << 30) ? (1 << 30) : std::int32_t(n);
  }

  // Clamped, so round-off at the far edge and positions outside the box (rejected later) stay in range.
  static std::int32_t cell_of(double v, double inv_w, std::int32_t n) {
    const double c = v * inv_w;
    if (!(c >= 0)) return 0;  // also NaN
    return c >= double(n - 1) ? n - 1 : std::int32_t(c);
  }

  std::size_t cell_index(double x, double y) const {
    return std::size_t(cell_of(y, inv_wy_, ny_)) * std::size_t(nx_) + std::size_t(cell_of(x, inv_wx_, nx_));
  }

  // The own cell first, then its neighbours; each distinct cell once (a periodic row of 1 or 2 cells).
  int neighbour_cells(std::int32_t c, std::int32_t n, std::int32_t* out) const {
    if (periodic_ && n < 3) {
      for (std::int32_t k = 0; k < n; ++k) out[k] = (c + k) % n;
      return int(n);
    }
    int m = 0;
    out[m++] = c;
    if (c > 0 || periodic_) out[m++] = c > 0 ? c - 1 : n - 1;
    if (c + 1 < n || periodic_) out[m++] = c + 1 < n ? c + 1 : 0;
    return m;
  }

  double wrap(double d, double length, double half) const {
    if (!periodic_) return d;
    if (d > half) return d - length;
    if (d < -half) return d + length;
    return d;
  }

  double lx_, ly_, half_lx_, half_ly_;
  bool periodic_;
  std::int32_t nx_ = 1, ny_ = 1;
  double inv_wx_ = 1, inv_wy_ = 1;
  std::vector<std::int32_t> head_;  // per cell: the last disk inserted there, or kNone
  std::vector<Node> nodes_;         // per disk, in insertion order
  BlockedVoxels blocked_;           // disabled unless enable_blocked_voxels was called
  double r_floor_ = 0;
};

// A number for an error message: by default enough digits to find the value in a file.
inline std::string number_text(double v, int significant_digits = 9) { return general_text(v, significant_digits); }

}  // namespace ede::setup_detail
