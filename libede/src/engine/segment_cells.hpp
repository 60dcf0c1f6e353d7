// Which wall segments each grid cell must look at: a segment is listed in every cell whose rectangle
// lies within `reach` of it (reach: the largest radius of the disks in the cell lists, plus a margin), so
// a disk predicts against the segments of its own cell only, and the cost of an event does not depend on
// how many segments lie elsewhere. A disk's prediction holds until it crosses into another cell, and
// while its centre is in this cell it can touch only segments within its radius of the cell.
// Lists are built once per engine (segments never move), as one array of ids with an offset per cell.
// Rejected: testing every segment at every prediction (cost grows with the segments, the issue's "far
// away segments cost nothing") and registering a segment in its bounding box's cells (a long diagonal
// segment would fill a whole square of cells).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ede {

class SegmentCells {
 public:
  // ends: one (ax, ay, bx, by) per segment; the grid has nx x ny cells over [0, lx] x [0, ly].
  void build(const std::vector<std::array<double, 4>>& ends, std::int32_t nx, std::int32_t ny, double lx,
             double ly, double reach) {
    const double wx = lx / nx, wy = ly / ny;
    std::vector<std::vector<std::int32_t>> lists(std::size_t(nx) * std::size_t(ny));
    for (std::size_t k = 0; k < ends.size(); ++k) {
      const auto& e = ends[k];
      const auto clamp_cell = [](double v, double w, std::int32_t n) {
        return std::clamp(std::int32_t(std::floor(v / w)), std::int32_t(0), n - 1);
      };
      const std::int32_t x0 = clamp_cell(std::min(e[0], e[2]) - reach, wx, nx);
      const std::int32_t x1 = clamp_cell(std::max(e[0], e[2]) + reach, wx, nx);
      const std::int32_t y0 = clamp_cell(std::min(e[1], e[3]) - reach, wy, ny);
      const std::int32_t y1 = clamp_cell(std::max(e[1], e[3]) + reach, wy, ny);
      for (std::int32_t cy = y0; cy <= y1; ++cy)
        for (std::int32_t cx = x0; cx <= x1; ++cx)
          if (rect_distance(e, cx * wx, cy * wy, (cx + 1) * wx, (cy + 1) * wy) <= reach)
            lists[std::size_t(cy) * std::size_t(nx) + std::size_t(cx)].push_back(std::int32_t(k));
    }
    offsets_.assign(lists.size() + 1, 0);
    ids_.clear();
    for (std::size_t c = 0; c < lists.size(); ++c) {
      ids_.insert(ids_.end(), lists[c].begin(), lists[c].end());
      offsets_[c + 1] = std::uint32_t(ids_.size());
    }
  }

  const std::int32_t* begin(std::int32_t cell) const { return ids_.data() + offsets_[std::size_t(cell)]; }
  const std::int32_t* end(std::int32_t cell) const { return ids_.data() + offsets_[std::size_t(cell) + 1]; }
  std::size_t memory_bytes() const {
    return offsets_.capacity() * sizeof(std::uint32_t) + ids_.capacity() * sizeof(std::int32_t);
  }

  // Distance between segment e and the rectangle [x0, x1] x [y0, y1]: 0 if they meet, else the least of
  // the corners' distances to the segment and the end points' distances to the rectangle (for a segment
  // and a convex polygon apart, the nearest pair of points includes a vertex of one of them).
  static double rect_distance(const std::array<double, 4>& e, double x0, double y0, double x1, double y1) {
    if (clips(e, x0, y0, x1, y1)) return 0;
    double best = std::min(point_rect(e[0], e[1], x0, y0, x1, y1), point_rect(e[2], e[3], x0, y0, x1, y1));
    for (const auto& c : {std::array<double, 2>{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}})
      best = std::min(best, point_segment(e, c[0], c[1]));
    return best;
  }

 private:
  static double point_rect(double x, double y, double x0, double y0, double x1, double y1) {
    const double dx = std::max({x0 - x, 0.0, x - x1}), dy = std::max({y0 - y, 0.0, y - y1});
    return std::sqrt(dx * dx + dy * dy);
  }
  static double point_segment(const std::array<double, 4>& e, double x, double y) {
    const double dx = e[2] - e[0], dy = e[3] - e[1];
    const double len2 = dx * dx + dy * dy;
    const double f = len2 > 0 ? std::clamp(((x - e[0]) * dx + (y - e[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    const double px = e[0] + f * dx - x, py = e[1] + f * dy - y;
    return std::sqrt(px * px + py * py);
  }
  // Liang-Barsky: does the segment pass through the rectangle?
  static bool clips(const std::array<double, 4>& e, double x0, double y0, double x1, double y1) {
    double lo = 0, hi = 1;
    const double dx = e[2] - e[0], dy = e[3] - e[1];
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {e[0] - x0, x1 - e[0], e[1] - y0, y1 - e[1]};
    for (int k = 0; k < 4; ++k) {
      if (p[k] == 0) {
        if (q[k] < 0) return false;
        continue;
      }
      const double f = q[k] / p[k];
      if (p[k] < 0)
        lo = std::max(lo, f);
      else
        hi = std::min(hi, f);
      if (lo > hi) return false;
    }
    return true;
  }

  std::vector<std::uint32_t> offsets_{0};
  std::vector<std::int32_t> ids_;
};

}  // namespace ede
