// ede-bench accuracy: runs the parts of the study (accuracy_parts.hpp) one after the other and writes the
// report (accuracy_report.hpp). The parts run sequentially, each measurement in its own child, so timings
// never share the machine with another of our measurements; the engine's timed runs go in interleaved
// rounds over all settings. --quick keeps every row and every metric but
// shrinks the runs and the lists (fewer dt, keyframe intervals, comparison times):
// it is what the test runs. Rejected: a shell script around several commands (one command, one plan,
// one set of medians; the figure still comes from the CSV alone).
#include "accuracy.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "accuracy_report.hpp"

namespace ede::bench {

namespace {

StudyPlan make_plan(const AccuracyOptions& o) {
  StudyPlan p;
  p.scenes_dir = o.scenes_dir;
  p.events = o.events;
  p.timing_events = std::min(o.timing_events, o.events);
  p.repeat = o.repeat;
  p.log_events = o.events;
  p.tmp_dir = o.tmp_dir;
  if (o.quick) {
    p.checkpoints = 20;
    p.divergence_cap = 40;
    p.ts_collisions = 10;
    p.cooling_collisions = 10;
    p.ts_dt_fractions = {1, 0.3, 0.1};
    p.cooling_points = 10;
    p.keyframe_intervals = {1u << 12, 1u << 14};
  }
  return p;
}

bool all_ok(const StudyResults& r) {
  bool ok = true;
  for (const EngineRow& e : r.engine) ok = ok && e.failure.empty() && e.repeats_agree;
  for (const SteppedRow& s : r.stepped.rows) ok = ok && s.failure.empty();
  for (const LogRow& l : r.log) ok = ok && l.failure.empty();
  return ok;
}

}  // namespace

int run_accuracy(const AccuracyOptions& o) {
  std::error_code ec;
  for (const std::string& dir : {o.out_dir, o.tmp_dir}) {
    std::filesystem::create_directories(dir, ec);
    if (ec) {
      std::fprintf(stderr, "ede-bench accuracy: cannot create %s: %s\n", dir.c_str(), ec.message().c_str());
      return 1;
    }
  }
  StudyResults res;
  res.plan = make_plan(o);
  std::fprintf(stderr, "ede-bench accuracy: errors of %zu settings on %zu scenes\n", study_settings().size(),
               engine_scenes().size());
  for (const std::string& scene : engine_scenes())
    for (const Setting& s : study_settings()) {
      EngineRow row;
      row.setting = s;
      row.scene = scene;
      measure_engine_errors(res.plan, row);
      if (row.failure.empty()) measure_chaos(res.plan, row);
      res.engine.push_back(row);
    }
  // Timed runs in rounds over every row: a slow spell of the machine slows one run of each, not all runs
  // of one setting.
  for (int round = 0; round < res.plan.repeat; ++round) {
    std::fprintf(stderr, "ede-bench accuracy: timing, round %d of %d\n", round + 1, res.plan.repeat);
    for (EngineRow& row : res.engine)
      if (row.failure.empty()) measure_engine_time(res.plan, row);
  }
  std::fprintf(stderr, "ede-bench accuracy: time-stepped\n");
  res.stepped = measure_time_stepped(res.plan);
  std::fprintf(stderr, "ede-bench accuracy: log\n");
  res.log = measure_log(res.plan);
  std::filesystem::remove(o.tmp_dir, ec);  // only if empty: the logs are already gone
  if (Status s = write_report(res, o.out_dir, o.plot); !s) {
    std::fprintf(stderr, "ede-bench accuracy: %s\n", s.error().message.c_str());
    return 1;
  }
  return all_ok(res) ? 0 : 1;
}

}  // namespace ede::bench
