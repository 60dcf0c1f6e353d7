// InterruptGuard; see interrupt.hpp. One Simulation at a time is guarded (a tool runs one).
#include "interrupt.hpp"

namespace ede::tools {

namespace {
Simulation* g_simulation = nullptr;
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int sig) {
  g_signal = sig;
  std::signal(sig, SIG_DFL);  // a second one ends the process
  if (g_simulation) g_simulation->interrupt();
}
}  // namespace

InterruptGuard::InterruptGuard(Simulation& sim) {
  g_simulation = &sim;
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  g_simulation = nullptr;
}

int InterruptGuard::signal_received() { return g_signal; }

}  // namespace ede::tools
