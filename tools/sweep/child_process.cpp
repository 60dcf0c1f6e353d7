// posix_spawn and a polled waitpid with a deadline (see child_process.hpp).
#include "child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

extern char** environ;

namespace ede::sweep {

namespace {

// The pids of running children (one slot per pool thread at most): terminate_children reads them from a
// signal handler, so plain atomics, no allocation.
std::array<std::atomic<pid_t>, 256> g_children{};

std::size_t remember(pid_t pid) {
  for (std::size_t k = 0; k < g_children.size(); ++k) {
    pid_t none = 0;
    if (g_children[k].compare_exchange_strong(none, pid)) return k;
  }
  return g_children.size();
}

void forget(std::size_t slot) {
  if (slot < g_children.size()) g_children[slot] = 0;
}

std::atomic<int> g_stop_signal{0};

void on_stop(int sig) {
  g_stop_signal = sig;
  terminate_children();
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

void terminate_children() {
  for (auto& c : g_children)
    if (const pid_t pid = c.load(); pid > 0) kill(pid, SIGTERM);
}

Result<ChildEnd> run_child_process(const std::vector<std::string>& argv, const std::string& stderr_path, double timeout) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return Error{"cannot start " + argv[0] + ": " + std::strerror(rc)};
  const std::size_t slot = remember(pid);
  ChildEnd end;
  int status = 0;
  bool termed = false;
  auto killed_at = start;
  for (;;) {
    // Without a deadline the thread blocks in waitpid (no polling delay on a run's end); with one it polls.
    const pid_t w = waitpid(pid, &status, timeout > 0 ? WNOHANG : 0);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      forget(slot);
      return Error{std::string("waiting for a run's process: ") + std::strerror(errno)};
    }
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (timeout > 0 && elapsed > timeout && !termed) {
      kill(pid, SIGTERM);
      termed = true;
      end.timed_out = true;
      killed_at = now;
    } else if (termed && std::chrono::duration<double>(now - killed_at).count() > 1.0) {
      kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 0.05 ? 1 : 5));
  }
  forget(slot);
  end.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  end.signalled = WIFSIGNALED(status);
  end.exit_status = end.signalled ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
  return end;
}

}  // namespace ede::sweep
