// ede-bench speed SCENE.toml... [--repeat N] [--set key=value]... [-o FILE.csv]: events per second, ns
// and cycles per event, bytes per disk for each scene (study/speed.hpp measures), with the all-pairs
// baseline; a Markdown table on stdout, the same rows as CSV with -o.
#include <cstdio>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "study/cpu_cycles.hpp"
#include "study/measurement.hpp"
#include "study/speed.hpp"

namespace ede::bench {

namespace {

using study::fmt;
using study::SpeedRow;

struct SpeedOptions {
  std::vector<std::string> scenes;
  study::SpeedPlan plan;
  std::string csv_path;
};

void print_table(const std::vector<SpeedRow>& rows, bool have_cycles) {
  std::printf("| scene | N | events | M events/s | M collisions/s | ns/event | %s B/disk (engine) | "
              "peak RSS B/disk | all-pairs M events/s | speed-up |\n",
              have_cycles ? "cycles/event |" : "");
  std::printf("|---|---:|---:|---:|---:|---:|%s---:|---:|---:|---:|\n", have_cycles ? "---:|" : "");
  for (const SpeedRow& r : rows) {
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

std::string csv_of(const std::vector<SpeedRow>& rows) {
  std::ostringstream o;
  o << "scene,disks,events,events_per_second,collisions_per_second,ns_per_event,cycles_per_event,"
       "engine_bytes_per_disk,peak_rss_bytes_per_disk,allpairs_events_per_second,allpairs_events\n";
  char line[512];
  for (const SpeedRow& r : rows) {
    if (!r.typical.ok) continue;
    const double n = r.typical.disks;
    std::snprintf(line, sizeof line, "%s,%.0f,%.0f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.0f\n", r.scene.c_str(), n,
                  r.typical.events, r.events_per_second, r.collisions_per_second, r.ns_per_event, r.cycles_per_event,
                  r.typical.engine_bytes / n, r.typical.peak_rss / n, r.baseline_events_per_second, r.baseline_events);
    o << line;
  }
  return o.str();
}

int run_speed(const SpeedOptions& o) {
  if (!check_scenes(o.scenes, o.plan.overrides)) return 1;
  std::vector<SpeedRow> rows;
  for (const std::string& path : o.scenes) {
    std::fprintf(stderr, "ede-bench speed: %s\n", path.c_str());
    rows.push_back(study::measure_speed(path, o.plan));
  }
  std::printf("Medians of %d runs per scene (cell engine); the all-pairs baseline runs once with a budget of "
              "~%.3g s.\n\n",
              o.plan.repeat, o.plan.baseline_seconds);
  print_table(rows, study::CpuCycles().available());
  if (!o.csv_path.empty() && !write_file(o.csv_path, csv_of(rows))) return 1;
  for (const SpeedRow& r : rows)
    if (!r.typical.ok) return 1;
  return 0;
}

}  // namespace

Command speed_command(CLI::App& app) {
  auto o = std::make_shared<SpeedOptions>();
  CLI::App* s = app.add_subcommand("speed", "events per second for scenes, with the all-pairs baseline");
  s->add_option("scenes", o->scenes, "scene files (e.g. examples/bench/*.toml)")->required();
  s->add_option("--repeat", o->plan.repeat, "runs per scene; medians are reported")->check(CLI::Range(1, 100));
  add_set_option(s, o->plan.overrides);
  s->add_option("--baseline-max-disks", o->plan.baseline_max_disks, "largest N for the all-pairs baseline");
  s->add_option("--baseline-seconds", o->plan.baseline_seconds, "approximate length of each baseline run");
  s->add_option("-o,--output", o->csv_path, "also write the table as CSV to this file");
  return {s, [o] { return run_speed(*o); }};
}

}  // namespace ede::bench
