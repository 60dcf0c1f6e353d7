// ede-bench accuracy, the engine part: for one setting on one scene, the cost (ns per event) and the
// errors a long elastic run leaves: the energy drift and the largest overlap; then the log's bytes per
// event for that scalar type.
//
// One timed child per repeat runs `plan.events` engine events in `plan.checkpoints` slices; only the
// run() calls are timed. Between slices (untimed) the energy, summed in a type wider than the run's
// (Wide<T>), is compared with the initial one, and EngineApi::largest_overlap() is read. The errors are
// deterministic, so they come from the first repeat and the others must agree (repeats_agree); the time
// is the median. Rejected: reading the drift from a sampled observer (the samples would be events in the
// timed loop) or from the engine's own double energy (it rounds away the drift of a long double run).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "accuracy_parts.hpp"
#include "bench_common.hpp"
#include "log_measure.hpp"

namespace ede::bench {

namespace {

// Enough for bytes per event to settle (keyframes included) without writing gigabytes per setting.
constexpr std::uint64_t kLogBytesEvents = 4000000;

template <class T>
int engine_child(const StudyScene& s, const StudyPlan& plan, std::string& out) {
  EngineOptions options = s.options;
  options.stop = StopSpec{};
  options.stop.events = plan.events;
  auto made = make_engine<T>(s.initial, options);
  if (!made) return out = made.error().message, 1;
  EngineApi<T>& engine = *made.value();
  const auto e0 = kinetic_energy_wide(engine.particles());
  const std::uint64_t slice = std::max<std::uint64_t>(1, plan.events / std::uint64_t(plan.checkpoints));
  double seconds = 0, drift = 0, drift_max = 0, overlap = 0;
  RunStatus status = RunStatus::Running;
  while (status == RunStatus::Running && engine.counts().events() < plan.events) {
    const auto t0 = std::chrono::steady_clock::now();
    status = engine.run(std::min(slice, plan.events - engine.counts().events()));
    seconds += seconds_since(t0);
    drift = relative_change(kinetic_energy_wide(engine.particles()), e0);
    drift_max = std::max(drift_max, drift);
    overlap = std::max(overlap, engine.largest_overlap());
  }
  if (status == RunStatus::Stalled) return out = engine.stall_message(), 1;
  std::ostringstream o;
  o.precision(17);
  o << "disks=" << s.initial.size() << " events=" << engine.counts().events()
    << " collisions=" << engine.counts().collisions() << " seconds=" << seconds << " drift=" << drift
    << " drift_max=" << drift_max << " overlap=" << overlap;
  out = o.str();
  return 0;
}

ChildMeasurement run_engine_child(const StudyPlan& plan, const EngineRow& row) {
  return run_child_measurement([&](std::string& out) {
    auto s = load_study_scene(plan.scene(row.scene), row.setting);
    if (!s) return out = s.error().message, 1;
    return with_precision(row.setting.precision, [&]<class T>() { return engine_child<T>(s.value(), plan, out); });
  });
}

void measure_log_bytes(const StudyPlan& plan, EngineRow& row) {
  if (!has_log(row.setting.precision)) return;
  RunConfig c;
  c.label = row.scene + "-" + precision_name(row.setting.precision);
  c.scene = plan.scene(row.scene);
  c.events = std::min(plan.events, kLogBytesEvents);
  c.overrides.push_back(scalar_override(row.setting.precision));
  c.contact = row.setting.contact;
  c.log = true;
  c.log_path = plan.tmp_dir + "/accuracy-" + std::to_string(::getpid()) + ".ede";
  const RunResult r = run_measured(c);
  std::filesystem::remove(c.log_path);
  if (!r.ok) row.failure = "log run: " + r.failure;
  else if (r.logged > 0) row.log_bytes_per_event = r.bytes / r.logged;
}

}  // namespace

const std::vector<std::string>& engine_scenes() {
  static const std::vector<std::string> names = {"gas", "dense", "crystal"};
  return names;
}

void measure_engine(const StudyPlan& plan, EngineRow& row) {
  std::vector<double> ns;
  for (int k = 0; k < plan.repeat && row.failure.empty(); ++k) {
    const ChildMeasurement m = run_engine_child(plan, row);
    if (!m.ok) {
      row.failure = m.failure;
      break;
    }
    const KeyValues& kv = m.values;
    if (k == 0) {
      row.disks = get(kv, "disks"), row.events = get(kv, "events"), row.collisions = get(kv, "collisions");
      row.drift = get(kv, "drift"), row.drift_max = get(kv, "drift_max"), row.overlap = get(kv, "overlap");
    } else if (get(kv, "drift") != row.drift || get(kv, "overlap") != row.overlap) {
      row.repeats_agree = false;
    }
    ns.push_back(1e9 * get(kv, "seconds") / std::max(1.0, get(kv, "events")));
    std::fprintf(stderr, "  %-8s %-26s run %d: %.0f ns/event, drift %.3g\n", row.scene.c_str(),
                 row.setting.label().c_str(), k + 1, ns.back(), get(kv, "drift"));
  }
  row.ns_per_event = median(ns);
  if (row.failure.empty()) measure_log_bytes(plan, row);
}

}  // namespace ede::bench
