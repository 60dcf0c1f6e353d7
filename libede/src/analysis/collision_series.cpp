// collision_series (ede/analysis.hpp): collision counts, rates and speed classes of a log over time.
//
// Counts come from log_series (one walk over the events), the speed classes from snapshots at the same
// times (for_each_snapshot, forward only). The rate in a row is that of the interval since the row
// before, so the first row has none. Rejected: a rate from a sliding window of events, whose width would
// be one more parameter to explain.
#include <limits>

#include "ede/analysis.hpp"

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
  for (std::size_t k = 0; k < l.time.size(); ++k) {
    if (k == 0 || !(l.time[k] > l.time[k - 1])) {
      c.rate.push_back(none);
      c.mean_free_time.push_back(none);
      continue;
    }
    const double r = (l.collisions_per_particle(k) - l.collisions_per_particle(k - 1)) / (l.time[k] - l.time[k - 1]);
    c.rate.push_back(r);
    c.mean_free_time.push_back(r > 0 ? 1 / r : std::numeric_limits<double>::infinity());
  }
  return c;
}

}  // namespace ede
