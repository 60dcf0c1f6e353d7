// Ctrl-C and kill (SIGINT, SIGTERM) during a long run: the handler asks the Simulation to stop at its next
// check (Simulation::interrupt is async-signal-safe), so the tool can print what was kept and how to go on
// instead of dying mid-write. A second signal while stopping ends the process at once (the default).
#pragma once

#include <csignal>

#include "ede/simulation.hpp"

namespace ede::tools {

class InterruptGuard {
 public:
  explicit InterruptGuard(Simulation& sim);
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The signal that interrupted the run (SIGINT or SIGTERM), or 0.
  static int signal_received();
  // The conventional exit status after that signal: 128 + its number.
  static int exit_status() { return 128 + signal_received(); }
};

}  // namespace ede::tools
