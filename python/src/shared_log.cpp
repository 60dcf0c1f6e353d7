// SharedLog (shared_log.hpp): the lock, close, Ctrl-C and out-of-memory handling around every read of a
// Log from Python, and the memory a request is checked against before numpy allocates it.
#include "shared_log.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>

namespace ede::python {

namespace {

constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();

// A "Key:   123 kB" line of a /proc file, in bytes.
std::optional<std::uint64_t> proc_kb(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size() + 1, key + ":") == 0) return std::stoull(line.substr(key.size() + 1)) * 1024;
  return std::nullopt;
}

// What a resource limit leaves, given the /proc/self/status field that counts against it.
std::uint64_t left_under(int resource, const char* used_field) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnlimited;
  const std::uint64_t used = proc_kb("/proc/self/status", used_field).value_or(0);
  return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

// What this process's cgroup (v2) still allows: a container's memory limit, which /proc/meminfo ignores.
std::uint64_t left_in_cgroup() {
  std::ifstream self("/proc/self/cgroup");
  std::string line;
  while (std::getline(self, line)) {
    if (line.compare(0, 3, "0::") != 0) continue;
    const std::string dir = "/sys/fs/cgroup" + line.substr(3);
    std::ifstream max_file(dir + "/memory.max"), current_file(dir + "/memory.current");
    std::string max_text;
    std::uint64_t current = 0;
    if (!(max_file >> max_text) || max_text == "max" || !(current_file >> current)) return kUnlimited;
    const std::uint64_t max = std::stoull(max_text);
    return max > current ? max - current : 0;
  }
  return kUnlimited;
}

}  // namespace

std::uint64_t allocatable_bytes() {
  std::uint64_t bytes = kUnlimited;
  if (const auto available = proc_kb("/proc/meminfo", "MemAvailable"))
    bytes = *available + proc_kb("/proc/meminfo", "SwapFree").value_or(0);
  bytes = std::min({bytes, left_under(RLIMIT_AS, "VmSize"), left_under(RLIMIT_DATA, "VmData"), left_in_cgroup()});
  return bytes;
}

bool may_not_fit(double bytes, std::uint64_t& left) {
  if (bytes < double(16 << 20)) return false;
  left = allocatable_bytes();
  return bytes > double(left);
}

std::string byte_text(double bytes) {
  char text[32];
  if (bytes >= 1e9) std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  else std::snprintf(text, sizeof text, "%.0f MB", std::max(bytes / 1e6, 0.0));
  return text;
}

SharedLog::SharedLog(const std::string& path) {
  Result<Log> opened = [&] {
    py::gil_scoped_release release;
    return Log::open(path);
  }();
  log_.emplace(value_or_raise(std::move(opened)));
  info_ = log_->info();
  log_->set_interrupt_check([this] { return should_stop(); });
}

const LogInfo& SharedLog::info() const {
  if (closed_) raise_closed();
  return info_;
}

void SharedLog::raise_closed() const {
  throw Exception(Error{info_.path + ": this ede.Log was closed (close(), or the end of its `with` block): open "
                        "the file again with ede.open(path) to read it"});
}

void SharedLog::close() {
  if (owner_.load() == std::this_thread::get_id())
    throw Exception(Error{path() + ": close() called from inside a call on this Log (a signal handler?): close "
                          "it once the call has returned"});
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(mutex_);
  closed_ = true;
  log_.reset();
}

Log SharedLog::handle() {
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(mutex_);
  if (closed_) raise_closed();
  return *log_;
}

std::unique_lock<std::mutex> SharedLog::enter() {
  if (owner_.load() == std::this_thread::get_id())
    throw Exception(Error{path() + ": this ede.Log is already inside a call on this thread (a signal handler or a "
                          "callback reading the log it interrupted): give it its own ede.open(path)"});
  std::unique_lock<std::mutex> lock(mutex_);
  if (closed_) raise_closed();
  owner_ = std::this_thread::get_id();
  stop_ = false;
  next_signal_check_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(20);
  return lock;
}

void SharedLog::leave() { owner_ = std::thread::id{}; }

// Asked by the library before each chunk, from every thread of a walk: the threads it started see only the
// flag; the calling thread also runs Python's signal handlers every 20 ms (a short call never takes the GIL).
bool SharedLog::should_stop() {
  if (stop_.load(std::memory_order_relaxed)) return true;
  if (owner_.load(std::memory_order_relaxed) != std::this_thread::get_id()) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_signal_check_) return false;
  next_signal_check_ = now + std::chrono::milliseconds(20);
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0) return false;
  pending_ = std::make_unique<py::error_already_set>();
  stop_ = true;
  return true;
}

void SharedLog::raise_pending() {
  if (!pending_) return;
  std::unique_ptr<py::error_already_set> e = std::move(pending_);
  throw std::move(*e);
}

}  // namespace ede::python
