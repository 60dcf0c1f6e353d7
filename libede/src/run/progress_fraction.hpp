// How far a run is towards its nearest stop condition, in [0, 1], for progress displays.
#pragma once

#include <cstdint>

#include "ede/scene.hpp"

namespace ede {

struct ProgressInputs {
  double time = 0;
  std::uint64_t events = 0;
  std::uint64_t pairs = 0;
  double energy_ratio = 1;  // current / initial kinetic energy
};

double progress_fraction(const StopSpec& stop, std::uint64_t disks, const ProgressInputs& now);

}  // namespace ede
