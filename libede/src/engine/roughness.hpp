// The state of a Rough engine (effects.hpp): 1 + beta per pair of species and of the box walls, and the
// spins' set-up (omega and I per disk live in Particles). A Smooth engine holds NoRoughness: nothing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/initial_state.hpp"
#include "core/particles.hpp"
#include "ede/scene.hpp"

namespace ede {

struct NoRoughness {};

template <class T>
struct Roughness {
  std::vector<T> beta_table;  // 1 + beta for species (a, b) at a * species + b
  std::size_t species = 1;
  T wall_one_plus_beta = 0;

  void setup(const std::vector<std::string>& names, const PhysicsSpec& ph) {
    species = std::max<std::size_t>(names.size(), 1);
    beta_table.assign(species * species, T(1) + T(ph.roughness));
    const auto index_of = [&](const std::string& name) {
      return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
    };
    for (const PairRestitution& pr : ph.pairs) {
      const std::size_t a = index_of(pr.a), b = index_of(pr.b);
      beta_table[a * species + b] = beta_table[b * species + a] = T(1) + T(ph.pair_roughness(pr));
    }
    wall_one_plus_beta = T(1) + T(ph.wall_roughness);
  }

  T pair_one_plus_beta(const Particles<T>& p, std::int32_t i, std::int32_t j) const {
    if (beta_table.size() == 1) return beta_table[0];
    return beta_table[std::size_t(p.species_of(std::size_t(i))) * species + std::size_t(p.species_of(std::size_t(j)))];
  }

  // omega and I from the initial state, or omega = 0 and I = m r^2 / 2 (a uniform disk) where it has none
  // (a state built in code, or a start from a smooth run's log).
  static void load_spins(const InitialState& init, Particles<T>& p) {
    const std::size_t n = init.size();
    p.omega.assign(n, T(0));
    p.inertia.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      p.inertia[i] = T(0.5) * p.mass(i) * p.disk[i].r * p.disk[i].r;
      if (init.omega.size() == n) p.omega[i] = T(init.omega[i]);
      if (init.inertia.size() == n) p.inertia[i] = T(init.inertia[i]);
    }
  }

  std::size_t memory_bytes() const { return beta_table.capacity() * sizeof(T); }
};

}  // namespace ede
