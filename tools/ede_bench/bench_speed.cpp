// The speed benchmark; see bench_speed.hpp. Each measurement runs in its own child process (clean heap,
// its own peak RSS); only the event loop is timed (scene loading and placement are not the engine's cost).
// Wall-clock figures are medians over the repeats; cycles come from perf events when available, which
// the other jobs on a shared machine disturb much less than wall time.
#include "bench_speed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "bench_common.hpp"
#include "cpu_cycles.hpp"
#include "engine/engine.hpp"
#include "ede/scene.hpp"
#include "setup/setup.hpp"
#include "core/scalar_dispatch.hpp"
#include "timed_run.hpp"

namespace ede::bench {

namespace {

struct Measurement {
  bool ok = false;
  std::string failure;
  double events = 0, collisions = 0, wall = 0, cycles = 0, engine_bytes = 0, disks = 0, setup = 0;
  double peak_rss = 0;
  double events_per_second() const { return wall > 0 ? events / wall : 0; }
};

// The child's side: load, set up, run, report key=value pairs.
int measure_in_child(const std::string& path, std::uint64_t events, Algorithm algorithm, std::string& out) {
  std::vector<Override> overrides;
  if (events) overrides.push_back({"stop.events=" + std::to_string(events)});
  const auto t0 = std::chrono::steady_clock::now();
  auto scene = load_scene_file(path, overrides);
  if (!scene) return out = scene.error().message, 1;
  auto initial = build_initial_state(scene.value());
  if (!initial) return out = initial.error().message, 1;
  const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EngineOptions options = engine_options_from(scene.value(), initial.value().size());
  options.algorithm = algorithm;
  return with_engine_scalar(scene.value().scalar, [&]<class T>() {
    auto made = make_engine<T>(initial.value(), options);
    if (!made) return out = made.error().message, 1;
    std::ostringstream o;
    o.precision(17);
    o << tools::timed_run_report(*made.value()) << " disks=" << initial.value().size() << " setup=" << setup;
    out = o.str();
    return 0;
  });
}

Measurement measure(const std::string& path, std::uint64_t events, Algorithm algorithm) {
  const ChildMeasurement r =
      run_child_measurement([&](std::string& out) { return measure_in_child(path, events, algorithm, out); });
  Measurement m;
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

struct Row {
  std::string scene;
  Measurement typical;  // the repeat with the median events/s
  double events_per_second = 0, collisions_per_second = 0, ns_per_event = 0, cycles_per_event = 0;
  bool baseline_run = false;
  std::string baseline_note;
  double baseline_events_per_second = 0;
  double baseline_events = 0;
};

Row bench_scene(const std::string& path, const SpeedOptions& o) {
  Row row;
  row.scene = scene_label(path);
  std::vector<Measurement> runs;
  for (int k = 0; k < o.repeat; ++k) {
    Measurement m = measure(path, o.events, Algorithm::Cells);
    if (!m.ok) {
      row.typical = m;
      return row;
    }
    std::fprintf(stderr, "  %s run %d: %.3g M events/s\n", row.scene.c_str(), k + 1, m.events_per_second() / 1e6);
    runs.push_back(m);
  }
  std::vector<double> eps, cps, cyc;
  for (const Measurement& m : runs) {
    eps.push_back(m.events_per_second());
    cps.push_back(m.wall > 0 ? m.collisions / m.wall : 0);
    cyc.push_back(m.events > 0 ? m.cycles / m.events : 0);
  }
  row.events_per_second = median(eps);
  row.collisions_per_second = median(cps);
  row.cycles_per_event = median(cyc);
  row.ns_per_event = row.events_per_second > 0 ? 1e9 / row.events_per_second : 0;
  row.typical = *std::min_element(runs.begin(), runs.end(), [&](const Measurement& a, const Measurement& b) {
    return std::abs(a.events_per_second() - row.events_per_second) <
           std::abs(b.events_per_second() - row.events_per_second);
  });
  const double n = row.typical.disks;
  if (n > double(o.baseline_max_disks)) {
    row.baseline_note = "skipped: O(N^2) start";
    return row;
  }
  // All-pairs costs ~N x 12 ns per event on this kind of machine: a budget of ~baseline_seconds.
  const double budget = std::max(1000.0, o.baseline_seconds / (12e-9 * n));
  const std::uint64_t events = std::uint64_t(std::min(budget, row.typical.events));
  const Measurement b = measure(path, events, Algorithm::AllPairs);
  row.baseline_run = b.ok;
  row.baseline_note = b.ok ? "" : b.failure;
  row.baseline_events_per_second = b.events_per_second();
  row.baseline_events = b.events;
  return row;
}

void print_table(const std::vector<Row>& rows, bool have_cycles) {
  std::printf("| scene | N | events | M events/s | M collisions/s | ns/event | %s B/disk (engine) | "
              "peak RSS B/disk | all-pairs M events/s | speed-up |\n",
              have_cycles ? "cycles/event |" : "");
  std::printf("|---|---:|---:|---:|---:|---:|%s---:|---:|---:|---:|\n", have_cycles ? "---:|" : "");
  for (const Row& r : rows) {
    if (!r.typical.ok) {
      std::printf("| %s | failed: %s |\n", r.scene.c_str(), r.typical.failure.c_str());
      continue;
    }
    const double n = r.typical.disks;
    std::string baseline = r.baseline_note, speedup = "";
    if (r.baseline_run) {
      baseline = fmt(r.baseline_events_per_second / 1e6) + " (" + fmt(r.baseline_events, 2) + " ev)";
      speedup = fmt(r.events_per_second / r.baseline_events_per_second) + "x";
    }
    std::printf("| %s | %.0f | %.3g | %s | %s | %s | %s%s | %s | %s | %s |\n", r.scene.c_str(), n, r.typical.events,
                fmt(r.events_per_second / 1e6).c_str(), fmt(r.collisions_per_second / 1e6).c_str(),
                fmt(r.ns_per_event).c_str(), have_cycles ? (fmt(r.cycles_per_event, 4) + " | ").c_str() : "",
                fmt(r.typical.engine_bytes / n).c_str(), fmt(r.typical.peak_rss / n).c_str(), baseline.c_str(),
                speedup.c_str());
  }
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "ede-bench: warning: cannot write %s\n", path.c_str());
    return;
  }
  std::fprintf(f, "scene,disks,events,events_per_second,collisions_per_second,ns_per_event,cycles_per_event,"
                  "engine_bytes_per_disk,peak_rss_bytes_per_disk,allpairs_events_per_second,allpairs_events\n");
  for (const Row& r : rows) {
    if (!r.typical.ok) continue;
    const double n = r.typical.disks;
    std::fprintf(f, "%s,%.0f,%.0f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.0f\n", r.scene.c_str(), n, r.typical.events,
                 r.events_per_second, r.collisions_per_second, r.ns_per_event, r.cycles_per_event,
                 r.typical.engine_bytes / n, r.typical.peak_rss / n, r.baseline_events_per_second, r.baseline_events);
  }
  std::fclose(f);
}

}  // namespace

int run_speed(const SpeedOptions& o) {
  std::vector<Row> rows;
  for (const std::string& path : o.scenes) {
    std::fprintf(stderr, "ede-bench speed: %s\n", path.c_str());
    rows.push_back(bench_scene(path, o));
  }
  tools::CpuCycles probe;
  std::printf("Medians of %d runs per scene (cell engine); the all-pairs baseline runs once with a budget of "
              "~%.3g s.\n\n",
              o.repeat, o.baseline_seconds);
  print_table(rows, probe.available());
  if (!o.csv_path.empty()) write_csv(o.csv_path, rows);
  for (const Row& r : rows)
    if (!r.typical.ok) return 1;
  return 0;
}

}  // namespace ede::bench
