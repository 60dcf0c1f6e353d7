// The state of a Dissipative engine (effects.hpp): restitution per pair of species (a table, with a fast
// path when every pair has the same) and per wall, the TC model, and the kinetic energy kept up to date
// for stop.energy_fraction. An Elastic engine holds NoRestitution: nothing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "core/scalar_math.hpp"
#include "ede/scene.hpp"

namespace ede {

struct NoRestitution {};

template <class T>
struct Restitution {
  bool tc_model = false;  // tc > 0 in a dissipative scene (uses_tc_model)
  T tc = 0;
  T xi_wall[4] = {1, 1, 1, 1};
  std::vector<T> pair_table;  // 1 + xi for species (a, b) at a * species + b
  std::size_t species = 1;
  bool uniform_pairs = true;
  T one_plus_xi = 2;
  double ke = 0;              // the kinetic energy now, kept by every collision
  std::int32_t too_slow = -1;  // the first disk to leave a collision too slow (stops.hpp), or -1

  void setup(const std::vector<std::string>& names, const PhysicsSpec& ph, bool tc_on) {
    tc_model = tc_on;
    tc = T(ph.tc);
    species = std::max<std::size_t>(names.size(), 1);
    pair_table.assign(species * species, T(1) + T(ph.restitution));
    const auto index_of = [&](const std::string& name) {
      return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
    };
    for (const PairRestitution& pr : ph.pairs) {
      const std::size_t a = index_of(pr.a), b = index_of(pr.b);  // checked by check_engine_input
      pair_table[a * species + b] = pair_table[b * species + a] = T(1) + T(pr.value);
    }
    uniform_pairs = std::all_of(pair_table.begin(), pair_table.end(), [&](T v) { return v == pair_table[0]; });
    one_plus_xi = pair_table[0];
    for (int w = 0; w < 4; ++w) xi_wall[w] = T(ph.wall(w));
  }

  T pair_one_plus_xi(const Particles<T>& p, std::int32_t i, std::int32_t j) const {
    if (uniform_pairs) return one_plus_xi;
    return pair_table[std::size_t(p.species_of(std::size_t(i))) * species + std::size_t(p.species_of(std::size_t(j)))];
  }

  // Within t_c of either disk's previous collision the TC model makes a collision elastic (j < 0: a wall).
  bool tc_elastic(const Particles<T>& p, T now, std::int32_t i, std::int32_t j) const {
    if (!tc_model) return false;
    if (now - p.last_collision[std::size_t(i)] < tc) return true;
    return j >= 0 && now - p.last_collision[std::size_t(j)] < tc;
  }

  // An inelastic run that cools for ever (a wall restitution of 0.1 divides a speed by 10 per bounce)
  // reaches speeds whose squares leave T's normal range: below sqrt(min / epsilon) (~1e-146 in double,
  // ~3e-16 in float) the products of the contact-time formula lose digits or underflow to zero, pairs
  // approaching each other are no longer seen, and disks overlap (found by fuzz_engine: three disks after
  // 3000 events at speeds ~1e-192). The first disk to leave a collision that slow ends the run (stops.hpp),
  // before anything goes wrong. Exact zero (a disk stopped dead by xi = 0) is fine: it is at rest. Not
  // under gravity (the caller's choice): g renews the speeds and bounds the times between events, and a
  // disk bouncing to rest on the floor is the stall detector's case.
  static inline const T kSlowestSpeed = ede::sqrt(scalar_limits<T>::min() / scalar_limits<T>::epsilon());
  void note_if_too_slow(const Particles<T>& p, std::int32_t i) {
    const Disk<T>& d = p.disk[std::size_t(i)];
    const T speed = std::max(ede::abs(d.vx), ede::abs(d.vy));
    if (speed != T(0) && speed < kSlowestSpeed && too_slow < 0) too_slow = i;
  }

  std::size_t memory_bytes() const { return pair_table.capacity() * sizeof(T); }
};

}  // namespace ede
