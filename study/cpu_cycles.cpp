// CpuCycles through perf_event_open(2); see cpu_cycles.hpp.
#include "study/cpu_cycles.hpp"

#include <linux/perf_event.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstring>

namespace ede::study {

CpuCycles::CpuCycles() {
  perf_event_attr attr;
  std::memset(&attr, 0, sizeof attr);
  attr.type = PERF_TYPE_HARDWARE;
  attr.size = sizeof attr;
  attr.config = PERF_COUNT_HW_CPU_CYCLES;
  attr.disabled = 1;
  attr.exclude_kernel = 1;
  attr.exclude_hv = 1;
  fd_ = int(syscall(SYS_perf_event_open, &attr, 0, -1, -1, 0));
}

CpuCycles::~CpuCycles() {
  if (fd_ >= 0) close(fd_);
}

void CpuCycles::start() {
  if (fd_ < 0) return;
  ioctl(fd_, PERF_EVENT_IOC_RESET, 0);
  ioctl(fd_, PERF_EVENT_IOC_ENABLE, 0);
}

std::uint64_t CpuCycles::stop() {
  if (fd_ < 0) return 0;
  ioctl(fd_, PERF_EVENT_IOC_DISABLE, 0);
  std::uint64_t count = 0;
  if (read(fd_, &count, sizeof count) != sizeof count) return 0;
  return count;
}

}  // namespace ede::study
