// ede-bench log [SCENE.toml...] [--reference SCENE.toml] [--repeat N] [--set key=value]...
//   [--seek-events N] [--skip-seek] [--levels 1,3,...] [--out-dir DIR] [--tmp-dir DIR] [--quick]
// What the event log costs (study/log_bench.hpp measures): bytes per event by scene and by column, the
// zstd level, the logging overhead, seeking; Markdown tables, and with --out-dir DIR the same rows as
// DIR/scenes.csv, columns.csv, levels.csv and seek.csv.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "bench_log_tables.hpp"
#include "commands.hpp"
#include "study/cpu_cycles.hpp"
#include "study/measurement.hpp"

namespace ede::bench {

using namespace study;

// ------------------------------------------------------------------------- 1. bytes per event, scenes

void print_scenes(const std::vector<ScenePair>& pairs, CsvDir& out) {
  std::printf("### Bytes per event and overhead, by scene (default log settings)\n\n");
  std::printf("| scene | N | logged events | collisions | file MiB | B/logged event | B/collision | keyframes | "
              "keyframe share | M events/s (log off) | wall overhead | CPU overhead (both threads) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::FILE* csv = out.open("scenes");
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

void print_columns(const std::vector<ScenePair>& pairs, CsvDir& out) {
  std::printf("### Where the bytes go (chunk columns, bytes per logged event)\n\n");
  std::printf("Each column of every chunk compressed alone at the log's level (an estimate of its share; the "
              "file compresses a chunk as one frame), then the chunks as stored, and the keyframes.\n\n");
  const auto& names = pairs.empty() ? std::vector<LogColumnSize>{} : pairs.front().on->shape.columns.columns;
  std::printf("| scene |");
  for (const LogColumnSize& c : names) std::printf(" %s |", c.name.c_str());
  std::printf(" columns alone, sum | chunks as stored | chunks decompressed | keyframes |\n|---|");
  for (std::size_t k = 0; k < names.size() + 4; ++k) std::printf("---:|");
  std::printf("\n");
  std::FILE* csv = out.open("columns");
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

namespace {

struct LogOptions {
  LogBenchPlan plan;
  std::string out_dir;  // the CSV tables
  bool quick = false;
};

int run_log(LogOptions o) {
  if (o.plan.scenes.empty()) o.plan.scenes = default_log_bench_scenes();
  if (o.plan.reference.empty()) o.plan.reference = default_log_bench_reference();
  if (o.quick) o.plan.overrides.insert(o.plan.overrides.begin(), "stop.events=500000");  // a --set wins
  std::vector<std::string> all = o.plan.scenes;
  all.push_back(o.plan.reference);
  if (!check_scenes(all, o.plan.overrides)) return 1;
  CsvDir csv{o.out_dir};
  std::error_code ec;
  if (!o.out_dir.empty() && (std::filesystem::create_directories(o.out_dir, ec), ec))
    return fail("cannot create " + o.out_dir + ": " + ec.message());
  auto made = run_log_bench(o.plan);
  if (!made) return fail("log: " + made.error().message);
  LogBenchResults& r = made.value();
  std::printf("Medians of %d runs per configuration, interleaved; each run in its own process. The machine is "
              "shared: compare ratios and medians, not single wall times.\n\n",
              o.plan.repeat);
  std::vector<ScenePair> pairs;
  for (std::size_t k = 0; k + 1 < r.scenes.size(); k += 2)
    pairs.push_back({scene_label(r.scenes[k].config.scene), &r.scenes[k], &r.scenes[k + 1]});
  print_scenes(pairs, csv);
  print_columns(pairs, csv);
  const LogSettings defaults;
  std::vector<Series*> levels, overhead{&r.ref.front()};
  for (std::size_t k = 1; k + 1 < r.ref.size(); ++k) levels.push_back(&r.ref[k]);
  print_levels(r.ref.front(), levels, csv);
  for (Series* s : levels)
    if (s->config.settings.compression_level == defaults.compression_level) overhead.push_back(s);
  overhead.push_back(&r.ref.back());
  print_overhead(overhead, CpuCycles().available());
  if (!o.plan.skip_seek) print_seek(r.seeks, r.sim.front(), csv);
  print_failures(r.scenes);
  print_failures(r.ref);
  print_failures(r.sim);
  return r.ok() && !csv.failed ? 0 : 1;
}

}  // namespace

Command log_command(CLI::App& app) {
  auto o = std::make_shared<LogOptions>();
  CLI::App* l = app.add_subcommand("log", "event log: bytes per event, zstd level, overhead, seek, replay speed");
  l->add_option("scenes", o->plan.scenes, "scene files (default: four N = 10^3 and 10^4 scenes of examples/bench)");
  l->add_option("--reference", o->plan.reference, "the scene of the level, overhead and seek measurements");
  CLI::Option* repeat = l->add_option("--repeat", o->plan.repeat, "runs per configuration; medians are reported")
                            ->check(CLI::Range(1, 100));
  add_set_option(l, o->plan.overrides);
  CLI::Option* seek_events = l->add_option("--seek-events", o->plan.seek_events,
                                           "engine events (stop.events) of the logs built for seeking");
  l->add_flag("--skip-seek", o->plan.skip_seek, "skip the seek and replay measurements");
  l->add_option("--levels", o->plan.levels, "zstd levels to compare")->delimiter(',')->check(CLI::Range(1, 22));
  l->add_option("--out-dir", o->out_dir, "also write the tables as CSV files into this folder");
  l->add_option("--tmp-dir", o->plan.tmp_dir, "where the temporary logs go (deleted as soon as read)");
  l->add_option("--format-version", o->plan.format_version, "log format version to write: 2 (default) or 1")
      ->check(CLI::Range(1, 2));
  l->add_flag("--quick", o->quick, "a smoke run (well under a minute): 1 repeat, stop.events=500000, 2e6 seek events");
  return {l, [o, repeat, seek_events] {
            if (o->quick && !repeat->count()) o->plan.repeat = 1;
            if (o->quick && !seek_events->count()) o->plan.seek_events = 2000000;
            return run_log(*o);
          }};
}

}  // namespace ede::bench
