// Timing an engine's event loop the way every benchmark does: wall clock, the thread's CPU time and
// user-mode cycles around run() only (loading and placement are not the engine's cost), reported as
// key=value text ("events=... collisions=... wall=... cpu=... cycles=...") for the parent process to parse.
// CPU time is what a busy machine without perf events (virtual machines) still measures well: time spent
// waiting for a core is not in it.
// A template, so that it also times an Engine used directly, without the EngineApi's virtual call
// (ede-bench-elastic).
#pragma once

#include <time.h>

#include <chrono>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "study/cpu_cycles.hpp"

namespace ede::study {

// CPU seconds of the calling thread (CLOCK_THREAD_CPUTIME_ID: nanosecond resolution, unlike getrusage).
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <class E>
std::string timed_run_report(E& engine) {
  CpuCycles cycles;
  cycles.start();
  const double cpu0 = thread_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  engine.run(std::numeric_limits<std::uint64_t>::max());  // (the default argument is on EngineApi only)
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = thread_cpu_seconds() - cpu0;
  const std::uint64_t cyc = cycles.stop();
  std::ostringstream o;
  o.precision(17);
  o << "events=" << engine.counts().events() << " collisions=" << engine.counts().collisions() << " wall=" << wall
    << " cpu=" << cpu << " cycles=" << cyc << " engine_bytes=" << engine.memory_bytes();
  return o.str();
}

}  // namespace ede::study
