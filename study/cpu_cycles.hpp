// User-mode CPU cycles of this process, from the kernel's perf events, when the machine allows it.
//
// Wall time on a shared machine moves with whatever else runs; cycles spent by this process in user mode
// do not (cache contention aside). Benchmarks report both. Where perf events are not available (some
// virtual machines, perf_event_paranoid) available() is false and the figure is reported as n/a.
#pragma once

#include <cstdint>

namespace ede::study {

class CpuCycles {
 public:
  CpuCycles();
  ~CpuCycles();
  CpuCycles(const CpuCycles&) = delete;
  CpuCycles& operator=(const CpuCycles&) = delete;

  bool available() const { return fd_ >= 0; }
  void start();
  std::uint64_t stop();  // cycles since start(), 0 if unavailable

 private:
  int fd_ = -1;
};

}  // namespace ede::study
