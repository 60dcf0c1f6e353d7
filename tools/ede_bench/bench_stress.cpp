// ede-bench stress [--set key=value]... [--disks N] [--checks N] [--out-dir DIR] [--keep-logs]: the hard
// cases run long with every invariant checked (study/stress.hpp); a Markdown table, status 1 if any check
// failed. Their length is their stop.events (10^7; --set stop.events=N).
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "study/measurement.hpp"
#include "study/stress.hpp"

namespace ede::bench {

namespace {

using study::fmt;

int stress(const study::StressPlan& plan) {
  const std::vector<study::StressOutcome> results = study::run_stress(plan);
  std::printf("| scene | N | events | wall s | M events/s | largest overlap | energy | momentum drift | "
              "TC-elastic | log replay | result |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n");
  int status = 0;
  for (const study::StressOutcome& r : results) {
    const std::string energy = r.scene == "dense" ? "drift " + fmt(r.worst_energy_drift, 2)
                                                  : "E/E0 = " + fmt(r.energy_ratio, 3) + ", never rose";
    std::printf("| %s | %llu | %llu | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.scene.c_str(),
                static_cast<unsigned long long>(r.disks), static_cast<unsigned long long>(r.events),
                fmt(r.seconds).c_str(), fmt(r.seconds > 0 ? double(r.events) / r.seconds / 1e6 : 0).c_str(),
                fmt(r.largest_overlap, 2).c_str(), energy.c_str(), fmt(r.momentum_drift, 2).c_str(),
                (fmt(100 * r.tc_share, 2) + " %").c_str(), r.replay_exact ? "bit-exact" : "-",
                r.failure.empty() ? ("ok (" + r.status + ")").c_str() : ("FAILED: " + r.failure).c_str());
    if (!r.failure.empty()) status = 1;
  }
  return status;
}

}  // namespace

Command stress_command(CLI::App& app) {
  auto plan = std::make_shared<study::StressPlan>();
  CLI::App* st = app.add_subcommand("stress", "hard cases run long with every invariant checked");
  add_set_option(st, plan->overrides);
  st->add_option("--disks", plan->disks, "disks per scene (default 10^4)");
  st->add_option("--checks", plan->checks, "invariant checks per scene (default 50)")->check(CLI::Range(1, 100000));
  st->add_option("--out-dir", plan->out_dir, "where the logs go (default /tmp)");
  st->add_flag("--keep-logs", plan->keep_logs, "keep the logs");
  return {st, [plan] { return stress(*plan); }};
}

}  // namespace ede::bench
