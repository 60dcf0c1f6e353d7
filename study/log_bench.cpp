// The event-log benchmark; see log_bench.hpp. One run, a log's shape and seeking are measured by the
// pieces of log_measure.hpp (shared with the accuracy study), each timed run in its own child process.
// Log sizes do not depend on timing (the writer's bytes are a function of the events), so they come from
// one run and are checked equal across repeats; times are medians over repeats, and within a repeat the
// configurations run one after the other, so a slow phase of a shared machine hits all of them alike
// and the per-repeat ratios (log on / log off) stay meaningful. The parent reads the logs afterwards
// (sizes, keyframe share, columns) and deletes them.
#include "study/log_bench.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "study/measurement.hpp"

namespace ede::study {

namespace {

constexpr std::uint64_t kFrequentKeyframes = 1u << 14;  // one keyframe per chunk of the default size

// Runs every configuration `repeat` times, interleaved; reads each log once (after its first run).
void run_series(std::vector<Series>& all, int repeat, int columns_level) {
  for (int k = 0; k < repeat; ++k) {
    for (Series& s : all) {
      if (!s.failure.empty()) continue;
      RunResult r = run_measured(s.config);
      if (!r.ok) {
        s.failure = r.failure;
        if (s.config.log) std::filesystem::remove(s.config.log_path);
        continue;
      }
      std::fprintf(stderr, "  %-28s run %d: %.3f s%s\n", s.config.label.c_str(), k + 1, r.wall,
                   s.config.log ? (", " + fmt(r.bytes / std::max(1.0, r.logged)) + " B/event").c_str() : "");
      if (s.config.log) {
        if (k == 0) {
          const bool columns = columns_level > 0 && s.config.settings.compression_level == columns_level;
          s.shape = read_shape(s.config.log_path, columns ? columns_level : 0);
          if (!s.shape.ok) s.failure = s.shape.failure;
        } else if (r.bytes != s.first().bytes) {
          s.sizes_differ = true;
        }
        std::filesystem::remove(s.config.log_path);
      }
      s.runs.push_back(r);
    }
  }
}

Series series(const LogBenchPlan& p, const std::string& label, const std::string& scene, bool log,
              const LogSettings& settings) {
  Series s;
  RunConfig& c = s.config;
  c.label = label;
  c.scene = scene;
  c.overrides = p.overrides;
  c.log = log;
  c.settings = settings;
  c.log_path = p.tmp_dir + "/" + label + ".ede";
  return s;
}

SeekRow seek_row(const LogBenchPlan& p, std::uint64_t interval, bool rebuilds) {
  LogSettings settings;
  settings.keyframe_interval = interval;
  settings.format_version = p.format_version;
  RunConfig c = series(p, "seek-" + power_of_two(interval) + (rebuilds ? "-rebuilds" : ""), p.reference, true,
                       settings).config;
  c.events = p.seek_events;
  if (!rebuilds) c.overrides.push_back(kNoRebuilds);
  return seek_row(c, power_of_two(interval) + (rebuilds ? " (automatic rebuilds)" : ""), interval, rebuilds, p.repeat);
}

}  // namespace

double Series::median_of(double (*f)(const RunResult&)) const {
  std::vector<double> v;
  for (const RunResult& r : runs) v.push_back(f(r));
  return median(v);
}
double Series::wall() const { return median_of([](const RunResult& r) { return r.wall; }); }
double Series::cycles() const { return median_of([](const RunResult& r) { return r.cycles; }); }
double Series::cpu_process() const { return median_of([](const RunResult& r) { return r.cpu_process; }); }
double Series::cpu_main() const { return median_of([](const RunResult& r) { return r.cpu_main; }); }
double Series::cpu_worker() const { return median_of([](const RunResult& r) { return r.cpu_worker(); }); }

double wall_of(const RunResult& r) { return r.wall; }
double cpu_of(const RunResult& r) { return r.cpu_process; }

double paired_ratio(const Series& s, const Series& base, double (*f)(const RunResult&)) {
  std::vector<double> v;
  for (std::size_t k = 0; k < s.runs.size() && k < base.runs.size(); ++k)
    if (f(base.runs[k]) > 0) v.push_back(f(s.runs[k]) / f(base.runs[k]));
  return median(v);
}

bool LogBenchResults::ok() const {
  bool all = true;
  for (const auto* list : {&scenes, &ref, &sim})
    for (const Series& s : *list) all = all && s.failure.empty();
  for (const SeekRow& r : seeks) all = all && r.failure.empty();
  return all;
}

std::vector<std::string> default_log_bench_scenes() {
  return {"examples/bench/gas-N10000-phi0.5-periodic.toml", "examples/bench/gas-N10000-phi0.5-walls.toml",
          "examples/bench/gas-N10000-phi0.3-periodic.toml", "examples/bench/gas-N1000-phi0.5-periodic.toml"};
}

std::string default_log_bench_reference() { return "examples/bench/gas-N10000-phi0.5-periodic.toml"; }

Result<LogBenchResults> run_log_bench(const LogBenchPlan& p) {
  std::error_code ec;
  const bool made_dir = std::filesystem::create_directories(p.tmp_dir, ec);
  if (ec) return Error{"cannot create " + p.tmp_dir + ": " + ec.message()};
  LogSettings defaults;
  defaults.format_version = p.format_version;
  LogBenchResults res;

  // 1. Scenes: log off and on (default settings).
  for (const std::string& path : p.scenes) {
    const std::string label = scene_label(path);
    res.scenes.push_back(series(p, label + "-off", path, false, defaults));
    res.scenes.push_back(series(p, label + "-on", path, true, defaults));
  }
  std::fprintf(stderr, "ede-bench log: scenes\n");
  run_series(res.scenes, p.repeat, defaults.compression_level);

  // 2 and 3. The reference scene: log off, every level, and frequent keyframes.
  res.ref.push_back(series(p, "log off", p.reference, false, defaults));
  std::vector<int> level_list = p.levels;  // the default level always runs: the overhead table needs it
  if (std::find(level_list.begin(), level_list.end(), defaults.compression_level) == level_list.end())
    level_list.push_back(defaults.compression_level);
  for (const int level : level_list) {
    LogSettings s = defaults;
    s.compression_level = level;
    res.ref.push_back(series(p, "level-" + std::to_string(level), p.reference, true, s));
  }
  LogSettings frequent = defaults;
  frequent.keyframe_interval = kFrequentKeyframes;
  res.ref.push_back(series(p, "keyframes-2^14", p.reference, true, frequent));
  std::fprintf(stderr, "ede-bench log: levels and overhead (%s)\n", p.reference.c_str());
  run_series(res.ref, p.repeat, 0);

  // 4. Seeking: logs built once per keyframe interval, seeks repeated; and the simulation without a log.
  res.sim.push_back(series(p, "seek-run-off", p.reference, false, defaults));
  res.sim.back().config.events = p.seek_events;
  if (!p.skip_seek) {
    std::fprintf(stderr, "ede-bench log: seeking\n");
    run_series(res.sim, p.repeat, 0);
    for (const int k : {16, 18, 20, 22}) res.seeks.push_back(seek_row(p, std::uint64_t(1) << k, false));
    res.seeks.push_back(seek_row(p, defaults.keyframe_interval, true));
  }
  if (made_dir) std::filesystem::remove(p.tmp_dir, ec);  // only if empty; the logs are already gone
  return res;
}

}  // namespace ede::study
