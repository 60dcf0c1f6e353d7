// run_program and find_program; see spawn.hpp.
#include "spawn.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace ede::tools {

namespace {

// Closes a posix_spawn_file_actions_t however the function returns.
struct FileActions {
  posix_spawn_file_actions_t actions;
  FileActions() { posix_spawn_file_actions_init(&actions); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
};

std::string read_all(int fd) {
  std::string out;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) out.append(buffer, std::size_t(n));
    else if (n < 0 && errno == EINTR) continue;
    else break;
  }
  return out;
}

}  // namespace

Result<SpawnResult> run_program(const SpawnRequest& request) {
  if (request.argv.empty()) return Error{"no program to run"};
  int pipe_fd[2];
  if (::pipe2(pipe_fd, O_CLOEXEC) != 0) return Error{std::string("cannot create a pipe: ") + std::strerror(errno)};
  FileActions fa;
  const std::string out = request.stdout_path.empty() ? "/dev/null" : request.stdout_path;
  posix_spawn_file_actions_addopen(&fa.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa.actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa.actions, pipe_fd[1], 2);
  std::vector<std::string> args = request.argv;
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int started = request.search_path ? ::posix_spawnp(&pid, argv[0], &fa.actions, nullptr, argv.data(), environ)
                                          : ::posix_spawn(&pid, argv[0], &fa.actions, nullptr, argv.data(), environ);
  ::close(pipe_fd[1]);
  if (started != 0) {
    ::close(pipe_fd[0]);
    return Error{"cannot run " + request.argv[0] + ": " + std::strerror(started)};
  }
  SpawnResult result;
  result.err = read_all(pipe_fd[0]);
  ::close(pipe_fd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
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

}  // namespace ede::tools
