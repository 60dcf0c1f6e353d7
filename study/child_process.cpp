// run_in_child: fork, pipe, wait4; see child_process.hpp.
#include "study/child_process.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>

namespace ede::study {

ChildResult run_in_child(const std::function<int(std::string& output)>& body) {
  ChildResult result;
  int fds[2];
  if (pipe(fds) != 0) {
    result.failure = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    result.failure = std::string("fork: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return result;
  }
  if (pid == 0) {
    close(fds[0]);
    std::string output;
    const int status = body(output);
    for (std::size_t done = 0; done < output.size();) {
      const ssize_t n = write(fds[1], output.data() + done, output.size() - done);
      if (n <= 0) break;
      done += std::size_t(n);
    }
    close(fds[1]);
    _exit(status);
  }
  close(fds[1]);
  char buffer[4096];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) result.output.append(buffer, std::size_t(n));
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  result.peak_rss_bytes = std::uint64_t(usage.ru_maxrss) * 1024;
  result.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!result.ok)
    result.failure = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                         : "exit status " + std::to_string(WEXITSTATUS(status));
  return result;
}

}  // namespace ede::study
