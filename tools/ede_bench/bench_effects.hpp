// ede-bench effects: what each physical effect costs per event, and what specializing the engine for a
// scene's effects saves (see bench_effects.cpp).
#pragma once

#include <cstdint>
#include <string>

namespace ede::bench {

struct EffectsOptions {
  std::string scene = "examples/bench/effects/gas-two-species.toml";
  int repeat = 5;
  std::uint64_t events = 2000000;  // engine events per run
  std::string csv_path;
};

int run_effects(const EffectsOptions& options);

}  // namespace ede::bench
