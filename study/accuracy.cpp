// The accuracy study: runs the parts (accuracy_parts.hpp) one after the other. The parts run
// sequentially, each measurement in its own child, so timings never share the machine with another of
// our measurements; the engine's timed runs go in interleaved rounds over all settings.
// Rejected: a shell script around several commands (one command, one plan, one set of medians; the
// figure still comes from the CSV alone).
#include "study/accuracy.hpp"

#include <cstdio>
#include <filesystem>

#include "study/measurement.hpp"

namespace ede::study {

bool StudyResults::ok() const {
  bool all = true;
  for (const EngineRow& e : engine) all = all && e.failure.empty() && e.repeats_agree;
  for (const SteppedRow& s : stepped.rows) all = all && s.failure.empty();
  for (const LogRow& l : log) all = all && l.failure.empty();
  return all;
}

StudyPlan quick_plan(StudyPlan p) {
  p.checkpoints = 20;
  p.divergence_cap = 40;
  p.ts_collisions = 10;
  p.cooling_collisions = 10;
  p.ts_dt_fractions = {1, 0.3, 0.1};
  p.cooling_points = 10;
  p.keyframe_intervals = {1u << 12, 1u << 14};
  p.float128_first_scene_only = true;
  return p;
}

Result<StudyResults> run_accuracy_study(const StudyPlan& plan) {
  for (const std::string& scene : engine_scenes()) {
    auto s = load_scene_file(plan.scene(scene), as_overrides(plan.overrides));
    if (!s) return s.error();
    if (!s.value().stop.events)
      return Error{plan.scene(scene) + ": the study runs each scene for its stop.events; set it (--set stop.events=N)"};
  }
  std::error_code ec;
  std::filesystem::create_directories(plan.tmp_dir, ec);
  if (ec) return Error{"cannot create " + plan.tmp_dir + ": " + ec.message()};
  StudyResults res;
  res.plan = plan;
  std::fprintf(stderr, "ede-bench accuracy: errors of %zu settings on %zu scenes\n", study_settings().size(),
               engine_scenes().size());
  for (const std::string& scene : engine_scenes())
    for (const Setting& s : study_settings()) {
      if (plan.float128_first_scene_only && s.precision == Precision::Float128 && scene != engine_scenes().front())
        continue;
      EngineRow row;
      row.setting = s;
      row.scene = scene;
      measure_engine_errors(plan, row);
      if (row.failure.empty()) measure_chaos(plan, row);
      res.engine.push_back(row);
    }
  // Timed runs in rounds over every row: a slow spell of the machine slows one run of each, not all runs
  // of one setting.
  for (int round = 0; round < plan.repeat; ++round) {
    std::fprintf(stderr, "ede-bench accuracy: timing, round %d of %d\n", round + 1, plan.repeat);
    for (EngineRow& row : res.engine)
      if (row.failure.empty()) measure_engine_time(plan, row);
  }
  std::fprintf(stderr, "ede-bench accuracy: time-stepped\n");
  res.stepped = measure_time_stepped(plan);
  std::fprintf(stderr, "ede-bench accuracy: log\n");
  res.log = measure_log(plan);
  std::filesystem::remove(plan.tmp_dir, ec);  // only if empty: the logs are already gone
  return res;
}

}  // namespace ede::study
