// run_program, terminate_children, find_program and run_in_child; see process.hpp.
#include "process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

extern char** environ;

namespace ede::tools {

namespace {

using Clock = std::chrono::steady_clock;

// The pids of running programs (a sweep's pool runs one per thread at most): terminate_children reads
// them from a signal handler, so plain atomics, no allocation.
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

// Closes a posix_spawn_file_actions_t however the function returns.
struct FileActions {
  posix_spawn_file_actions_t actions;
  FileActions() { posix_spawn_file_actions_init(&actions); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
};

// Appends what `fd` has to `out`; false at its end (or on an error other than EINTR/EAGAIN).
bool read_some(int fd, std::string& out) {
  char buffer[4096];
  const ssize_t n = ::read(fd, buffer, sizeof buffer);
  if (n > 0) return out.append(buffer, std::size_t(n)), true;
  return n < 0 && (errno == EINTR || errno == EAGAIN);
}

void fill_end(ProcessEnd& end, int status, const rusage& usage, Clock::time_point start) {
  end.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  end.signalled = WIFSIGNALED(status);
  end.exit_status = end.signalled ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
  end.peak_rss_bytes = std::uint64_t(usage.ru_maxrss) * 1024;
}

}  // namespace

void terminate_children() {
  for (auto& c : g_children)
    if (const pid_t pid = c.load(); pid > 0) kill(pid, SIGTERM);
}

// Without a deadline the caller blocks (reading the child's stderr to its end, then in wait4: no polling
// delay on its end); with one it polls the pipe, or sleeps, a few milliseconds at a time.
Result<SpawnResult> run_program(const SpawnRequest& request) {
  if (request.argv.empty()) return Error{"no program to run"};
  const bool capture = request.stderr_path.empty();
  int pipe_fd[2] = {-1, -1};
  if (capture && ::pipe2(pipe_fd, O_CLOEXEC) != 0)
    return Error{std::string("cannot create a pipe: ") + std::strerror(errno)};
  FileActions fa;
  const std::string out = request.stdout_path.empty() ? "/dev/null" : request.stdout_path;
  posix_spawn_file_actions_addopen(&fa.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa.actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (capture)
    posix_spawn_file_actions_adddup2(&fa.actions, pipe_fd[1], 2);
  else
    posix_spawn_file_actions_addopen(&fa.actions, 2, request.stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = request.argv;
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const auto start = Clock::now();
  pid_t pid = 0;
  const int started = request.search_path ? ::posix_spawnp(&pid, argv[0], &fa.actions, nullptr, argv.data(), environ)
                                          : ::posix_spawn(&pid, argv[0], &fa.actions, nullptr, argv.data(), environ);
  if (capture) ::close(pipe_fd[1]);
  int err_fd = pipe_fd[0];
  if (started != 0) {
    if (err_fd >= 0) ::close(err_fd);
    return Error{"cannot run " + request.argv[0] + ": " + std::strerror(started)};
  }
  const std::size_t slot = remember(pid);
  const bool deadline = request.timeout > 0;
  SpawnResult result;
  int status = 0;
  rusage usage{};
  bool termed = false;
  auto killed_at = start;
  for (;;) {
    if (err_fd >= 0) {
      pollfd p{err_fd, POLLIN, 0};
      if (::poll(&p, 1, deadline ? 5 : -1) != 0 && !read_some(err_fd, result.err)) ::close(err_fd), err_fd = -1;
      if (!deadline && err_fd >= 0) continue;  // no deadline: its stderr to the end first
    }
    const pid_t w = ::wait4(pid, &status, deadline ? WNOHANG : 0, &usage);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      forget(slot);
      if (err_fd >= 0) ::close(err_fd);
      return Error{std::string("waiting for ") + request.argv[0] + ": " + std::strerror(errno)};
    }
    if (!deadline) continue;
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (elapsed > request.timeout && !termed) {
      kill(pid, SIGTERM);
      termed = true;
      result.timed_out = true;
      killed_at = now;
    } else if (termed && std::chrono::duration<double>(now - killed_at).count() > 1.0) {
      kill(pid, SIGKILL);
    }
    if (err_fd < 0) std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 0.05 ? 1 : 5));
  }
  forget(slot);
  if (err_fd >= 0) {
    while (read_some(err_fd, result.err)) {
    }
    ::close(err_fd);
  }
  fill_end(result, status, usage, start);
  return result;
}

std::optional<std::string> find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  const std::string dirs = path;
  for (std::size_t start = 0; start <= dirs.size();) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
    const std::string candidate = dir + "/" + name;
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

ChildResult run_in_child(const std::function<int(std::string& output)>& body) {
  ChildResult result;
  int fds[2];
  if (::pipe(fds) != 0) {
    result.failure = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  const auto start = Clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    result.failure = std::string("fork: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return result;
  }
  if (pid == 0) {
    ::close(fds[0]);
    std::string output;
    const int status = body(output);
    for (std::size_t done = 0; done < output.size();) {
      const ssize_t n = ::write(fds[1], output.data() + done, output.size() - done);
      if (n <= 0) break;
      done += std::size_t(n);
    }
    ::close(fds[1]);
    ::_exit(status);
  }
  ::close(fds[1]);
  while (read_some(fds[0], result.output)) {
  }
  ::close(fds[0]);
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  fill_end(result, status, usage, start);
  result.ok = !result.signalled && result.exit_status == 0;
  if (!result.ok)
    result.failure = result.signalled ? "killed by signal " + std::to_string(result.exit_status - 128)
                                      : "exit status " + std::to_string(result.exit_status);
  return result;
}

}  // namespace ede::tools
