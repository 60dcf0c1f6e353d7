// RunSummary: what a finished (or interrupted) run reports: counts, times, energies, memory, effects.
//
// Computed from an engine's state and counters alone, so ede-sim, ede-bench and tests report the same
// numbers the same way. Formatting (text for people, JSON for scripts) lives beside it so that every tool
// prints identical keys.
#pragma once

#include <cstdint>
#include <string>

#include "engine/engine.hpp"

namespace ede {

struct RunSummary {
  std::string scene;          // file name
  std::string scalar;         // "double", ...
  std::string effects;        // the engine instantiation's effects
  std::string status;         // why the run ended
  std::string stall_message;  // non-empty if it stalled
  std::uint64_t seed = 0;
  std::uint64_t disks = 0;
  EventCounts counts;
  double collisions_per_particle = 0;  // 2 * pair collisions / N
  double sim_time = 0;
  double wall_seconds = 0;             // time spent in the event loop (setup excluded)
  double setup_seconds = 0;            // scene loading, placement, initial predictions
  double energy_initial = 0, energy_final = 0;
  double momentum_initial[2] = {0, 0}, momentum_final[2] = {0, 0};
  std::uint64_t engine_bytes = 0;      // the engine's own arrays
  std::uint64_t peak_rss_bytes = 0;    // the whole process, from getrusage

  double events_per_second() const;      // every processed event (pair, wall, cell, wrap, action)
  double collisions_per_second() const;  // pair + wall
};

template <class T>
RunSummary summarize(const EngineApi<T>& engine, double momentum_initial_x, double momentum_initial_y);

std::uint64_t peak_rss_bytes();
std::string to_text(const RunSummary& s);
std::string to_json(const RunSummary& s);

}  // namespace ede
