// The event-log benchmark; see bench_log.hpp.
//
// Every timed measurement runs in its own child process (run_in_child: a clean heap, and the log writer's
// second thread is the child's own, so getrusage(RUSAGE_SELF) in the child is the CPU time of exactly
// one run's two threads). Only the event loop is timed, writer start-up and scene setup are not; the
// writer's final flush is inside the loop's last call (on_finish), so the time to drain its queue counts.
// Log sizes do not depend on timing (the writer's bytes are a function of the events), so they come from
// one run and are checked equal across repeats; times are medians over repeats, and within a repeat the
// configurations run one after the other, so a slow phase of a shared machine hits all of them alike
// and the per-repeat ratios (log on / log off) stay meaningful. The parent reads the logs afterwards
// (sizes, keyframe share, columns) and deletes them.
// Rejected: timing `ede-sim -o` from outside (progress, summary and setup get mixed in, and the worker
// thread's CPU time is not separable from the main thread's).
#include "bench_log.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "bench_common.hpp"
#include "cpu_cycles.hpp"
#include "ede/engine.hpp"
#include "ede/log_column_sizes.hpp"
#include "ede/log_reader.hpp"
#include "ede/log_writer.hpp"
#include "ede/replay.hpp"
#include "ede/scene_loader.hpp"
#include "ede/setup.hpp"
#include "scalar_dispatch.hpp"

namespace ede::bench {

namespace {

constexpr int kSeekTimes = 20;
constexpr std::uint64_t kFrequentKeyframes = 1u << 14;  // one keyframe per chunk of the default size
constexpr const char* kNoRebuilds = "engine.rebuild_interval=1099511627776";  // 2^40: only the one at start

// ---------------------------------------------------------------------------------------------- helpers

std::string percent(double ratio) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.1f %%", 100 * (ratio - 1));
  return buf;
}

std::string share(double part, double whole) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", whole > 0 ? 100 * part / whole : 0.0);
  return buf;
}

std::string mib(double bytes) { return fmt(bytes / 1048576, 4); }

std::string power_of_two(std::uint64_t v) {
  int k = 0;
  while ((std::uint64_t(1) << k) < v) ++k;
  return (std::uint64_t(1) << k) == v ? "2^" + std::to_string(k) : std::to_string(v);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct CpuTimes {
  double process = 0, thread = 0;  // user + system seconds: all threads, the calling thread
};

CpuTimes cpu_times() {
  const auto seconds = [](const rusage& u) {
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  };
  rusage self{}, thread{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_THREAD, &thread);
  return {seconds(self), seconds(thread)};
}

// ------------------------------------------------------------------------------------- one timed run

struct RunConfig {
  std::string label;
  std::string scene;
  std::uint64_t events = 0;            // stop.events override (0: the scene's)
  std::vector<std::string> overrides;  // more scene overrides
  bool log = false;
  LogSettings settings;
  std::string log_path;
};

struct RunResult {
  bool ok = false;
  std::string failure;
  double disks = 0, events = 0, collisions = 0, logged = 0, bytes = 0, sim_time = 0;
  double wall = 0, cycles = 0, cpu_process = 0, cpu_main = 0;
  double cpu_worker() const { return std::max(0.0, cpu_process - cpu_main); }
};

template <class T>
int timed_run(const RunConfig& c, const Scene& scene, const InitialState& initial, const EngineOptions& options,
              std::string& out) {
  auto made = make_engine<T>(initial, options);
  if (!made) return out = made.error().message, 1;
  EngineApi<T>& engine = *made.value();
  std::unique_ptr<LogWriter<T>> log;
  if (c.log) {
    auto w = LogWriter<T>::create(c.log_path, LogRunInfo::from(scene, options, initial.species_names), c.settings);
    if (!w) return out = w.error().message, 1;
    log = std::move(w).value();
    engine.add_sink(log.get());
  }
  tools::CpuCycles cycles;
  const CpuTimes cpu0 = cpu_times();
  cycles.start();
  const auto start = std::chrono::steady_clock::now();
  engine.run();
  const double wall = seconds_since(start);
  const std::uint64_t cyc = cycles.stop();
  const CpuTimes cpu1 = cpu_times();
  if (log && !log->error().empty()) return out = "the log failed: " + log->error(), 1;
  const EventCounts& n = engine.counts();
  std::ostringstream o;
  o.precision(17);
  o << "disks=" << initial.size() << " events=" << n.events() << " collisions=" << n.collisions()
    << " logged=" << (log ? log->events_logged() : 0) << " bytes=" << (log ? log->bytes_written() : 0)
    << " sim_time=" << double(engine.time()) << " wall=" << wall << " cycles=" << cyc
    << " cpu_process=" << cpu1.process - cpu0.process << " cpu_main=" << cpu1.thread - cpu0.thread;
  out = o.str();
  return 0;
}

int run_child(const RunConfig& c, std::string& out) {
  std::vector<Override> overrides;
  if (c.events) overrides.push_back({"stop.events=" + std::to_string(c.events)});
  for (const std::string& s : c.overrides) overrides.push_back({s});
  auto scene = load_scene_file(c.scene, overrides);
  if (!scene) return out = scene.error().message, 1;
  auto initial = build_initial_state(scene.value());
  if (!initial) return out = initial.error().message, 1;
  const EngineOptions options = engine_options_from(scene.value(), initial.value().size());
  if (scene.value().scalar == ScalarKind::Float128)
    return out = c.scene + ": float128 runs write no event log (the log format holds float, double and long "
                           "double); benchmark them with ede-bench speed",
           1;
  return tools::with_scalar(scene.value().scalar, [&]<class T>() {
    return timed_run<T>(c, scene.value(), initial.value(), options, out);
  });
}

RunResult run_measured(const RunConfig& c) {
  const ChildMeasurement r = run_child_measurement([&](std::string& out) { return run_child(c, out); });
  RunResult m;
  m.ok = r.ok;
  m.failure = r.failure;
  if (!r.ok) return m;
  const KeyValues& kv = r.values;
  m.disks = get(kv, "disks"), m.events = get(kv, "events"), m.collisions = get(kv, "collisions");
  m.logged = get(kv, "logged"), m.bytes = get(kv, "bytes"), m.sim_time = get(kv, "sim_time");
  m.wall = get(kv, "wall"), m.cycles = get(kv, "cycles");
  m.cpu_process = get(kv, "cpu_process"), m.cpu_main = get(kv, "cpu_main");
  return m;
}

// ------------------------------------------------------------------------------ what a log is made of

struct LogShape {
  bool ok = false;
  std::string failure;
  double file_bytes = 0, events = 0, chunks = 0, chunk_payload = 0;
  double keyframes = 0, resumable_keyframes = 0, keyframe_payload = 0;
  LogColumnSizes columns;  // filled when asked for
};

LogShape read_shape(const std::string& path, int columns_level) {
  LogShape s;
  auto log = LogReader::open(path);
  if (!log) return s.failure = log.error().message, s;
  const LogReader& r = *log.value();
  if (!r.complete()) return s.failure = path + ": incomplete log: " + r.incomplete_reason(), s;
  s.file_bytes = double(r.file_size());
  s.events = double(r.total_events());
  s.chunks = double(r.chunks().size());
  for (const LogRecordRef& c : r.chunks()) s.chunk_payload += double(c.payload_size);
  s.keyframes = double(r.keyframes().size());
  for (const LogRecordRef& k : r.keyframes()) {
    s.keyframe_payload += double(k.payload_size);
    s.resumable_keyframes += k.resumable ? 1 : 0;
  }
  if (columns_level > 0) {
    auto cols = log_column_sizes(r, columns_level);
    if (!cols) return s.failure = cols.error().message, s;
    s.columns = std::move(cols).value();
  }
  s.ok = true;
  return s;
}

// ------------------------------------------------------------------ configurations run side by side

// The results of one configuration over the repeats, and the shape of its log.
struct Series {
  RunConfig config;
  std::vector<RunResult> runs;
  LogShape shape;
  std::string failure;
  bool sizes_differ = false;

  bool ok() const { return failure.empty() && !runs.empty(); }
  const RunResult& first() const { return runs.front(); }
  double med(double (*f)(const RunResult&)) const {
    std::vector<double> v;
    for (const RunResult& r : runs) v.push_back(f(r));
    return median(v);
  }
  double wall() const { return med([](const RunResult& r) { return r.wall; }); }
  double cycles() const { return med([](const RunResult& r) { return r.cycles; }); }
  double cpu_process() const { return med([](const RunResult& r) { return r.cpu_process; }); }
  double cpu_main() const { return med([](const RunResult& r) { return r.cpu_main; }); }
  double cpu_worker() const { return med([](const RunResult& r) { return r.cpu_worker(); }); }
};

// The median over repeats of (this run / the baseline's run of the same repeat).
double paired_ratio(const Series& s, const Series& base, double (*f)(const RunResult&)) {
  std::vector<double> v;
  for (std::size_t k = 0; k < s.runs.size() && k < base.runs.size(); ++k)
    if (f(base.runs[k]) > 0) v.push_back(f(s.runs[k]) / f(base.runs[k]));
  return median(v);
}

double wall_of(const RunResult& r) { return r.wall; }
double cpu_of(const RunResult& r) { return r.cpu_process; }

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

RunConfig config(const std::string& label, const std::string& scene, std::uint64_t events, bool log,
                 const LogSettings& settings, const std::string& out_dir) {
  RunConfig c;
  c.label = label;
  c.scene = scene;
  c.events = events;
  c.log = log;
  c.settings = settings;
  c.log_path = out_dir + "/" + label + ".ede";
  return c;
}

Series series_of(RunConfig c) {
  Series s;
  s.config = std::move(c);
  return s;
}

void print_failures(const std::vector<Series>& all) {
  for (const Series& s : all) {
    if (!s.failure.empty()) std::printf("\n**%s failed**: %s\n", s.config.label.c_str(), s.failure.c_str());
    if (s.sizes_differ) std::printf("\n**%s: the log size differed between repeats** (expected identical)\n",
                                    s.config.label.c_str());
  }
}

std::FILE* open_csv(const std::string& prefix, const char* what) {
  if (prefix.empty()) return nullptr;
  const std::string path = prefix + "-" + what + ".csv";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) std::fprintf(stderr, "ede-bench: warning: cannot write %s\n", path.c_str());
  return f;
}

// ------------------------------------------------------------------------- 1. bytes per event, scenes

struct ScenePair {
  std::string label;
  Series* off;
  Series* on;
};

void print_scenes(const std::vector<ScenePair>& pairs, const std::string& csv_prefix) {
  std::printf("### Bytes per event and overhead, by scene (default log settings)\n\n");
  std::printf("| scene | N | logged events | collisions | file MiB | B/logged event | B/collision | keyframes | "
              "keyframe share | M events/s (log off) | wall overhead | CPU overhead (both threads) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::FILE* csv = open_csv(csv_prefix, "scenes");
  if (csv)
    std::fprintf(csv, "scene,disks,logged_events,collisions,file_bytes,bytes_per_event,bytes_per_collision,keyframes,"
                      "keyframe_bytes,chunk_bytes,events_per_second_off,wall_ratio,cpu_ratio\n");
  for (const ScenePair& p : pairs) {
    if (!p.off->ok() || !p.on->ok()) continue;
    const RunResult& r = p.on->first();
    const LogShape& s = p.on->shape;
    const double eps = p.off->first().events / p.off->wall();
    const double wall_ratio = paired_ratio(*p.on, *p.off, wall_of), cpu_ratio = paired_ratio(*p.on, *p.off, cpu_of);
    std::printf("| %s | %.0f | %.4g | %.4g | %s | %s | %s | %.0f | %s | %s | %s | %s |\n", p.label.c_str(), r.disks,
                s.events, r.collisions, mib(s.file_bytes).c_str(), fmt(s.file_bytes / s.events).c_str(),
                fmt(s.file_bytes / r.collisions).c_str(), s.keyframes,
                share(s.keyframe_payload, s.keyframe_payload + s.chunk_payload).c_str(), fmt(eps / 1e6).c_str(),
                percent(wall_ratio).c_str(), percent(cpu_ratio).c_str());
    if (csv)
      std::fprintf(csv, "%s,%.0f,%.0f,%.0f,%.0f,%.6g,%.6g,%.0f,%.0f,%.0f,%.6g,%.6g,%.6g\n", p.label.c_str(), r.disks,
                   s.events, r.collisions, s.file_bytes, s.file_bytes / s.events, s.file_bytes / r.collisions,
                   s.keyframes, s.keyframe_payload, s.chunk_payload, eps, wall_ratio, cpu_ratio);
  }
  if (csv) std::fclose(csv);
  std::printf("\nKeyframe share: keyframe payloads / (keyframe + chunk payloads). Overheads: median over repeats of "
              "(log on / log off) in the same repeat; CPU is user + system time of both threads (getrusage).\n\n");
}

void print_columns(const std::vector<ScenePair>& pairs, const std::string& csv_prefix) {
  std::printf("### Where the bytes go (chunk columns, bytes per logged event)\n\n");
  std::printf("Each column of every chunk compressed alone at the log's level (an estimate of its share; the "
              "file compresses a chunk as one frame), then the chunks as stored, and the keyframes.\n\n");
  const auto& names = pairs.empty() ? std::vector<LogColumnSize>{} : pairs.front().on->shape.columns.columns;
  std::printf("| scene |");
  for (const LogColumnSize& c : names) std::printf(" %s |", c.name.c_str());
  std::printf(" columns alone, sum | chunks as stored | chunks decompressed | keyframes |\n|---|");
  for (std::size_t k = 0; k < names.size() + 4; ++k) std::printf("---:|");
  std::printf("\n");
  std::FILE* csv = open_csv(csv_prefix, "columns");
  if (csv) std::fprintf(csv, "scene,column,bytes,compressed_alone,events\n");
  for (const ScenePair& p : pairs) {
    if (!p.on->ok()) continue;
    const LogShape& s = p.on->shape;
    const LogColumnSizes& c = s.columns;
    if (c.events == 0) continue;
    const double ev = double(c.events);
    double alone = 0;
    std::printf("| %s |", p.label.c_str());
    for (const LogColumnSize& col : c.columns) {
      alone += double(col.compressed);
      std::printf(" %s (%s) |", fmt(double(col.compressed) / ev).c_str(), fmt(double(col.bytes) / ev).c_str());
      if (csv)
        std::fprintf(csv, "%s,%s,%.0f,%.0f,%.0f\n", p.label.c_str(), col.name.c_str(), double(col.bytes),
                     double(col.compressed), ev);
    }
    std::printf(" %s | %s | %s | %s |\n", fmt(alone / ev).c_str(), fmt(double(c.payload) / ev).c_str(),
                fmt(double(c.message) / ev).c_str(), fmt(s.keyframe_payload / s.events).c_str());
  }
  if (csv) std::fclose(csv);
  std::printf("\nIn each column cell: compressed alone (decompressed). velocitiesRaw holds v_i' of pair events "
              "as raw scalars; velocityResiduals the other velocities as residuals against momentum conservation "
              "(pairs) or reflection (walls).\n\n");
}

// -------------------------------------------------------------- 2 and 3. zstd level, logging overhead

void print_levels(const Series& off, const std::vector<Series*>& levels, const std::string& csv_prefix) {
  std::printf("### zstd level (%s)\n\n", scene_label(off.config.scene).c_str());
  std::printf("| level | file MiB | B/logged event | wall s | wall overhead | compressing thread CPU s | "
              "compressing ns/logged event | CPU overhead (both threads) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::FILE* csv = open_csv(csv_prefix, "levels");
  if (csv)
    std::fprintf(csv, "level,file_bytes,bytes_per_event,wall,wall_ratio,worker_cpu,worker_ns_per_event,cpu_ratio\n");
  for (const Series* s : levels) {
    if (!s->ok() || !off.ok()) continue;
    const double ev = s->shape.events, wall_ratio = paired_ratio(*s, off, wall_of);
    const double cpu_ratio = paired_ratio(*s, off, cpu_of);
    std::printf("| %d | %s | %s | %s | %s | %s | %s | %s |\n", s->config.settings.compression_level,
                mib(s->shape.file_bytes).c_str(), fmt(s->shape.file_bytes / ev).c_str(), fmt(s->wall()).c_str(),
                percent(wall_ratio).c_str(), fmt(s->cpu_worker()).c_str(), fmt(1e9 * s->cpu_worker() / ev).c_str(),
                percent(cpu_ratio).c_str());
    if (csv)
      std::fprintf(csv, "%d,%.0f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", s->config.settings.compression_level,
                   s->shape.file_bytes, s->shape.file_bytes / ev, s->wall(), wall_ratio, s->cpu_worker(),
                   1e9 * s->cpu_worker() / ev, cpu_ratio);
  }
  if (csv) std::fclose(csv);
  std::printf("\nThe compressing thread's CPU time is the process's (getrusage RUSAGE_SELF) minus the event loop "
              "thread's (RUSAGE_THREAD).\n\n");
}

std::string overhead_label(const Series& s) {
  if (!s.config.log) return "log off";
  const LogSettings& l = s.config.settings;
  return "log on: level " + std::to_string(l.compression_level) + ", keyframe every " +
         power_of_two(l.keyframe_interval) + " logged events";
}

void print_overhead(const std::vector<Series*>& rows, bool have_cycles) {
  const Series& off = *rows.front();
  std::printf("### Logging overhead (%s, %.3g engine events)\n\n", scene_label(off.config.scene).c_str(),
              off.ok() ? off.first().events : 0.0);
  std::printf("| configuration | B/logged event | keyframe share | wall s | wall overhead | %s"
              "event-loop thread CPU s | both threads CPU s | CPU overhead (both threads) |\n",
              have_cycles ? "event-loop cycles/event | " : "");
  std::printf("|---|---:|---:|---:|---:|%s---:|---:|---:|\n", have_cycles ? "---:|" : "");
  for (const Series* s : rows) {
    if (!s->ok() || !off.ok()) continue;
    const bool log = s->config.log;
    const double ev = s->first().events;
    const double kf_total = s->shape.keyframe_payload + s->shape.chunk_payload;
    std::printf("| %s | %s | %s | %s | %s | %s%s | %s | %s |\n", overhead_label(*s).c_str(),
                log ? fmt(s->shape.file_bytes / s->shape.events).c_str() : "–",
                log ? share(s->shape.keyframe_payload, kf_total).c_str() : "–",
                fmt(s->wall()).c_str(), log ? percent(paired_ratio(*s, off, wall_of)).c_str() : "–",
                have_cycles ? (fmt(s->cycles() / ev, 4) + " | ").c_str() : "", fmt(s->cpu_main()).c_str(),
                fmt(s->cpu_process()).c_str(), log ? percent(paired_ratio(*s, off, cpu_of)).c_str() : "–");
  }
  std::printf("\nCycles: user-mode cycles of the event-loop thread only (perf events); the compressing thread "
              "shows in the CPU-time columns.\n\n");
}

// ------------------------------------------------------------------------------------------- 4. seek

struct SeekResult {
  bool ok = false;
  std::string failure;
  double open = 0, replay_wall = 0, replay_events = 0;
  std::vector<double> create, seek;  // per seek time
};

template <class T>
int seek_child_typed(const std::shared_ptr<const LogReader>& log, double open_seconds, std::string& out) {
  std::ostringstream o;
  o.precision(17);
  o << "open=" << open_seconds;
  T t_end{};
  {
    auto probe = Replay<T>::create(log);
    if (!probe) return out = probe.error().message, 1;
    t_end = probe.value()->final_time();
  }
  for (int k = 0; k < kSeekTimes; ++k) {
    const T t = t_end * T(k + 0.37) / T(kSeekTimes);
    const auto t0 = std::chrono::steady_clock::now();
    auto replay = Replay<T>::create(log);
    if (!replay) return out = replay.error().message, 1;
    const double create = seconds_since(t0);
    const auto t1 = std::chrono::steady_clock::now();
    if (Status s = replay.value()->seek_time(t); !s) return out = s.error().message, 1;
    o << " create_" << k << "=" << create << " seek_" << k << "=" << seconds_since(t1);
  }
  auto replay = Replay<T>::create(log);
  if (!replay) return out = replay.error().message, 1;
  const auto t0 = std::chrono::steady_clock::now();
  const Status s = replay.value()->for_each_event(0, log->total_events(), [](const ReplayedEvent<T>&) { return true; });
  if (!s) return out = s.error().message, 1;
  o << " replay_wall=" << seconds_since(t0) << " replay_events=" << replay.value()->events_applied();
  out = o.str();
  return 0;
}

int seek_child(const std::string& path, std::string& out) {
  const auto t0 = std::chrono::steady_clock::now();
  auto log = LogReader::open(path);
  if (!log) return out = log.error().message, 1;
  const double open_seconds = seconds_since(t0);
  std::shared_ptr<const LogReader> reader = log.value();
  return tools::with_scalar(reader->header().scalar,
                            [&]<class T>() { return seek_child_typed<T>(reader, open_seconds, out); });
}

SeekResult measure_seeks(const std::string& path) {
  const ChildMeasurement r = run_child_measurement([&](std::string& out) { return seek_child(path, out); });
  SeekResult m;
  m.ok = r.ok;
  m.failure = r.failure;
  if (!r.ok) return m;
  const KeyValues& kv = r.values;
  m.open = get(kv, "open");
  m.replay_wall = get(kv, "replay_wall");
  m.replay_events = get(kv, "replay_events");
  for (int k = 0; k < kSeekTimes; ++k) {
    m.create.push_back(get(kv, "create_" + std::to_string(k)));
    m.seek.push_back(get(kv, "seek_" + std::to_string(k)));
  }
  return m;
}

struct SeekRow {
  std::string label;
  std::uint64_t interval = 0;
  bool rebuilds = false;  // automatic engine rebuilds (resumable keyframes) left on
  RunResult build;
  LogShape shape;
  std::vector<SeekResult> repeats;
  std::string failure;
};

// Per seek time the median over repeats; then min, median, max over the times.
void seek_stats(const SeekRow& row, double& lo, double& mid, double& hi, double& create, double& replay_eps) {
  std::vector<double> per_time, creates, eps;
  for (int k = 0; k < kSeekTimes; ++k) {
    std::vector<double> v, c;
    for (const SeekResult& r : row.repeats) v.push_back(r.seek[std::size_t(k)]), c.push_back(r.create[std::size_t(k)]);
    per_time.push_back(median(v));
    creates.push_back(median(c));
  }
  for (const SeekResult& r : row.repeats) eps.push_back(r.replay_wall > 0 ? r.replay_events / r.replay_wall : 0);
  lo = *std::min_element(per_time.begin(), per_time.end());
  hi = *std::max_element(per_time.begin(), per_time.end());
  mid = median(per_time);
  create = median(creates);
  replay_eps = median(eps);
}

SeekRow seek_row(const LogBenchOptions& o, std::uint64_t interval, bool rebuilds) {
  SeekRow row;
  row.interval = interval;
  row.rebuilds = rebuilds;
  row.label = power_of_two(interval) + (rebuilds ? " (automatic rebuilds)" : "");
  LogSettings settings;
  settings.keyframe_interval = interval;
  RunConfig c = config("seek-" + power_of_two(interval) + (rebuilds ? "-rebuilds" : ""), o.reference, o.seek_events,
                       true, settings, o.out_dir);
  if (!rebuilds) c.overrides.push_back(kNoRebuilds);
  std::fprintf(stderr, "  building %s\n", c.log_path.c_str());
  row.build = run_measured(c);
  if (!row.build.ok) return row.failure = row.build.failure, row;
  row.shape = read_shape(c.log_path, 0);
  if (!row.shape.ok) {
    std::filesystem::remove(c.log_path);
    return row.failure = row.shape.failure, row;
  }
  for (int k = 0; k < o.repeat && row.failure.empty(); ++k) {
    SeekResult r = measure_seeks(c.log_path);
    if (!r.ok) row.failure = r.failure;
    else row.repeats.push_back(std::move(r));
    std::fprintf(stderr, "  %s seeks, run %d\n", row.label.c_str(), k + 1);
  }
  std::filesystem::remove(c.log_path);
  return row;
}

void print_seek(const std::vector<SeekRow>& rows, const Series& sim, const std::string& csv_prefix) {
  const double sim_eps = sim.ok() ? sim.first().events / sim.wall() : 0;
  std::printf("### Seeking (%s, %.3g engine events)\n\n", scene_label(sim.config.scene).c_str(),
              sim.ok() ? sim.first().events : 0.0);
  std::printf("| keyframe interval | keyframes (resumable) | logged events | log MiB | B/logged event | "
              "keyframe share | seek min ms | seek median ms | seek max ms | fresh Replay ms | "
              "replay M logged events/s | simulation M logged events/s (log on) | replay / simulation |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::FILE* csv = open_csv(csv_prefix, "seek");
  if (csv)
    std::fprintf(csv, "keyframe_interval,automatic_rebuilds,keyframes,resumable_keyframes,logged_events,file_bytes,"
                      "seek_min,seek_median,seek_max,create_median,replay_events_per_second,"
                      "simulation_logged_events_per_second\n");
  for (const SeekRow& r : rows) {
    if (!r.failure.empty()) {
      std::printf("| %s | failed: %s |\n", r.label.c_str(), r.failure.c_str());
      continue;
    }
    double lo, mid, hi, create, replay_eps;
    seek_stats(r, lo, mid, hi, create, replay_eps);
    const double sim_logged_eps = r.build.logged / r.build.wall;
    std::printf("| %s | %.0f (%.0f) | %.4g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %sx |\n", r.label.c_str(),
                r.shape.keyframes, r.shape.resumable_keyframes, r.shape.events, mib(r.shape.file_bytes).c_str(),
                fmt(r.shape.file_bytes / r.shape.events).c_str(),
                share(r.shape.keyframe_payload, r.shape.keyframe_payload + r.shape.chunk_payload).c_str(),
                fmt(1e3 * lo).c_str(), fmt(1e3 * mid).c_str(), fmt(1e3 * hi).c_str(), fmt(1e3 * create).c_str(),
                fmt(replay_eps / 1e6).c_str(), fmt(sim_logged_eps / 1e6).c_str(),
                fmt(replay_eps / sim_logged_eps).c_str());
    if (csv)
      std::fprintf(csv, "%llu,%d,%.0f,%.0f,%.0f,%.0f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", (unsigned long long)r.interval,
                   r.rebuilds ? 1 : 0, r.shape.keyframes, r.shape.resumable_keyframes, r.shape.events,
                   r.shape.file_bytes, lo, mid, hi, create, replay_eps, sim_logged_eps);
  }
  if (csv) std::fclose(csv);
  std::printf("\nSeek: Replay::seek_time at t_end (k + 0.37) / %d, k = 0..%d, each on a freshly created Replay "
              "(its creation, which loads the first keyframe, is the \"fresh Replay\" column and not in the seek "
              "time); per time the median of %zu repeats, then min / median / max over the times. The log was "
              "just written, so it is read from the page cache. Rows without \"automatic rebuilds\" set "
              "engine.rebuild_interval = 2^40 so that keyframe_interval alone places the keyframes; the last row "
              "is the default configuration, where every engine rebuild (every max(2^20, 16 N) engine events) "
              "also writes a (resumable) keyframe.\n\n",
              kSeekTimes, kSeekTimes - 1, rows.empty() ? std::size_t(0) : rows.front().repeats.size());
  std::printf("Replay throughput: a fresh Replay applying every logged event from the start (for_each_event, "
              "median of the repeats); simulation: the run that wrote the log.\n\n");
  const SeekRow* defaults = rows.empty() || !rows.back().failure.empty() ? nullptr : &rows.back();
  if (sim.ok() && defaults) {
    double lo, mid, hi, create, replay_eps;
    seek_stats(*defaults, lo, mid, hi, create, replay_eps);
    const double logged_eps = defaults->shape.events / sim.wall();
    std::printf("The same run as the last row without a log (median of %zu): %.3g s, %.3g M engine events/s, "
                "%.3g M logged events/s; replay applies events %.3gx as fast.\n\n",
                sim.runs.size(), sim.wall(), sim_eps / 1e6, logged_eps / 1e6, replay_eps / logged_eps);
  }
}

}  // namespace

std::vector<std::string> default_log_bench_scenes() {
  return {"examples/bench/gas-N10000-phi0.5-periodic.toml", "examples/bench/gas-N10000-phi0.5-walls.toml",
          "examples/bench/gas-N10000-phi0.3-periodic.toml", "examples/bench/gas-N1000-phi0.5-periodic.toml"};
}

std::string default_log_bench_reference() { return "examples/bench/gas-N10000-phi0.5-periodic.toml"; }

int run_log_bench(const LogBenchOptions& o) {
  std::error_code ec;
  const bool made_dir = std::filesystem::create_directories(o.out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "ede-bench log: cannot create %s: %s\n", o.out_dir.c_str(), ec.message().c_str());
    return 1;
  }
  const LogSettings defaults;
  tools::CpuCycles probe;

  // 1. Scenes: log off and on (default settings).
  std::vector<Series> scenes;
  for (const std::string& path : o.scenes) {
    const std::string label = scene_label(path);
    scenes.push_back(series_of(config(label + "-off", path, o.events, false, defaults, o.out_dir)));
    scenes.push_back(series_of(config(label + "-on", path, o.events, true, defaults, o.out_dir)));
  }
  std::fprintf(stderr, "ede-bench log: scenes\n");
  run_series(scenes, o.repeat, defaults.compression_level);

  // 2 and 3. The reference scene: log off, every level, and frequent keyframes.
  std::vector<Series> ref;
  ref.push_back(series_of(config("log off", o.reference, o.events, false, defaults, o.out_dir)));
  std::vector<int> level_list = o.levels;  // the default level always runs: the overhead table needs it
  if (std::find(level_list.begin(), level_list.end(), defaults.compression_level) == level_list.end())
    level_list.push_back(defaults.compression_level);
  for (const int level : level_list) {
    LogSettings s = defaults;
    s.compression_level = level;
    ref.push_back(series_of(config("level-" + std::to_string(level), o.reference, o.events, true, s, o.out_dir)));
  }
  LogSettings frequent = defaults;
  frequent.keyframe_interval = kFrequentKeyframes;
  ref.push_back(series_of(config("keyframes-2^14", o.reference, o.events, true, frequent, o.out_dir)));
  std::fprintf(stderr, "ede-bench log: levels and overhead (%s)\n", o.reference.c_str());
  run_series(ref, o.repeat, 0);

  // 4. Seeking: logs built once per keyframe interval, seeks repeated; and the simulation without a log.
  std::vector<SeekRow> seeks;
  std::vector<Series> sim;
  sim.push_back(series_of(config("seek-run-off", o.reference, o.seek_events, false, defaults, o.out_dir)));
  if (!o.skip_seek) {
    std::fprintf(stderr, "ede-bench log: seeking\n");
    run_series(sim, o.repeat, 0);
    for (const int k : {16, 18, 20, 22}) seeks.push_back(seek_row(o, std::uint64_t(1) << k, false));
    seeks.push_back(seek_row(o, defaults.keyframe_interval, true));
  }

  std::printf("Medians of %d runs per configuration, interleaved; each run in its own process. The machine is "
              "shared: compare ratios and medians, not single wall times.\n\n",
              o.repeat);
  std::vector<ScenePair> pairs;
  for (std::size_t k = 0; k + 1 < scenes.size(); k += 2)
    pairs.push_back({scene_label(scenes[k].config.scene), &scenes[k], &scenes[k + 1]});
  print_scenes(pairs, o.csv_prefix);
  print_columns(pairs, o.csv_prefix);
  std::vector<Series*> levels, overhead{&ref.front()};
  for (std::size_t k = 1; k + 1 < ref.size(); ++k) levels.push_back(&ref[k]);
  print_levels(ref.front(), levels, o.csv_prefix);
  for (Series* s : levels)
    if (s->config.settings.compression_level == defaults.compression_level) overhead.push_back(s);
  overhead.push_back(&ref.back());
  print_overhead(overhead, probe.available());
  if (!o.skip_seek) print_seek(seeks, sim.front(), o.csv_prefix);
  print_failures(scenes);
  print_failures(ref);
  print_failures(sim);

  if (made_dir) std::filesystem::remove(o.out_dir, ec);  // only if empty; the logs are already gone
  bool ok = true;
  for (const auto* all : {&scenes, &ref, &sim})
    for (const Series& s : *all) ok = ok && s.failure.empty();
  for (const SeekRow& r : seeks) ok = ok && r.failure.empty();
  return ok ? 0 : 1;
}

}  // namespace ede::bench
