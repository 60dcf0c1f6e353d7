// The speed benchmark (ede-bench speed): events per second, nanoseconds and cycles per event, bytes per
// disk, for a scene run with the cell engine (median of repeats) and with the naive all-pairs baseline.
// Each measurement runs in its own child process (clean heap, its own peak RSS); only the event loop is
// timed (scene loading and placement are not the engine's cost). Wall-clock figures are medians over the
// repeats; cycles come from perf events when available, which the other jobs on a shared machine disturb
// much less than wall time. ede-bench prints the rows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ede::study {

struct SpeedPlan {
  int repeat = 3;
  std::vector<std::string> overrides;        // --set key=value, applied to every scene
  std::uint64_t baseline_max_disks = 10000;  // above this the O(N^2) start of all-pairs is unbearable
  double baseline_seconds = 2;               // target duration of a baseline run (its event budget ~ 1/N)
};

struct SpeedMeasurement {
  bool ok = false;
  std::string failure;
  double events = 0, collisions = 0, wall = 0, cycles = 0, engine_bytes = 0, disks = 0, setup = 0;
  double peak_rss = 0;
  double events_per_second() const { return wall > 0 ? events / wall : 0; }
};

struct SpeedRow {
  std::string scene;              // its label (file name without .toml)
  SpeedMeasurement typical;       // the repeat with the median events/s (or the failed one)
  double events_per_second = 0, collisions_per_second = 0, ns_per_event = 0, cycles_per_event = 0;
  bool baseline_run = false;
  std::string baseline_note;      // why the baseline did not run, or its failure
  double baseline_events_per_second = 0;
  double baseline_events = 0;
};

SpeedRow measure_speed(const std::string& scene_path, const SpeedPlan& plan);

}  // namespace ede::study
