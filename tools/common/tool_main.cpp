// run_tool and the memory messages; see tool_main.hpp.
#include "tool_main.hpp"

#include <malloc.h>
#include <sys/resource.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>

#include "ede/error.hpp"
#include "ede/simulation.hpp"
#include "report_error.hpp"

namespace ede::tools {

namespace {

std::string mib(std::uint64_t bytes) { return std::to_string((bytes + (1u << 19)) >> 20) + " MiB"; }

std::uint64_t address_space_limit() {
  struct rlimit r {};
  if (::getrlimit(RLIMIT_AS, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return 0;
  return std::uint64_t(r.rlim_cur);
}

std::uint64_t machine_available() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::uint64_t kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return 0;
}

int check_stdout(const char* tool, int status) {
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    report_error(tool, std::string("error while writing <stdout>: ") + std::strerror(errno ? errno : EIO) +
                           "; the output is incomplete");
    return status == 0 ? 1 : status;
  }
  return status;
}

}  // namespace

std::uint64_t memory_available_bytes() {
  const std::uint64_t a = address_space_limit(), b = machine_available();
  if (a == 0) return b;
  if (b == 0) return a;
  return a < b ? a : b;
}

std::string out_of_memory_message(const std::string& doing) {
  std::string m = "out of memory while " + doing + " (the process had reached " + mib(peak_rss_bytes()) + " resident";
  if (const std::uint64_t as = address_space_limit()) m += "; its address-space limit, ulimit -v, is " + mib(as);
  if (const std::uint64_t av = machine_available()) m += "; the machine has " + mib(av) + " available";
  return m + "). Fix: run fewer disks, raise the limit, or free memory.";
}

// glibc raises its mmap threshold to the size of any large block freed (up to 32 MiB), so after setup frees
// its placement arrays every later array below that size comes from the heap and stays in the process
// when freed: at N = 1e6 with the log, ~54 B/disk of ede-sim's peak RSS was such memory (268 B/disk with
// glibc's defaults, 216 with these). Fixed thresholds turn the adjustment off: blocks above 2 MiB (the
// engine's and the log's per-disk arrays, keyframes) are mapped and returned on free; the heap keeps up to
// 8 MiB free at its top, so the log's ~1 MB chunk buffers are reused without a system call (N = 1e4 with
// the log: the same wall time, interleaved). Set in the tools only: a program using the library keeps its own.
void fix_malloc_thresholds() {
  ::mallopt(M_MMAP_THRESHOLD, 2 << 20);
  ::mallopt(M_TRIM_THRESHOLD, 8 << 20);
}

int run_tool(const char* tool, int (*body)(int, char**), int argc, char** argv) {
  fix_malloc_thresholds();
  int status = 1;
  try {
    status = body(argc, argv);
  } catch (const std::bad_alloc&) {
    report_error(tool, out_of_memory_message("running"));
    status = 1;
  } catch (const ede::Exception& e) {
    report_error(tool, e.what());
    status = 1;
  } catch (const std::exception& e) {
    report_error(tool, std::string("internal error: ") + e.what() + " (please report it with the command line)");
    status = 1;
  }
  return check_stdout(tool, status);
}

}  // namespace ede::tools
