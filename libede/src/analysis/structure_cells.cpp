// The structure analyses' cell grid (structure_cells.hpp): a counting sort of the centres into cells, and
// the k nearest neighbours by rings of cells, stopping once the ring searched is farther than the k-th
// distance found. Rejected: a k-d tree (nanoflann): one more dependency for what a uniform grid of nearly
// uniform disks does as well.
#include "analysis/structure_cells.hpp"

#include <limits>
#include <utility>

namespace ede::structure {

Points points_of(const State& s, std::int32_t species) {
  Points p;
  p.lx = s.lx;
  p.ly = s.ly;
  p.periodic = s.boundary == BoundaryKind::Periodic;
  p.shift = s.shear_offset;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (species >= 0 && s.species[i] != species) continue;
    p.x.push_back(s.x[i]);
    p.y.push_back(s.y[i]);
    p.id.push_back(std::int32_t(i));
  }
  return p;
}

CellGrid::CellGrid(const Points& p, double cell) : p_(p) {
  const double max_cells = std::max(1.0, 4.0 * double(p.size()));  // no more cells than ~4 per point
  nx_ = int(std::clamp(std::floor(p.lx / cell), 1.0, std::sqrt(max_cells)));
  ny_ = int(std::clamp(std::floor(p.ly / cell), 1.0, std::sqrt(max_cells)));
  brute_ = p.periodic ? (nx_ < 3 || ny_ < 3) : (nx_ < 2 && ny_ < 2);
  wx_ = p.lx / nx_;
  wy_ = p.ly / ny_;
  start_.assign(std::size_t(nx_) * ny_ + 1, 0);
  std::vector<std::uint32_t> cell_of_point(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    int cx, cy;
    cell_of_point[i] = std::uint32_t(cell_of(p.x[i], p.y[i], cx, cy));
    ++start_[cell_of_point[i] + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  items_.resize(p.size());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < p.size(); ++i) items_[fill[cell_of_point[i]]++] = std::uint32_t(i);
}

std::size_t CellGrid::cell_of(double x, double y, int& cx, int& cy) const {
  cx = std::clamp(int(std::floor(x / wx_)), 0, nx_ - 1);
  cy = std::clamp(int(std::floor(y / wy_)), 0, ny_ - 1);
  return std::size_t(cy) * nx_ + cx;
}

std::vector<std::size_t> CellGrid::nearest(std::size_t i, std::size_t k) const {
  std::vector<std::pair<double, std::size_t>> found;  // (r2, point), over the rings searched so far
  const auto consider = [&](std::size_t j) {
    if (j == i) return;
    double dx, dy;
    p_.separation(i, j, dx, dy);
    found.emplace_back(dx * dx + dy * dy, j);
  };
  const auto take = [&] {
    const std::size_t m = std::min(k, found.size());
    std::partial_sort(found.begin(), found.begin() + m, found.end(), [&](const auto& a, const auto& b) {
      return a.first != b.first ? a.first < b.first : p_.id[a.second] < p_.id[b.second];
    });
    std::vector<std::size_t> out(m);
    for (std::size_t q = 0; q < m; ++q) out[q] = found[q].second;
    return out;
  };
  // The rings of cells do not follow a sheared box's sliding image (the row above the top is slid): every
  // point then, correct and O(N) per call; psi6 of a sheared log is refused for its cost (sheared_guard.hpp).
  if (brute_ || (p_.periodic && p_.shift != 0)) {
    for (std::size_t j = 0; j < p_.size(); ++j) consider(j);
    return take();
  }
  int cx, cy;
  cell_of(p_.x[i], p_.y[i], cx, cy);
  const int max_ring = std::max(nx_, ny_);
  for (int ring = 0; ring <= max_ring; ++ring) {
    for (int oy = -ring; oy <= ring; ++oy)
      for (int ox = -ring; ox <= ring; ++ox) {
        if (std::max(std::abs(ox), std::abs(oy)) != ring) continue;
        int x = cx + ox, y = cy + oy;
        if (p_.periodic) {
          // A ring wider than the grid would visit a cell twice: stop at half the grid each way.
          if (2 * std::abs(ox) > nx_ || 2 * std::abs(oy) > ny_) continue;
          if (2 * std::abs(ox) == nx_ && ox < 0) continue;
          if (2 * std::abs(oy) == ny_ && oy < 0) continue;
          x = (x % nx_ + nx_) % nx_;
          y = (y % ny_ + ny_) % ny_;
        } else if (x < 0 || x >= nx_ || y < 0 || y >= ny_) {
          continue;
        }
        const std::size_t c = std::size_t(y) * nx_ + x;
        for (std::uint32_t a = start_[c]; a < start_[c + 1]; ++a) consider(items_[a]);
      }
    // Every point not yet seen is at least ring * (narrower cell side) away.
    const double reach = ring * std::min(wx_, wy_);
    if (found.size() >= k) {
      std::nth_element(found.begin(), found.begin() + (k - 1), found.end());
      if (found[k - 1].first < reach * reach) return take();
    }
  }
  return take();
}

}  // namespace ede::structure
