// run_tool and the memory messages; see tool_main.hpp.
#include "tool_main.hpp"

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

int run_tool(const char* tool, int (*body)(int, char**), int argc, char** argv) {
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
