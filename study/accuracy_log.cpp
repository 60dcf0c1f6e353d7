// The accuracy study, the log part: the log changes no result (the writer never changes the run), so its
// "error" is what it costs to get a state back: seek time against bytes, for the keyframe interval.
// On the elastic gas (double), its stop.events engine events: the log off; on with a keyframe every 2^k logged
// events (engine rebuilds off, so that the interval alone places the keyframes); on with the defaults.
// ns/event is the median over repeats of the event loop (log_measure's run_measured, a child each); the
// seek times are log_measure's seek_row (20 times, fresh Replays, medians over repeats) on the last
// build. Rejected: a second implementation of the log benchmark; this is bench_log's machinery with the
// study's scene and rows.
#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include "study/accuracy_parts.hpp"
#include "study/measurement.hpp"
#include "study/log_measure.hpp"

namespace ede::study {

namespace {

RunConfig log_config(const StudyPlan& plan, bool log, std::uint64_t interval, bool rebuilds) {
  RunConfig c;
  c.label = log ? "log-" + power_of_two(interval) : "log-off";
  c.scene = plan.scene("gas");
  c.overrides = plan.overrides;
  if (log && !rebuilds) c.overrides.push_back(kNoRebuilds);
  c.log = log;
  c.settings.keyframe_interval = interval;
  c.log_path = plan.tmp_dir + "/accuracy-log-" + std::to_string(::getpid()) + ".ede";
  return c;
}

// ns/event over `runs` timed runs (their logs deleted), appended to `ns`; false with row.failure on failure.
bool time_runs(const RunConfig& c, int runs, std::vector<double>& ns, LogRow& row) {
  for (int k = 0; k < runs; ++k) {
    const RunResult r = run_measured(c);
    if (c.log) std::filesystem::remove(c.log_path);
    if (!r.ok) return row.failure = r.failure, false;
    ns.push_back(1e9 * r.wall / r.events);
  }
  return true;
}

LogRow log_row(const StudyPlan& plan, const std::string& label, std::uint64_t interval, bool rebuilds, double off_ns) {
  LogRow row;
  row.label = label;
  row.interval = interval;
  row.rebuilds = rebuilds;
  const RunConfig c = log_config(plan, true, interval, rebuilds);
  std::vector<double> ns;
  if (!time_runs(c, plan.repeat - 1, ns, row)) return row;
  const SeekRow seek = seek_row(c, label, interval, rebuilds, plan.repeat);
  if (!seek.failure.empty()) return row.failure = seek.failure, row;
  ns.push_back(1e9 * seek.build.wall / seek.build.events);
  const SeekStats st = seek_stats(seek);
  row.ns_per_event = median(ns);
  row.ratio_to_off = row.ns_per_event / off_ns;
  row.bytes_per_event = seek.shape.file_bytes / seek.shape.events;
  row.keyframe_share = seek.shape.keyframe_payload / (seek.shape.keyframe_payload + seek.shape.chunk_payload);
  row.seek_median = st.median;
  row.seek_max = st.max;
  std::fprintf(stderr, "  log %-22s %.0f ns/event, %.3g B/event, seek median %.3g ms\n", label.c_str(),
               row.ns_per_event, row.bytes_per_event, 1e3 * row.seek_median);
  return row;
}

}  // namespace

std::vector<LogRow> measure_log(const StudyPlan& plan) {
  std::vector<LogRow> rows(1);
  rows[0].label = "log off";
  std::vector<double> off;
  if (!time_runs(log_config(plan, false, 0, false), plan.repeat, off, rows[0])) return rows;
  rows[0].ns_per_event = median(off);
  rows[0].ratio_to_off = 1;
  for (const std::uint64_t interval : plan.keyframe_intervals)
    rows.push_back(log_row(plan, "keyframe every " + power_of_two(interval), interval, false, rows[0].ns_per_event));
  rows.push_back(log_row(plan, "defaults", 0, true, rows[0].ns_per_event));
  return rows;
}

}  // namespace ede::study
