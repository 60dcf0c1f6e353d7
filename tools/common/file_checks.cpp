// check_outputs_distinct; see file_checks.hpp.
#include "file_checks.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <mutex>

namespace ede::tools {

namespace {

struct Identity {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
};

Identity identity_of(const std::string& path) {
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0) return {};
  return {true, st.st_dev, st.st_ino};
}

bool same(const Identity& a, const Identity& b) { return a.exists && b.exists && a.dev == b.dev && a.ino == b.ino; }

bool is_device(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode));
}

}  // namespace

Status check_outputs_distinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const NamedPath& out = outputs[k];
    const Identity o = identity_of(out.path);
    if (!o.exists || is_device(out.path)) continue;  // new files, and /dev/null or /dev/full, are never inputs
    for (const NamedPath& in : inputs)
      if (same(o, identity_of(in.path)))
        return Error{out.what + " '" + out.path + "' is " + in.what + " '" + in.path +
                         "' (the same file): writing it would destroy the input. Fix: choose another output file."};
    for (std::size_t m = 0; m < k; ++m)
      if (same(o, identity_of(outputs[m].path)))
        return Error{out.what + " '" + out.path + "' and " + outputs[m].what + " '" + outputs[m].path +
                         "' are the same file. Fix: give each output its own file."};
  }
  for (std::size_t k = 0; k < outputs.size(); ++k)
    for (std::size_t m = 0; m < k; ++m)
      if (!outputs[k].path.empty() && outputs[k].path == outputs[m].path)
        return Error{outputs[k].what + " and " + outputs[m].what + " both name '" + outputs[k].path +
                     "'. Fix: give each output its own file."};
  return Ok{};
}

namespace {
struct NotedInput {
  std::string what, path;
  Identity id;
  int fd;  // held open with a shared lock until the process ends (-1: none)
};
std::vector<NotedInput>& noted() {  // under noted_mutex(): ede-crater scan opens logs on several threads
  static std::vector<NotedInput> inputs;
  return inputs;
}
std::mutex& noted_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

void note_input(const std::string& what, const std::string& path) {
  const Identity id = identity_of(path);
  const std::lock_guard<std::mutex> lock(noted_mutex());
  if (!id.exists || is_device(path)) return;
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd >= 0 && ::flock(fd, LOCK_SH | LOCK_NB) != 0) {  // being written: read it anyway, unlocked
    ::close(fd);
    fd = -1;
  }
  noted().push_back({what, path, id, fd});
}

Status check_not_an_input(const std::string& output) {
  const Identity o = identity_of(output);
  if (!o.exists) return Ok{};
  const std::lock_guard<std::mutex> lock(noted_mutex());
  for (const NotedInput& in : noted())
    if (same(o, in.id))
      return Error{"the output '" + output + "' is " + in.what + " '" + in.path +
                   "' (the same file): writing it would destroy the input. Fix: choose another output file."};
  return Ok{};
}

}  // namespace ede::tools
