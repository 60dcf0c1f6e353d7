// ede-bench log's tables 2 to 4 (levels, overhead, seeking) and what the tables share; see bench_log_tables.hpp.
#include "bench_log_tables.hpp"

#include "commands.hpp"
#include "study/measurement.hpp"

namespace ede::bench {

using namespace study;

std::FILE* CsvDir::open(const char* name) {
  if (dir.empty()) return nullptr;
  const std::string path = dir + "/" + name + ".csv";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) failed = true, fail("cannot write " + path);
  return f;
}

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

void print_failures(const std::vector<Series>& all) {
  for (const Series& s : all) {
    if (!s.failure.empty()) std::printf("\n**%s failed**: %s\n", s.config.label.c_str(), s.failure.c_str());
    if (s.sizes_differ) std::printf("\n**%s: the log size differed between repeats** (expected identical)\n",
                                    s.config.label.c_str());
  }
}

// -------------------------------------------------------------- 2 and 3. zstd level, logging overhead

void print_levels(const Series& off, const std::vector<Series*>& levels, CsvDir& out) {
  std::printf("### zstd level (%s)\n\n", scene_label(off.config.scene).c_str());
  std::printf("| level | file MiB | B/logged event | wall s | wall overhead | compressing thread CPU s | "
              "compressing ns/logged event | CPU overhead (both threads) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::FILE* csv = out.open("levels");
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
// ------------------------------------------------------------------------------------------- 4. seek

void print_seek(const std::vector<SeekRow>& rows, const Series& sim, CsvDir& out) {
  const double sim_eps = sim.ok() ? sim.first().events / sim.wall() : 0;
  std::printf("### Seeking (%s, %.3g engine events)\n\n", scene_label(sim.config.scene).c_str(),
              sim.ok() ? sim.first().events : 0.0);
  std::printf("| keyframe interval | keyframes (resumable) | logged events | log MiB | B/logged event | "
              "keyframe share | seek min ms | seek median ms | seek max ms | fresh Replay ms | "
              "replay M logged events/s: state / with records | simulation M logged events/s (log on) | replay / simulation |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::FILE* csv = out.open("seek");
  if (csv)
    std::fprintf(csv, "keyframe_interval,automatic_rebuilds,keyframes,resumable_keyframes,logged_events,file_bytes,"
                      "seek_min,seek_median,seek_max,create_median,replay_events_per_second,"
                      "simulation_logged_events_per_second,state_replay_events_per_second\n");
  for (const SeekRow& r : rows) {
    if (!r.failure.empty()) {
      std::printf("| %s | failed: %s |\n", r.label.c_str(), r.failure.c_str());
      continue;
    }
    const SeekStats st = seek_stats(r);
    const double sim_logged_eps = r.build.logged / r.build.wall;
    std::printf("| %s | %.0f (%.0f) | %.4g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %sx |\n", r.label.c_str(),
                r.shape.keyframes, r.shape.resumable_keyframes, r.shape.events, mib(r.shape.file_bytes).c_str(),
                fmt(r.shape.file_bytes / r.shape.events).c_str(),
                share(r.shape.keyframe_payload, r.shape.keyframe_payload + r.shape.chunk_payload).c_str(),
                fmt(1e3 * st.min).c_str(), fmt(1e3 * st.median).c_str(), fmt(1e3 * st.max).c_str(),
                fmt(1e3 * st.create).c_str(),
                (fmt(st.state_replay_events_per_second / 1e6) + " / " + fmt(st.replay_events_per_second / 1e6)).c_str(),
                fmt(sim_logged_eps / 1e6).c_str(), fmt(st.replay_events_per_second / sim_logged_eps).c_str());
    if (csv)
      std::fprintf(csv, "%llu,%d,%.0f,%.0f,%.0f,%.0f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", (unsigned long long)r.interval,
                   r.rebuilds ? 1 : 0, r.shape.keyframes, r.shape.resumable_keyframes, r.shape.events,
                   r.shape.file_bytes, st.min, st.median, st.max, st.create, st.replay_events_per_second,
                   sim_logged_eps, st.state_replay_events_per_second);
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
  std::printf("Replay throughput: a fresh Replay applying every logged event from the start, median of the "
              "repeats: \"state\" applies them as a seek does (the state only), \"with records\" also builds "
              "each event's record for a callback (for_each_event, what ede-replay events and the analyses "
              "read); simulation: the run that wrote the log.\n\n");
  const SeekRow* defaults = rows.empty() || !rows.back().failure.empty() ? nullptr : &rows.back();
  if (sim.ok() && defaults) {
    const double replay_eps = seek_stats(*defaults).state_replay_events_per_second;
    const double logged_eps = defaults->shape.events / sim.wall();
    std::printf("The same run as the last row without a log (median of %zu): %.3g s, %.3g M engine events/s, "
                "%.3g M logged events/s; replay applies events (state only) %.3gx as fast.\n\n",
                sim.runs.size(), sim.wall(), sim_eps / 1e6, logged_eps / 1e6, replay_eps / logged_eps);
  }
}

}  // namespace ede::bench
