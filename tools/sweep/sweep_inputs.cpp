// check_points, inputs_digest, scene_of and ResultsLock; see sweep_inputs.hpp.
#include "sweep_inputs.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace ede::sweep {

namespace {

constexpr std::size_t kListed = 10;  // bad points named in full; the rest are counted

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h) {
  for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "\x01(unreadable)";
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string point_text(const Sweep& s, const PlannedRun& r) {
  const std::vector<std::string> keys = parameter_columns(s.spec);
  std::string t = "point " + std::to_string(r.point);
  for (std::size_t k = 0; k < keys.size() && k < r.columns.size(); ++k)
    t += std::string(k ? ", " : " (") + keys[k] + " = " + r.columns[k] + (k + 1 == keys.size() ? ")" : "");
  return t;
}

}  // namespace

Result<Scene> scene_of(const Sweep& s, const PlannedRun& r) {
  std::vector<Override> overrides;
  for (const std::string& o : r.overrides) overrides.push_back({o});
  return load_scene_file(s.spec.scene_path, overrides);
}

Status check_points(const Sweep& s) {
  std::string listed;
  std::size_t bad = 0, points = 0;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    if (k > 0 && s.runs[k].point == s.runs[k - 1].point) continue;  // one run per point: seeds change nothing here
    ++points;
    auto scene = scene_of(s, s.runs[k]);
    if (scene) continue;
    if (bad++ < kListed) listed += "\n  " + point_text(s, s.runs[k]) + ": " + scene.error().message;
  }
  if (bad == 0) return Ok{};
  if (bad > kListed) listed += "\n  ... and " + std::to_string(bad - kListed) + " more";
  return Error{s.spec.path + ": " + std::to_string(bad) + " of the " + std::to_string(points) +
               " points give a scene that does not load, so nothing was run:" + listed +
               "\nFix: change those values in the sweep file (or its --set), then run it again."};
}

std::string inputs_digest(const SweepSpec& spec) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  h = fnv1a(file_bytes(spec.path), h);
  h = fnv1a(std::string(1, '\0'), h);
  h = fnv1a(file_bytes(spec.scene_path), h);
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

Result<std::unique_ptr<ResultsLock>> ResultsLock::take(const std::string& folder) {
  const std::string path = folder + "/.ede-sweep.lock";
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return Error{path + ": cannot open the results folder's lock: " + std::strerror(errno), ErrorKind::Io};
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char pid[32] = {};
    (void)::pread(fd, pid, sizeof pid - 1, 0);
    ::close(fd);
    std::string holder = pid;
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    return Error{folder + ": another ede-sweep" + (holder.empty() ? "" : " (pid " + holder + ")") +
                 " is writing this results folder now; two sweeps in one folder would run the same runs and "
                 "overwrite each other's rows and tables. Fix: wait for it to end, or give this sweep another "
                 "folder (--out-dir)."};
  }
  // The pid is only a note for a second sweep's message: the lock holds without it.
  const std::string me = std::to_string(::getpid()) + "\n";
  [[maybe_unused]] const bool noted = ::ftruncate(fd, 0) == 0 && ::pwrite(fd, me.data(), me.size(), 0) > 0;
  return std::unique_ptr<ResultsLock>(new ResultsLock(fd));
}

ResultsLock::~ResultsLock() { ::close(fd_); }

}  // namespace ede::sweep
