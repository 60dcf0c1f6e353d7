// step_potential_energy: see step_potential.hpp.
#include "analysis/step_potential.hpp"

#include <algorithm>
#include <cmath>

namespace ede {

namespace {

// The steps of every pair of species as (radius, energy) lists, the default first and named pairs over it
// (as the engine's step table reads them).
std::vector<std::vector<PairSteps>> steps_by_pair(const std::vector<PairSteps>& steps,
                                                  const std::vector<std::string>& names) {
  const std::size_t n = std::max<std::size_t>(names.size(), 1);
  std::vector<std::vector<PairSteps>> table(n * n);
  const auto index_of = [&](const std::string& s) {
    return std::size_t(std::find(names.begin(), names.end(), s) - names.begin());
  };
  for (const PairSteps& st : steps)
    if (st.a.empty())
      for (auto& entry : table) entry = {st};
  for (const PairSteps& st : steps)
    if (!st.a.empty() && index_of(st.a) < n && index_of(st.b) < n)
      table[index_of(st.a) * n + index_of(st.b)] = table[index_of(st.b) * n + index_of(st.a)] = {st};
  return table;
}

}  // namespace

double step_potential_energy(const std::vector<PairSteps>& steps, const StepPositions& at) {
  if (steps.empty() || at.x.empty()) return 0;
  double reach = 0;
  for (const PairSteps& st : steps) reach = std::max(reach, st.radius.back());
  const auto table = steps_by_pair(steps, at.names);
  const std::size_t ns = std::max<std::size_t>(at.names.size(), 1);
  long nx = std::max(1L, long(at.lx / reach)), ny = std::max(1L, long(at.ly / reach));
  // A periodic box under three cells a side would visit a cell twice: one cell then, and every pair in it.
  const long span = !at.periodic || (nx >= 3 && ny >= 3) ? 1 : 0;
  if (span == 0) nx = ny = 1;
  std::vector<std::vector<std::size_t>> cells(std::size_t(nx * ny));
  const auto cell = [&](double v, double l, long n) { return std::clamp(long(v / l * double(n)), 0L, n - 1); };
  for (std::size_t i = 0; i < at.x.size(); ++i)
    cells[std::size_t(cell(at.y[i], at.ly, ny) * nx + cell(at.x[i], at.lx, nx))].push_back(i);
  double u = 0;
  for (std::size_t i = 0; i < at.x.size(); ++i) {
    const long cx = cell(at.x[i], at.lx, nx), cy = cell(at.y[i], at.ly, ny);
    for (long dy = -span; dy <= span; ++dy)
      for (long dx = -span; dx <= span; ++dx) {
        long kx = cx + dx, ky = cy + dy;
        if (at.periodic) kx = (kx + nx) % nx, ky = (ky + ny) % ny;
        if (kx < 0 || ky < 0 || kx >= nx || ky >= ny) continue;
        for (const std::size_t j : cells[std::size_t(ky * nx + kx)]) {
          if (j <= i) continue;
          double ddx = at.x[j] - at.x[i], ddy = at.y[j] - at.y[i];
          if (at.periodic) ddx -= at.lx * std::nearbyint(ddx / at.lx), ddy -= at.ly * std::nearbyint(ddy / at.ly);
          const double d = std::sqrt(ddx * ddx + ddy * ddy);
          const std::size_t a = i < at.species.size() ? std::size_t(at.species[i]) : 0;
          const std::size_t b = j < at.species.size() ? std::size_t(at.species[j]) : 0;
          for (const PairSteps& st : table[std::min(a, ns - 1) * ns + std::min(b, ns - 1)])
            for (std::size_t k = 0; k < st.radius.size(); ++k)
              if (d < st.radius[k]) u += st.energy[k];
        }
      }
  }
  return u;
}

}  // namespace ede
