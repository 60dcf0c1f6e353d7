// Timing an engine's event loop the way every benchmark does: wall clock and user-mode cycles around
// run() only (loading and placement are not the engine's cost), reported as key=value text
// ("events=... collisions=... wall=... cycles=...") for the parent process to parse.
// A template, so that it also times an Engine used directly, without the EngineApi's virtual call
// (ede-bench-elastic).
#pragma once

#include <chrono>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "cpu_cycles.hpp"

namespace ede::tools {

template <class E>
std::string timed_run_report(E& engine) {
  CpuCycles cycles;
  cycles.start();
  const auto start = std::chrono::steady_clock::now();
  engine.run(std::numeric_limits<std::uint64_t>::max());  // (the default argument is on EngineApi only)
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::uint64_t cyc = cycles.stop();
  std::ostringstream o;
  o.precision(17);
  o << "events=" << engine.counts().events() << " collisions=" << engine.counts().collisions() << " wall=" << wall
    << " cycles=" << cyc << " engine_bytes=" << engine.memory_bytes();
  return o.str();
}

}  // namespace ede::tools
