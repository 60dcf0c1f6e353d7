// run_jobs: a small process pool for scans: fork + execv, each child writing to its own files.
//
// Independent runs are the one place DESIGN.md allows parallelism, because no result can depend on timing:
// every run writes its own log, and results are stored by job index, not by finishing order. Waiting is
// waitpid(-1): ede-crater has no other children while the pool runs. Rejected: threads calling the engine
// in-process, which would share one address space (a crash takes the scan down) and one allocator, and
// would duplicate ede-sim's set-up and logging code instead of running the very program users run.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>

#include "crater_tool.hpp"

namespace ede::crater_tool {

namespace {

pid_t start(const Job& job) {
  const pid_t pid = fork();
  if (pid != 0) return pid;
  const int out = open(job.stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = open(job.stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (out < 0 || err < 0) _exit(126);
  dup2(out, 1);
  dup2(err, 2);
  close(out);
  close(err);
  std::vector<char*> argv;
  std::vector<std::string> args = job.argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::fprintf(stderr, "cannot run %s: %s\n", argv[0], std::strerror(errno));
  _exit(127);
}

std::string describe(int status) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "exit status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

std::vector<JobResult> run_jobs(const std::vector<Job>& jobs, std::size_t parallel, const std::vector<int>& acceptable,
                                bool progress) {
  std::vector<JobResult> results(jobs.size());
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, finished = 0;
  bool failed = false;
  if (parallel == 0) parallel = 1;
  while ((!failed && next < jobs.size()) || !running.empty()) {
    while (!failed && next < jobs.size() && running.size() < parallel) {
      const pid_t pid = start(jobs[next]);
      results[next].started = true;
      if (pid < 0) {
        results[next].failure = std::string("fork: ") + std::strerror(errno);
        failed = true;
      } else {
        running[pid] = next;
      }
      ++next;
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;  // no children left to wait for (cannot happen while `running` is not empty)
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    JobResult& r = results[it->second];
    running.erase(it);
    ++finished;
    r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    bool ok = false;
    for (const int a : acceptable) ok = ok || (WIFEXITED(status) && r.exit_status == a);
    if (!ok) r.failure = describe(status), failed = true;
    if (progress)
      std::fprintf(stderr, "ede-crater: %zu/%zu runs done (%s%s)\n", finished, jobs.size(),
                   jobs[&r - results.data()].label.c_str(), ok ? "" : (": " + r.failure).c_str());
  }
  return results;
}

}  // namespace ede::crater_tool
