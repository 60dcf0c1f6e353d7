// Wall-clock seconds since a steady_clock instant: the one formula the run room's timings share (setup
// time, progress, a live run's pace). Header-only, so that a room compiled as one translation unit (the
// unity build) holds it once instead of one copy per file.
#pragma once

#include <chrono>

namespace ede {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ede
