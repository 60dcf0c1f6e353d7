// live_overrides, actions_override and the reversal checks; see live_schedule.hpp.
#include "run/live_schedule.hpp"

#include <algorithm>
#include <cmath>

#include "ede/number_text.hpp"

namespace ede {

std::vector<Override> live_overrides(const Scene& base, const LiveRunSetup& setup) {
  std::vector<Override> o;
  for (const std::string& s : setup.overrides) o.push_back({s});
  o.push_back({"stop.time=" + exact_number(setup.until)});
  // A run stopped by a new setup or by the front end's end keeps its complete chunks only: small chunks
  // lose at most 1024 events (the log's bytes per event barely change).
  if (!base.log.chunk_events) o.push_back({"log.chunk_events=1024"});
  // Lifted far past any live run, yet within what the run checks allow with samples by collisions per
  // disk (1e8 samples: 1e15 with samples every 5 collisions per disk was refused as endless sampling).
  if (base.stop.collisions_per_particle)
    o.push_back({"stop.collisions_per_particle=" +
                 exact_number(base.sample_collisions ? std::min(1e15, 1e8 * *base.sample_collisions) : 1e15)});
  if (base.stop.events) o.push_back({"stop.events=1000000000000000000"});
  return o;
}

bool actions_by_collisions(const Scene& scene) {
  return !scene.actions.empty() && scene.actions.front().collisions_per_disk.has_value();
}

// c is moved by one double at a time until ceil(c n / 2) is exactly `pairs` (2 pairs / n alone can round
// either way).
double collisions_per_disk_for(std::uint64_t pairs, std::size_t n) {
  const auto target = [n](double c) { return std::uint64_t(std::ceil(c * double(n) / 2)); };
  double c = 2.0 * double(pairs) / double(n);
  while (target(c) > pairs) c = std::nextafter(c, 0.0);
  while (target(c) < pairs) c = std::nextafter(c, HUGE_VAL);
  return c;
}

Override actions_override(const Scene& scene, const std::vector<double>& times, const std::vector<std::uint64_t>& pairs,
                          std::size_t n) {
  const bool by_collisions = actions_by_collisions(scene);
  std::vector<double> when = by_collisions ? std::vector<double>() : times;
  for (std::uint64_t p : pairs) when.push_back(collisions_per_disk_for(p, n));
  for (const ActionSpec& a : scene.actions) when.push_back(a.collisions_per_disk.value_or(a.time));
  std::sort(when.begin(), when.end());
  const std::string key = by_collisions ? "{collisions_per_disk=" : "{time=";
  std::string text = "actions=[";
  for (std::size_t k = 0; k < when.size(); ++k)
    text += (k ? "," : "") + key + exact_number(when[k]) + ",kind=\"reverse_velocities\"}";
  return {text + "]"};
}

std::string cannot_reverse(const Scene& scene, double time, std::uint64_t pairs) {
  if (actions_by_collisions(scene) && pairs == 0)
    return "this scene schedules its actions by collisions per disk, so a reversal is one too (right after the "
           "latest pair collision): there has been none yet. Fix: press GO, then reverse";
  if (!actions_by_collisions(scene) && !(time > 0))
    return "a reversal is an action at the current time, which must be after t = 0. Fix: press GO, then reverse";
  return "";
}

}  // namespace ede
