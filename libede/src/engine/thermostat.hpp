// The state of an engine with the Andersen thermostat (effects.hpp, Andersen): which disks it covers, at
// which kT, and its one clock. An engine without it holds NoThermostatClock: nothing.
//
// One clock for the whole system: the redraws of N_g disks of rate nu_g each (per group g, a species) are
// together one Poisson process of rate R = sum_g N_g nu_g, each of whose events picks group g with
// probability N_g nu_g / R and a disk of it uniformly (the superposition of independent Poisson processes).
// So the state is one time, not N, and no disk's prediction carries a thermostat candidate. The clock is
// drawn again at every rebuild of the predictions (the exponential law forgets how long it has waited, so
// the process stays Poisson of rate R), from a stream keyed by the event count there: a run resumed from a
// rebuild point draws the same time, and a resumable keyframe needs no thermostat field.
// Rejected: one clock per disk in its prediction (N more times to store and to restore on resume, a
// thermostat candidate in every prediction of the hot loop) and std:: distributions (not portable).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry.hpp"
#include "core/rng.hpp"
#include "ede/scene.hpp"

namespace ede {

struct NoThermostatClock {};

// The thermostat of one species, resolved from the scene ([thermostat] and [species.thermostat]).
struct SpeciesThermostat {
  std::string species;
  double temperature = 1, rate = 0;
};

// The thermostats per species a scene asks for (engine_options_from): a species' own first, else
// [thermostat] if it covers the species. Species named nowhere are not thermostatted.
inline ThermostatSpec thermostat_for(const std::string& species, const PhysicsSpec& ph,
                                     const std::vector<SpeciesThermostat>& own) {
  for (const SpeciesThermostat& s : own)
    if (s.species == species) return {s.temperature, s.rate, {}};
  if (!ph.thermostat) return {};
  const std::vector<std::string>& only = ph.thermostat->species;
  bool covered = only.empty();
  for (const std::string& name : only) covered = covered || name == species;
  return covered ? ThermostatSpec{ph.thermostat->temperature, ph.thermostat->rate, {}} : ThermostatSpec{};
}

// Random streams (Rng::for_stream of the scene's seed): the redraw that is the thermostat's m-th event
// uses stream kThermostatStreams + 2 m, the clock drawn at a rebuild after c events kThermostatStreams +
// 2 c + 1: far from the species' streams (0, 1, ...) and the growth's.
inline constexpr std::uint64_t kThermostatStreams = 0x7468000000000000ull;  // "th"

template <class T>
struct AndersenClock {
  struct Group {
    std::vector<std::int32_t> disks;  // in id order
    double temperature = 1;           // kT
    double weight = 0;                // N_g nu_g
  };
  std::vector<Group> groups;  // the thermostatted species, in species order
  double total_rate = 0;      // R
  std::uint64_t seed = 0;
  T next = kNever<T>;         // the next redraw's time

  void setup(const std::vector<std::string>& names, const std::vector<std::int32_t>& species, const PhysicsSpec& ph,
             const std::vector<SpeciesThermostat>& own, std::uint64_t run_seed) {
    seed = run_seed;
    const std::size_t kinds = std::max<std::size_t>(names.size(), 1);
    std::vector<Group> by_species(kinds);
    std::vector<double> rates(kinds, 0);
    for (std::size_t k = 0; k < kinds; ++k) {
      const ThermostatSpec t = thermostat_for(k < names.size() ? names[k] : std::string(), ph, own);
      by_species[k].temperature = t.temperature;
      rates[k] = t.rate;
    }
    for (std::size_t i = 0; i < species.size(); ++i)
      if (rates[std::size_t(species[i])] > 0) by_species[std::size_t(species[i])].disks.push_back(std::int32_t(i));
    for (std::size_t k = 0; k < kinds; ++k) {
      if (by_species[k].disks.empty()) continue;
      by_species[k].weight = double(by_species[k].disks.size()) * rates[k];
      total_rate += by_species[k].weight;
      groups.push_back(std::move(by_species[k]));
    }
  }

  // The time of the next redraw after `now`, from `rng`: now + E / R, E exponential of mean 1.
  T draw_next(T now, Rng& rng) const {
    if (total_rate <= 0) return kNever<T>;
    return now + T(rng.exponential_exact() / total_rate);
  }

  // The disk a redraw picks and its group: with several groups, one uniform01() against the cumulative
  // weights (in group order), then below(N_g) within the group; with one group, below(N_g) alone.
  std::int32_t pick(Rng& rng, const Group*& group) const {
    std::size_t g = 0;
    if (groups.size() > 1) {
      const double u = rng.uniform01() * total_rate;
      double below_g = 0;
      for (g = 0; g + 1 < groups.size(); ++g) {
        below_g += groups[g].weight;
        if (u < below_g) break;
      }
    }
    group = &groups[g];
    return group->disks[std::size_t(rng.below(group->disks.size()))];
  }

  std::size_t memory_bytes() const {
    std::size_t bytes = groups.capacity() * sizeof(Group);
    for (const Group& g : groups) bytes += g.disks.capacity() * sizeof(std::int32_t);
    return bytes;
  }
};

}  // namespace ede
