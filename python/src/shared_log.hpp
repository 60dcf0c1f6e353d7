// SharedLog: an ede::Log as Python holds it (ede._ede.Log). The library's Log serves one thread at a time
// and frees its file when destroyed; Python shares objects between threads freely, collects them whenever,
// and stops long calls with Ctrl-C. So every call that reads the log goes through read(), which
//   - waits for the calls of other threads on this Log (a lock taken with the GIL released, so a thread
//     holding the GIL never waits on a thread that needs it), and refuses a call from inside a call on the
//     same thread (a signal handler reading the log it interrupted) instead of corrupting the cached replay;
//   - refuses a closed Log with ede.InvalidError naming the file (close() frees the file at once, after the
//     calls in progress);
//   - lets Ctrl-C stop the library's seeks and walks at their next chunk (Log::set_interrupt_check; Python's
//     signal handlers run on the calling thread every 20 ms) and raises what the handler raised
//     (KeyboardInterrupt), never a partial result;
//   - turns an allocation that fails into a MemoryError naming the file and the request.
// Rejected: a lock per Python method in log.py (the analyses take the C++ Log directly), a copy of the Log
// per thread (copies share the cached replay, so they are not independent), and checking signals from a
// watcher thread (only the main thread may run Python's handlers).
#pragma once

#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

#include "bindings.hpp"

namespace ede::python {

// Raised as Python's MemoryError with its message (errors.cpp registers the translation).
struct OutOfMemory : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The bytes this process may still allocate: the smallest of the machine's available memory (with swap)
// and what its address-space and data limits (ulimit -v, -d) and its cgroup leave; what a request is
// checked against before numpy allocates it (the kernel would otherwise grant it and kill the process when
// it is used).
std::uint64_t allocatable_bytes();
// Whether `bytes` may not fit: false at once below 16 MiB (reading /proc costs more than a small state),
// else whether they exceed allocatable_bytes(), which `left` receives.
bool may_not_fit(double bytes, std::uint64_t& left);
// "1.2 GB"
std::string byte_text(double bytes);

class SharedLog {
 public:
  explicit SharedLog(const std::string& path);
  SharedLog(const SharedLog&) = delete;
  SharedLog& operator=(const SharedLog&) = delete;

  const std::string& path() const { return info_.path; }
  bool closed() const { return closed_.load(); }
  // What the log holds (read once at open); ede.InvalidError once closed.
  const LogInfo& info() const;
  // Frees the file once the calls in progress on other threads have returned. Idempotent.
  void close();
  // A handle on the same open log for a call that only reads its file (diff's other log): it keeps the
  // file open even if this SharedLog is closed meanwhile.
  Log handle();

  // f(const Log&) -> Result<V> or Status, called with the GIL released as described above; its value, or
  // its error raised as the matching ede exception. `what` names the request in a MemoryError.
  template <class F>
  auto read(const char* what, F&& f);

  // For binding code running inside read(): whether the call should stop now (Ctrl-C). Thread-safe.
  bool interrupted() { return should_stop(); }

 private:
  std::unique_lock<std::mutex> enter();
  void leave();
  bool should_stop();
  [[noreturn]] void raise_closed() const;
  void raise_pending();

  LogInfo info_;
  std::optional<Log> log_;
  std::mutex mutex_;
  std::atomic<bool> closed_{false};
  std::atomic<std::thread::id> owner_{};  // the thread inside read(), if any
  std::atomic<bool> stop_{false};
  std::chrono::steady_clock::time_point next_signal_check_{};
  std::unique_ptr<py::error_already_set> pending_;  // what a signal handler raised during the call
};

template <class F>
auto SharedLog::read(const char* what, F&& f) {
  using R = std::invoke_result_t<F&, const Log&>;
  std::optional<R> result;
  std::string no_memory;
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> lock = enter();
    try {
      result.emplace(f(*log_));
    } catch (const std::bad_alloc&) {
      no_memory = path() + ": " + what + ": not enough memory (an allocation failed; this process may still " +
                  "allocate about " + byte_text(double(allocatable_bytes())) + "): ask for less at a time";
    } catch (...) {
      failure = std::current_exception();
    }
    leave();
  }
  raise_pending();  // first: the user pressed Ctrl-C, whatever the call made of being stopped
  if (failure) std::rethrow_exception(failure);
  if (!no_memory.empty()) throw OutOfMemory(no_memory);
  return value_or_raise(std::move(*result));
}

}  // namespace ede::python
