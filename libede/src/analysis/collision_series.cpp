// collision_series (ede/analysis.hpp): collision counts, rates and speed classes of a log over time.
//
// Counts come from log_series (one walk over the events), the speed classes from snapshots at the same
// times (for_each_snapshot, forward only). The rate in a row is that of the interval since the row
// before, so the first row has none. Rejected: a rate from a sliding window of events, whose width would
// be one more parameter to explain.
// Enskog's rate of a window (ede/kinetic_theory.hpp) is the mean of omega_E at its two ends, each at the
// kT of the series' kinetic energy there (centre-of-mass frame with N - 1 in a periodic box, whose total
// momentum, taken at the first time, is conserved; the box frame with N with walls).
#include <cmath>
#include <limits>

#include "ede/analysis.hpp"
#include "ede/kinetic_theory.hpp"

namespace ede {

Result<CollisionSeries> collision_series(const Log& log, const std::vector<double>& times) {
  auto series = log_series(log, times);
  if (!series) return series.error();
  CollisionSeries c;
  c.series = std::move(series).value();
  Status s = for_each_snapshot(log, times, [&](const GasSnapshot& snap) {
    if (c.classes.empty()) c.reference_speed = mean_speed(snap);
    c.classes.push_back(speed_classes(snap, c.reference_speed));
  });
  if (!s) return s.error();
  const LogSeries& l = c.series;
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  if (!times.empty()) {
    auto e = enskog_at(log, times.front());
    if (!e) return e.error();
    c.enskog = e.value();
  }
  const Temperature& t0 = c.enskog.temperature;
  const double momentum_energy = t0.kinetic - t0.kinetic_cm;  // P^2 / 2M (0 with walls)
  const auto enskog_now = [&](std::size_t k) {
    const double kT = (l.kinetic_energy[k] - momentum_energy) / t0.degrees;
    return enskog_collision_rate(c.enskog.number_density, c.enskog.sigma, c.enskog.g_contact, kT, c.enskog.mass);
  };
  for (std::size_t k = 0; k < l.time.size(); ++k) {
    if (k == 0 || !(l.time[k] > l.time[k - 1])) {
      c.rate.push_back(none);
      c.mean_free_time.push_back(none);
      c.enskog_rate.push_back(none);
      continue;
    }
    const double r = (l.collisions_per_particle(k) - l.collisions_per_particle(k - 1)) / (l.time[k] - l.time[k - 1]);
    c.rate.push_back(r);
    c.enskog_rate.push_back(c.enskog.applicable ? (enskog_now(k - 1) + enskog_now(k)) / 2 : none);
    c.mean_free_time.push_back(r > 0 ? 1 / r : std::numeric_limits<double>::infinity());
  }
  return c;
}

}  // namespace ede
