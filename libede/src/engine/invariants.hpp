// Debug and test aids over an engine's state, O(N) with the grid: every pair of disks close enough to touch,
// the largest overlap, and the invariants the fuzzers check (no pair overlapping beyond a tolerance, no
// prediction in the past, no disk inside a segment).
#pragma once

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "engine/engine_state.hpp"
#include "engine/neighbours.hpp"

namespace ede {

// f(i, k, distance, contact distance) at now for every pair of disks close enough to touch (through any
// periodic image), each pair at least once: neighbouring cells, and big disks' reach.
template <class S, class F>
void for_each_near_pair(const S& s, F&& f) {
  using T = typename S::Scalar;
  const auto visit = [&](std::int32_t i, std::int32_t k, T sx, T sy) {
    const Position2<T> pi = s.pos_at(s.p.disk[i]), pk = s.pos_at(s.p.disk[k]);
    const double dx = double((pk.x + sx) - pi.x), dy = double((pk.y + sy) - pi.y);
    f(i, k, std::sqrt(dx * dx + dy * dy), double(s.p.disk[i].r + s.p.disk[k].r));
  };
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    if (s.is_big(s.p.disk[i])) continue;
    for_each_neighbour(s, std::int32_t(i), s.grid.cell_of(std::int32_t(i)), [&](std::int32_t k, T sx, T sy) {
      if (std::size_t(k) > i) visit(std::int32_t(i), k, sx, sy);
    });
  }
  for (const BigDisk& b : s.big) {
    for_each_in_reach(s, b, [&](std::int32_t k, T sx, T sy) { visit(b.id, k, sx, sy); });
    for (const BigDisk& other : s.big) {
      if (other.id <= b.id) continue;
      const int images = S::Effects::kPeriodic ? 1 : 0;
      for (int ky = -images; ky <= images; ++ky)
        for (int kx = -images; kx <= images; ++kx) visit(b.id, other.id, T(kx) * s.lx, T(ky) * s.ly);
    }
  }
}

template <class S>
double largest_overlap(const S& s) {
  double worst = 0;
  for_each_near_pair(s, [&](std::int32_t, std::int32_t, double distance, double contact) {
    worst = std::max(worst, (contact - distance) / contact);
  });
  return worst;
}

// Empty when all is well, else each problem described.
template <class S>
std::string check_invariants(const S& s, double tolerance) {
  using T = typename S::Scalar;
  std::ostringstream problems;
  for (std::size_t i = 0; i < s.p.size(); ++i)
    if (s.queue.key_of(std::uint32_t(i)).time < s.now) problems << "disk " << i << " has an event in the past; ";
  for_each_near_pair(s, [&](std::int32_t i, std::int32_t k, double distance, double contact) {
    if (distance < contact * (1 - tolerance))
      problems << "disks " << i << " and " << k << " overlap by " << (contact - distance) / contact
               << " of their contact distance; ";
  });
  if constexpr (S::Effects::kSegments)
    for (std::size_t i = 0; i < s.p.size(); ++i)
      for (std::size_t k = 0; k < s.walls.seg.size(); ++k) {
        const Position2<T> pi = s.pos_at(s.p.disk[i]);
        const double distance = double(segment_distance(s.walls.seg[k], pi.x, pi.y)), r = double(s.p.disk[i].r);
        if (distance < r * (1 - tolerance))
          problems << "disk " << i << " overlaps segment " << k << " by " << (r - distance) / r << " of its radius; ";
      }
  return problems.str();
}

}  // namespace ede
