// The pieces of log measurement shared by the log benchmark and the accuracy study; see log_measure.hpp.
//
// Every timed measurement runs in its own child process (run_in_child: a clean heap, and the log writer's
// second thread is the child's own, so getrusage(RUSAGE_SELF) in the child is the CPU time of exactly
// one run's two threads). Log sizes do not depend on timing (the writer's bytes are a function of the
// events); the caller reads the log afterwards and deletes it.
#include "run/log_run_info.hpp"
#include "study/log_measure.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "study/measurement.hpp"
#include "study/cpu_cycles.hpp"
#include "log/log_reader.hpp"
#include "replay/replay.hpp"
#include "ede/scene.hpp"
#include "setup/setup.hpp"
#include "core/scalar_dispatch.hpp"

namespace ede::study {

std::string power_of_two(std::uint64_t v) {
  if (v == 0) return "auto";  // LogSettings: 0 is the automatic keyframe interval
  int k = 0;
  while ((std::uint64_t(1) << k) < v) ++k;
  return (std::uint64_t(1) << k) == v ? "2^" + std::to_string(k) : std::to_string(v);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

CpuTimes cpu_times() {
  const auto seconds = [](const rusage& u) {
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  };
  rusage self{}, thread{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_THREAD, &thread);
  return {seconds(self), seconds(thread)};
}

namespace {

// `initial` is freed once the engine holds it, as ede-sim does (its per-disk arrays are ~52 B/disk): the peak
// RSS measured here is then ede-sim's, not ede-sim's plus a second copy of the initial state.
template <class T>
int timed_run(const RunConfig& c, const Scene& scene, InitialState& initial, const EngineOptions& options,
              std::string& out) {
  auto made = make_study_engine<T>(initial, options, c.variant);
  if (!made) return out = made.error().message, 1;
  EngineApi<T>& engine = *made.value();
  const std::size_t disks = initial.size();
  const LogRunInfo run_info = log_run_info(scene, options, initial.species_names);
  initial = InitialState{};
  std::unique_ptr<LogWriter<T>> log;
  if (c.log) {
    auto w = LogWriter<T>::create(c.log_path, run_info, c.settings);
    if (!w) return out = w.error().message, 1;
    log = std::move(w).value();
    engine.add_sink(log.get());
  }
  if (c.warmup_collisions_per_disk > 0) {
    const double target = c.warmup_collisions_per_disk * double(disks) / 2;
    while (double(engine.counts().of(EventKind::Pair)) < target)
      if (engine.run(std::max<std::uint64_t>(1000, disks / 4)) != RunStatus::Running) break;
  }
  const std::uint64_t pairs0 = engine.counts().of(EventKind::Pair);
  CpuCycles cycles;
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
  o << "disks=" << disks << " events=" << n.events() << " collisions=" << n.collisions()
    << " logged=" << (log ? log->events_logged() : 0) << " bytes=" << (log ? log->bytes_written() : 0)
    << " sim_time=" << double(engine.time()) << " wall=" << wall << " cycles=" << cyc
    << " cpu_process=" << cpu1.process - cpu0.process << " cpu_main=" << cpu1.thread - cpu0.thread
    << " timed_pairs=" << n.of(EventKind::Pair) - pairs0 << " engine_bytes=" << engine.memory_bytes();
  out = o.str();
  return 0;
}

int run_child(const RunConfig& c, std::string& out) {
  std::vector<Override> overrides = as_overrides(c.overrides);
  if (c.events) overrides.push_back({"stop.events=" + std::to_string(c.events)});  // after them: it wins
  auto scene = load_scene_file(c.scene, overrides);
  if (!scene) return out = scene.error().message, 1;
  auto initial = build_initial_state(scene.value());
  if (!initial) return out = initial.error().message, 1;
  const EngineOptions options = engine_options_from(scene.value(), initial.value().size());
  if (scene.value().scalar == ScalarKind::Float128)
    return out = c.scene + ": float128 runs write no event log (the log format holds float, double and long "
                           "double); benchmark them with ede-bench speed",
           1;
  return with_scalar(scene.value().scalar, [&]<class T>() {
    return timed_run<T>(c, scene.value(), initial.value(), options, out);
  });
}

}  // namespace

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
  m.timed_pairs = get(kv, "timed_pairs"), m.engine_bytes = get(kv, "engine_bytes");
  m.peak_rss = r.peak_rss;
  return m;
}

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

namespace {

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
  {
    // The state only: an empty function makes for_each_event apply events as a seek does.
    auto state_replay = Replay<T>::create(log);
    if (!state_replay) return out = state_replay.error().message, 1;
    const auto t0 = std::chrono::steady_clock::now();
    const Status s = state_replay.value()->for_each_event(0, log->total_events(), {});
    if (!s) return out = s.error().message, 1;
    o << " state_replay_wall=" << seconds_since(t0) << " state_replay_events=" << state_replay.value()->events_applied();
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
  return with_scalar(reader->header().scalar,
                            [&]<class T>() { return seek_child_typed<T>(reader, open_seconds, out); });
}

}  // namespace

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
  m.state_replay_wall = get(kv, "state_replay_wall");
  m.state_replay_events = get(kv, "state_replay_events");
  for (int k = 0; k < kSeekTimes; ++k) {
    m.create.push_back(get(kv, "create_" + std::to_string(k)));
    m.seek.push_back(get(kv, "seek_" + std::to_string(k)));
  }
  return m;
}

// Per seek time the median over repeats; then min, median, max over the times.
SeekStats seek_stats(const SeekRow& row) {
  std::vector<double> per_time, creates, eps, state_eps;
  for (int k = 0; k < kSeekTimes; ++k) {
    std::vector<double> v, c;
    for (const SeekResult& r : row.repeats) v.push_back(r.seek[std::size_t(k)]), c.push_back(r.create[std::size_t(k)]);
    per_time.push_back(median(v));
    creates.push_back(median(c));
  }
  for (const SeekResult& r : row.repeats) {
    eps.push_back(r.replay_wall > 0 ? r.replay_events / r.replay_wall : 0);
    state_eps.push_back(r.state_replay_wall > 0 ? r.state_replay_events / r.state_replay_wall : 0);
  }
  SeekStats st;
  st.min = *std::min_element(per_time.begin(), per_time.end());
  st.max = *std::max_element(per_time.begin(), per_time.end());
  st.median = median(per_time);
  st.create = median(creates);
  st.replay_events_per_second = median(eps);
  st.state_replay_events_per_second = median(state_eps);
  return st;
}

SeekRow seek_row(const RunConfig& build, const std::string& label, std::uint64_t interval, bool rebuilds,
                 int repeat) {
  SeekRow row;
  row.interval = interval;
  row.rebuilds = rebuilds;
  row.label = label;
  std::fprintf(stderr, "  building %s\n", build.log_path.c_str());
  row.build = run_measured(build);
  if (!row.build.ok) return row.failure = row.build.failure, row;
  row.shape = read_shape(build.log_path, 0);
  if (!row.shape.ok) {
    std::filesystem::remove(build.log_path);
    return row.failure = row.shape.failure, row;
  }
  for (int k = 0; k < repeat && row.failure.empty(); ++k) {
    SeekResult r = measure_seeks(build.log_path);
    if (!r.ok) row.failure = r.failure;
    else row.repeats.push_back(std::move(r));
    std::fprintf(stderr, "  %s seeks, run %d\n", row.label.c_str(), k + 1);
  }
  std::filesystem::remove(build.log_path);
  return row;
}

}  // namespace ede::study
