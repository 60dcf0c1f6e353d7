// bed_body: the bed disks connected to the bottom of the bed, so that ejecta do not count as surface.
//
// Linked pairs (rim gap <= link_gap) are found with a uniform grid of cells at least as wide as the longest
// link, so each disk is compared only with the disks of its own and the 8 neighbouring cells, and merged
// with a union-find (path halving, the lower index as root: the result does not depend on visiting order).
// Rejected: "the largest cluster", which drops half the bed when a deep crater cuts it in two; and a
// height cut-off, which needs a guess of how high the rim may rise.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "analysis/crater.hpp"

namespace ede {

namespace {

// Cells per side at most: a sparse bed in a huge box must not allocate a huge grid.
constexpr std::size_t kMaxCellsPerSide = 2048;

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) {
    for (std::size_t i = 0; i < n; ++i) parent[i] = std::uint32_t(i);
  }
  std::uint32_t find(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

struct Grid {
  std::size_t nx = 1, ny = 1;
  double cx = 1, cy = 1;  // cell sizes
  std::vector<std::vector<std::uint32_t>> cells;

  Grid(double lx, double ly, double cell) {
    nx = std::clamp<std::size_t>(std::size_t(lx / cell), 1, kMaxCellsPerSide);
    ny = std::clamp<std::size_t>(std::size_t(ly / cell), 1, kMaxCellsPerSide);
    cx = lx / double(nx), cy = ly / double(ny);
    cells.resize(nx * ny);
  }
  static std::size_t index(double v, double size, std::size_t n) {
    const double k = std::floor(v / size);
    return k < 0 || !(k == k) ? 0 : std::min(std::size_t(k), n - 1);
  }
  std::size_t ix(double x) const { return index(x, cx, nx); }
  std::size_t iy(double y) const { return index(y, cy, ny); }
};

double minimum_image(double d, double length) { return d - length * std::round(d / length); }

}  // namespace

std::vector<bool> bed_body(const DiskPositions& s, const std::vector<bool>& is_bed, const CraterBox& box,
                           double link_gap) {
  const std::size_t n = std::min(s.size(), is_bed.size());
  double r_max = 0, floor = INFINITY;
  for (std::size_t i = 0; i < n; ++i)
    if (is_bed[i]) r_max = std::max(r_max, s.r[i]), floor = std::min(floor, s.y[i] - s.r[i]);
  std::vector<bool> body(s.size(), false);
  if (!(r_max > 0)) return body;

  Grid grid(box.lx, box.ly, 2 * r_max + link_gap);
  for (std::size_t i = 0; i < n; ++i)
    if (is_bed[i]) grid.cells[grid.iy(s.y[i]) * grid.nx + grid.ix(s.x[i])].push_back(std::uint32_t(i));

  UnionFind uf(n);
  const auto link = [&](std::uint32_t i, std::uint32_t j) {
    double dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
    if (box.periodic) dx = minimum_image(dx, box.lx), dy = minimum_image(dy, box.ly);
    const double reach = s.r[i] + s.r[j] + link_gap;
    if (dx * dx + dy * dy <= reach * reach) uf.unite(i, j);
  };
  const auto wrap = [&](long k, std::size_t m, bool& ok) -> std::size_t {
    ok = true;
    if (k >= 0 && k < long(m)) return std::size_t(k);
    if (!box.periodic) return ok = false, 0;
    return std::size_t((k % long(m) + long(m)) % long(m));
  };
  for (std::size_t cy = 0; cy < grid.ny; ++cy)
    for (std::size_t cx = 0; cx < grid.nx; ++cx)
      for (const std::uint32_t i : grid.cells[cy * grid.nx + cx])
        for (long dy = -1; dy <= 1; ++dy)
          for (long dx = -1; dx <= 1; ++dx) {
            bool okx = false, oky = false;
            const std::size_t ox = wrap(long(cx) + dx, grid.nx, okx), oy = wrap(long(cy) + dy, grid.ny, oky);
            if (!okx || !oky) continue;
            for (const std::uint32_t j : grid.cells[oy * grid.nx + ox])
              if (j > i) link(i, j);
          }

  std::vector<bool> root_on_floor(n, false);
  for (std::size_t i = 0; i < n; ++i)
    if (is_bed[i] && s.y[i] - s.r[i] <= floor + link_gap) root_on_floor[uf.find(std::uint32_t(i))] = true;
  for (std::size_t i = 0; i < n; ++i) body[i] = is_bed[i] && root_on_floor[uf.find(std::uint32_t(i))];
  return body;
}

}  // namespace ede
