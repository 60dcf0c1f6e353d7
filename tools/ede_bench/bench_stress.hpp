// ede-bench stress: the hard cases run long with every invariant checked (see bench_stress.cpp).
#pragma once

#include <cstdint>
#include <string>

namespace ede::bench {

struct StressOptions {
  std::uint64_t events = 10000000;  // engine events per scene
  std::uint64_t disks = 10000;
  std::uint64_t checks = 50;        // invariant checks per scene, evenly spaced in events
  std::string out_dir = "/tmp";     // where the logs go
  bool keep_logs = false;
};

int run_stress(const StressOptions& options);

}  // namespace ede::bench
