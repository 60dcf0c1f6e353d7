// find_program and encode_mp4; see ffmpeg.hpp.
#include "ffmpeg.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace ede::render {

namespace {

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

// Runs argv[0] (a full path) with argv; returns its exit status (or 128 + signal) and its stderr.
Result<std::pair<int, std::string>> run(std::vector<std::string> argv_text) {
  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) return Error{std::string("cannot create a pipe: ") + std::strerror(errno)};
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return Error{std::string("cannot start ") + argv_text[0] + ": " + std::strerror(errno)};
  if (pid == 0) {
    const int null_fd = ::open("/dev/null", O_RDWR);
    ::dup2(null_fd, 0);
    ::dup2(null_fd, 1);
    ::dup2(pipe_fd[1], 2);
    ::close(pipe_fd[0]);
    ::execv(argv[0], argv.data());
    std::fprintf(stderr, "cannot run %s: %s\n", argv[0], std::strerror(errno));
    ::_exit(127);
  }
  ::close(pipe_fd[1]);
  std::string err = read_all(pipe_fd[0]);
  ::close(pipe_fd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return std::make_pair(code, std::move(err));
}

}  // namespace

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

Status encode_mp4(const std::string& ffmpeg, const std::string& frames_dir, double fps, const std::string& output) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  const std::string out = output.starts_with("-") ? "./" + output : output;  // not an option to ffmpeg
  auto r = run({ffmpeg, "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-framerate", rate, "-i",
                frames_dir + "/frame_%05d.png", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white", "-c:v",
                "libx264", "-pix_fmt", "yuv420p", "-movflags", "+faststart", out});
  if (!r) return r.error();
  const auto& [code, err] = r.value();
  if (code != 0)
    return Error{"ffmpeg failed (exit status " + std::to_string(code) + ") encoding '" + output + "'" +
                 (err.empty() ? std::string() : ":\n" + err)};
  return Ok{};
}

}  // namespace ede::render
