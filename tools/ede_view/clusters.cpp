// bond_radii, find_clusters; see clusters.hpp.
#include "clusters.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ede::view {
namespace {

// The outermost well of one species pair's steps: the largest radius whose step has a negative energy.
double outermost_well(const PairSteps& st) {
  double r = 0;
  for (std::size_t k = 0; k < st.radius.size() && k < st.energy.size(); ++k)
    if (st.energy[k] < 0) r = std::max(r, st.radius[k]);
  return r;
}

// Union-find over disk ids, the smaller id the root (path halving).
struct Forest {
  std::vector<std::uint32_t> parent;
  explicit Forest(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t root(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = root(a), b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Cells at least `reach` wide over an lx by ly box, at most about 4 per disk (a sparse box in few cells).
struct Grid {
  long nx = 1, ny = 1;
  Grid(double lx, double ly, double reach, std::size_t disks) {
    nx = std::max(1L, long(std::min(lx / reach, 1e6)));
    ny = std::max(1L, long(std::min(ly / reach, 1e6)));
    const double limit = std::max(16.0, 4.0 * double(disks));
    while (double(nx) * double(ny) > limit) nx = std::max(1L, nx / 2), ny = std::max(1L, ny / 2);
  }
  long index(double v, double l, long n) const { return std::clamp(long(std::floor(v / l * double(n))), 0L, n - 1); }
};

}  // namespace

BondRadii bond_radii(const std::vector<PairSteps>& steps, const std::vector<std::string>& names) {
  BondRadii b;
  b.species = std::max<std::size_t>(names.size(), 1);
  b.radius.assign(b.species * b.species, 0.0);
  const auto index_of = [&](const std::string& name) {
    return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
  };
  for (const PairSteps& st : steps)
    if (st.a.empty()) std::fill(b.radius.begin(), b.radius.end(), outermost_well(st));
  for (const PairSteps& st : steps) {
    const std::size_t i = index_of(st.a), j = index_of(st.b);
    if (st.a.empty() || i >= b.species || j >= b.species) continue;
    b.radius[i * b.species + j] = b.radius[j * b.species + i] = outermost_well(st);
  }
  b.largest = *std::max_element(b.radius.begin(), b.radius.end());
  return b;
}

std::string clusters_unavailable(const BondRadii& bonds) {
  if (bonds.largest > 0) return "";
  return "colouring by clusters needs a square well (a [[physics.steps]] entry with a negative energy): "
         "this scene has none, so no two disks are ever bonded";
}

Clusters find_clusters(const State& s, const BondRadii& bonds) {
  const std::size_t n = s.size();
  Clusters out;
  out.rank.assign(n, 0);
  if (n == 0 || !(bonds.largest > 0)) {
    out.alone = n;
    out.largest = n ? 1 : 0;
    return out;
  }
  const std::vector<double> x = s.x.to_doubles(), y = s.y.to_doubles();
  const bool periodic = s.boundary == BoundaryKind::Periodic;
  const Grid grid(s.lx, s.ly, bonds.largest, n);
  // Disks sorted by cell: cell k holds order[start[k] .. start[k + 1]).
  std::vector<long> cell(n);
  for (std::size_t i = 0; i < n; ++i) cell[i] = grid.index(y[i], s.ly, grid.ny) * grid.nx + grid.index(x[i], s.lx, grid.nx);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return cell[a] < cell[b]; });
  std::vector<std::size_t> start(std::size_t(grid.nx * grid.ny) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++start[std::size_t(cell[i]) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());

  const auto species = [&](std::size_t i) {
    return std::min<std::size_t>(i < s.species.size() ? std::size_t(std::max(s.species[i], 0)) : 0, bonds.species - 1);
  };
  Forest forest(n);
  std::vector<long> near;
  for (std::size_t i = 0; i < n; ++i) {
    const long cx = cell[i] % grid.nx, cy = cell[i] / grid.nx;
    near.clear();  // the neighbouring cells, each once (a periodic box of one or two cells a side wraps onto itself)
    for (long dy = -1; dy <= 1; ++dy)
      for (long dx = -1; dx <= 1; ++dx) {
        long kx = cx + dx, ky = cy + dy;
        if (periodic) kx = (kx + grid.nx) % grid.nx, ky = (ky + grid.ny) % grid.ny;
        if (kx >= 0 && ky >= 0 && kx < grid.nx && ky < grid.ny) near.push_back(ky * grid.nx + kx);
      }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (const long k : near)
      for (std::size_t m = start[std::size_t(k)]; m < start[std::size_t(k) + 1]; ++m) {
        const std::uint32_t j = order[m];
        if (j <= i) continue;
        const double bond = bonds.radius[species(i) * bonds.species + species(j)];
        double ddx = x[j] - x[i], ddy = y[j] - y[i];
        if (periodic) ddx -= s.lx * std::nearbyint(ddx / s.lx), ddy -= s.ly * std::nearbyint(ddy / s.ly);
        if (ddx * ddx + ddy * ddy < bond * bond) forest.join(std::uint32_t(i), j);
      }
  }

  // Sizes by root (the cluster's lowest id), then ranks: largest first, ties by the lowest id.
  std::vector<std::size_t> size(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) ++size[forest.root(i)];
  std::vector<std::uint32_t> roots;
  for (std::uint32_t i = 0; i < n; ++i)
    if (size[i] >= 2) roots.push_back(i);
  std::stable_sort(roots.begin(), roots.end(), [&](std::uint32_t a, std::uint32_t b) { return size[a] > size[b]; });
  std::vector<std::uint32_t> rank_of(n, 0);
  for (std::size_t r = 0; r < roots.size(); ++r) rank_of[roots[r]] = std::uint32_t(r + 1);
  for (std::uint32_t i = 0; i < n; ++i) out.rank[i] = rank_of[forest.root(i)];
  out.count = roots.size();
  out.largest = roots.empty() ? 1 : size[roots.front()];
  out.alone = std::size_t(std::count(out.rank.begin(), out.rank.end(), 0u));
  return out;
}

}  // namespace ede::view
