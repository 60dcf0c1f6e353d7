// ede-bench speed: events per second, nanoseconds and cycles per event, bytes per disk, for scenes run
// with the cell engine (median of repeats) and with the naive all-pairs baseline in the same invocation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ede::bench {

struct SpeedOptions {
  std::vector<std::string> scenes;
  int repeat = 3;
  std::uint64_t events = 0;              // 0: the scene's own stop.events
  std::uint64_t baseline_max_disks = 10000;  // above this the O(N^2) start of all-pairs is unbearable
  double baseline_seconds = 2;           // target duration of a baseline run (its event budget ~ 1/N)
  std::string csv_path;
};

int run_speed(const SpeedOptions& options);

}  // namespace ede::bench
