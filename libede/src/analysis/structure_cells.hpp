// A cell grid over the disk centres of one State for the structure analyses: every pair within r_max once
// (g(r), g6(r)), and the k nearest neighbours of a disk (psi6). Positions in double, minimum image when
// periodic (through the sliding image across the top and bottom of a sheared box: for_pairs scans the
// whole slid row for the top row's cells, nearest falls back to every point). Cells are at least r_max wide, so a pair within r_max lies in the same or an adjacent cell;
// with fewer than 3 cells along a periodic side the grid would meet itself, so it falls back to every pair.
// Rejected: the engine's cell grid (engine/ is a room below but holds the run's hot state in the run's
// scalar type, and an analysis must not depend on the engine's layout).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ede/state.hpp"

namespace ede::structure {

struct Points {
  std::vector<double> x, y;
  std::vector<std::int32_t> id;  // disk ids, for ties
  double lx = 1, ly = 1;
  bool periodic = false;
  double shift = 0;  // Lees-Edwards: the image above is shifted by this in x (State::shear_offset)

  std::size_t size() const { return x.size(); }
  // The separation r_j - r_i (minimum image when periodic: across the top or bottom edge of a sheared box,
  // the sliding image's).
  void separation(std::size_t i, std::size_t j, double& dx, double& dy) const {
    dx = x[j] - x[i];
    dy = y[j] - y[i];
    if (periodic) {
      const double rows = std::nearbyint(dy / ly);  // +1: j's image below i's row is the nearer
      dy -= ly * rows;
      dx -= shift * rows;
      dx -= lx * std::nearbyint(dx / lx);
    }
  }
};

// Every disk of `s` (species < 0) or of one species.
Points points_of(const State& s, std::int32_t species = -1);

class CellGrid {
 public:
  CellGrid(const Points& p, double cell);
  // f(i, j, dx, dy, r2) for every unordered pair i != j with r2 = dx^2 + dy^2 < r_max^2 (r_max <= cell).
  template <class F>
  void for_pairs(double r_max, F&& f) const;
  // The k nearest neighbours of i, nearest first (fewer if there are fewer other points).
  std::vector<std::size_t> nearest(std::size_t i, std::size_t k) const;

 private:
  std::size_t cell_of(double x, double y, int& cx, int& cy) const;
  const Points& p_;
  int nx_ = 1, ny_ = 1;
  double wx_ = 1, wy_ = 1;
  bool brute_ = false;
  std::vector<std::uint32_t> start_, items_;  // counting-sort layout: items of cell c in [start_[c], start_[c+1])
};

template <class F>
void CellGrid::for_pairs(double r_max, F&& f) const {
  const double r2max = r_max * r_max;
  const auto visit = [&](std::size_t i, std::size_t j) {
    double dx, dy;
    p_.separation(i, j, dx, dy);
    const double r2 = dx * dx + dy * dy;
    if (r2 < r2max) f(i, j, dx, dy, r2);
  };
  if (brute_) {
    for (std::size_t i = 0; i < p_.size(); ++i)
      for (std::size_t j = i + 1; j < p_.size(); ++j) visit(i, j);
    return;
  }
  // Half the neighbour stencil: the cell itself (pairs a < b) and four of its eight neighbours. In a
  // sheared box the row above the top one is the bottom row slid by the shift, out of line with the
  // columns: a top-row cell then meets every cell of the bottom row once instead (nx cells for three; the
  // distance test keeps the near ones).
  static constexpr int kStencil[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  const auto visit_cells = [&](std::size_t c, std::size_t o) {
    for (std::uint32_t a = start_[c]; a < start_[c + 1]; ++a)
      for (std::uint32_t b = start_[o]; b < start_[o + 1]; ++b) visit(items_[a], items_[b]);
  };
  for (int cy = 0; cy < ny_; ++cy)
    for (int cx = 0; cx < nx_; ++cx) {
      const std::size_t c = std::size_t(cy) * nx_ + cx;
      for (std::uint32_t a = start_[c]; a < start_[c + 1]; ++a)
        for (std::uint32_t b = a + 1; b < start_[c + 1]; ++b) visit(items_[a], items_[b]);
      const bool slid = p_.periodic && p_.shift != 0 && cy == ny_ - 1;
      if (slid)
        for (int bx = 0; bx < nx_; ++bx) visit_cells(c, std::size_t(bx));
      for (const auto& d : kStencil) {
        if (slid && d[1] == 1) continue;
        int ox = cx + d[0], oy = cy + d[1];
        if (p_.periodic) {
          ox = (ox + nx_) % nx_;
          oy = (oy + ny_) % ny_;
        } else if (ox < 0 || ox >= nx_ || oy >= ny_) {
          continue;
        }
        visit_cells(c, std::size_t(oy) * nx_ + ox);
      }
    }
}

}  // namespace ede::structure
