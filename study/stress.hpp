// The stress study (ede-bench stress): the hard cases run long with every invariant checked as they go.
//
// Two scenes, built as scene text and run through the normal path (scene loader, setup, engine, log):
//   dense      elastic disks on a hexagonal lattice at packing fraction 0.8 in a periodic box;
//   inelastic  restitution 0.5 with the TC model at packing fraction 0.3 in a periodic box (inelastic
//              collapse would stall it without TC).
// Each runs its stop.events (10^7 unless overridden) in `checks` slices; after each: no pair overlaps
// beyond 1e-9 of its contact distance and no prediction lies in the past (check_invariants); the energy
// is constant to 1e-10 (dense) or never increases (inelastic); the momentum is constant (periodic boxes,
// any restitution). At the end the log is replayed and must give the engine's state bit for bit. CI runs
// it small (tests/tools/test_tool_ede_bench.cpp); by hand with 10^7 events or more (the README's
// reliability section). ede-bench prints the outcomes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ede::study {

struct StressPlan {
  std::uint64_t disks = 10000;
  std::uint64_t checks = 50;           // invariant checks per scene, evenly spaced in events
  std::vector<std::string> overrides;  // --set key=value on both scenes (stop.events: their length)
  std::string out_dir = "/tmp";        // where the logs go
  bool keep_logs = false;
};

struct StressOutcome {
  std::string scene, status, failure;  // failure: empty when every check passed
  std::uint64_t disks = 0, events = 0;
  double seconds = 0, largest_overlap = 0, energy_ratio = 1, worst_energy_drift = 0, momentum_drift = 0;
  double tc_share = 0;                 // TC-elastic collisions / collisions
  bool replay_exact = false;
};

// Both scenes, one after the other: dense, inelastic.
std::vector<StressOutcome> run_stress(const StressPlan& plan);

}  // namespace ede::study
