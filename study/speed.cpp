// The speed benchmark; see speed.hpp.
#include "study/speed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "ede/internal/run.hpp"
#include "study/measurement.hpp"
#include "study/timed_run.hpp"

namespace ede::study {

namespace {

// The child's side: load, set up, run, report key=value pairs. `events` (0: none) comes after the
// plan's overrides: the baseline's budget.
int measure_in_child(const std::string& path, const SpeedPlan& plan, std::uint64_t events, Algorithm algorithm,
                     std::string& out) {
  std::vector<Override> overrides = as_overrides(plan.overrides);
  if (events) overrides.push_back({"stop.events=" + std::to_string(events)});
  const auto t0 = std::chrono::steady_clock::now();
  auto scene = load_scene_file(path, overrides);
  if (!scene) return out = scene.error().message, 1;
  auto planned = plan_run(scene.value());
  if (!planned) return out = planned.error().message, 1;
  const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  planned.value().options.algorithm = algorithm;
  const std::size_t disks = planned.value().initial.size();
  return with_engine_scalar(scene.value().scalar, [&]<class T>() {
    auto run = start_run<T>(planned.value());
    if (!run) return out = run.error().message, 1;
    std::ostringstream o;
    o.precision(17);
    o << timed_run_report(*run.value().engine) << " disks=" << disks << " setup=" << setup;
    out = o.str();
    return 0;
  });
}

SpeedMeasurement measure(const std::string& path, const SpeedPlan& plan, std::uint64_t events, Algorithm algorithm) {
  const ChildMeasurement r =
      run_child_measurement([&](std::string& out) { return measure_in_child(path, plan, events, algorithm, out); });
  SpeedMeasurement m;
  m.ok = r.ok;
  m.failure = r.failure;
  if (!r.ok) return m;
  const KeyValues& kv = r.values;
  m.events = get(kv, "events");
  m.collisions = get(kv, "collisions");
  m.wall = get(kv, "wall");
  m.cycles = get(kv, "cycles");
  m.engine_bytes = get(kv, "engine_bytes");
  m.disks = get(kv, "disks");
  m.setup = get(kv, "setup");
  m.peak_rss = r.peak_rss;
  return m;
}

}  // namespace

SpeedRow measure_speed(const std::string& path, const SpeedPlan& plan) {
  SpeedRow row;
  row.scene = scene_label(path);
  std::vector<SpeedMeasurement> runs;
  for (int k = 0; k < plan.repeat; ++k) {
    SpeedMeasurement m = measure(path, plan, 0, Algorithm::Cells);
    if (!m.ok) {
      row.typical = m;
      return row;
    }
    std::fprintf(stderr, "  %s run %d: %.3g M events/s\n", row.scene.c_str(), k + 1, m.events_per_second() / 1e6);
    runs.push_back(m);
  }
  std::vector<double> eps, cps, cyc;
  for (const SpeedMeasurement& m : runs) {
    eps.push_back(m.events_per_second());
    cps.push_back(m.wall > 0 ? m.collisions / m.wall : 0);
    cyc.push_back(m.events > 0 ? m.cycles / m.events : 0);
  }
  row.events_per_second = median(eps);
  row.collisions_per_second = median(cps);
  row.cycles_per_event = median(cyc);
  row.ns_per_event = row.events_per_second > 0 ? 1e9 / row.events_per_second : 0;
  row.typical = *std::min_element(runs.begin(), runs.end(), [&](const SpeedMeasurement& a, const SpeedMeasurement& b) {
    return std::abs(a.events_per_second() - row.events_per_second) <
           std::abs(b.events_per_second() - row.events_per_second);
  });
  const double n = row.typical.disks;
  if (n > double(plan.baseline_max_disks)) {
    row.baseline_note = "skipped: O(N^2) start";
    return row;
  }
  // All-pairs costs ~N x 12 ns per event on this kind of machine: a budget of ~baseline_seconds.
  const double budget = std::max(1000.0, plan.baseline_seconds / (12e-9 * n));
  const std::uint64_t events = std::uint64_t(std::min(budget, row.typical.events));
  const SpeedMeasurement b = measure(path, plan, events, Algorithm::AllPairs);
  row.baseline_run = b.ok;
  row.baseline_note = b.ok ? "" : b.failure;
  row.baseline_events_per_second = b.events_per_second();
  row.baseline_events = b.events;
  return row;
}

}  // namespace ede::study
