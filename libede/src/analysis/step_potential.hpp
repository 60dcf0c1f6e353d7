// The potential energy of a stepped potential (square wells and shoulders, [[physics.steps]]) from the
// positions alone: for every pair, the energies of the steps whose radius exceeds its distance. What a log
// reader needs at the start of a walk (log_series.cpp): from there on each step event changes the potential
// energy by minus the kinetic energy it changes, so the walk never recomputes it. A pair exactly on a
// step's radius (an event's instant) counts as outside; at a log's start no event has happened yet.
// A grid of cells at least the outermost step wide makes it O(N); rejected: all pairs, O(N^2), minutes at 10^5.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/scene.hpp"

namespace ede {

struct StepPositions {
  const std::vector<double>& x;
  const std::vector<double>& y;
  const std::vector<std::int32_t>& species;  // index into names
  const std::vector<std::string>& names;
  double lx = 1, ly = 1;
  bool periodic = false;
};

double step_potential_energy(const std::vector<PairSteps>& steps, const StepPositions& at);

}  // namespace ede
