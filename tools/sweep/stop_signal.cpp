// The sweep's stop handler; see stop_signal.hpp.
#include "stop_signal.hpp"

#include <signal.h>

#include <atomic>

#include "process.hpp"

namespace ede::sweep {

namespace {

std::atomic<int> g_stop_signal{0};

void on_stop(int sig) {
  g_stop_signal = sig;
  tools::terminate_children();
}

}  // namespace

void install_stop_handler() {
  struct sigaction sa {};
  sa.sa_handler = on_stop;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

bool stop_requested() { return g_stop_signal != 0; }
int stop_signal() { return g_stop_signal; }

}  // namespace ede::sweep
