// progress_fraction; see progress_fraction.hpp. The energy stop is measured on a log scale: inelastic
// cooling is roughly exponential in the number of collisions, so the fraction then grows evenly.
#include "run/progress_fraction.hpp"

#include <algorithm>
#include <cmath>

namespace ede {

double progress_fraction(const StopSpec& stop, std::uint64_t disks, const ProgressInputs& now) {
  double f = 0;
  if (stop.time && *stop.time > 0) f = std::max(f, now.time / *stop.time);
  if (stop.events && *stop.events > 0) f = std::max(f, double(now.events) / double(*stop.events));
  if (stop.collisions_per_particle && disks > 0)
    f = std::max(f, 2.0 * double(now.pairs) / double(disks) / *stop.collisions_per_particle);
  if (stop.energy_fraction && *stop.energy_fraction < 1 && now.energy_ratio < 1)
    f = std::max(f, std::log(now.energy_ratio) / std::log(*stop.energy_fraction));
  return std::clamp(f, 0.0, 1.0);
}

}  // namespace ede
