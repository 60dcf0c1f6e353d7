// The parts of the accuracy study (ede-bench accuracy) and the rows they produce; accuracy.cpp runs them,
// ede-bench's accuracy_report.cpp prints them. Each part measures in child processes (run_child_measurement), one file per part:
//   accuracy_engine.cpp        per setting and scene: ns/event, energy drift, largest overlap, log bytes/event
//   accuracy_chaos.cpp         per setting and scene: time reversal, divergence of runs one ulp apart
//   accuracy_time_stepped.cpp  a time-stepped simulation at several dt against the event-driven engine
//   accuracy_log.cpp           the log off, on, and its keyframe interval: time, bytes, seek time
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "study/accuracy_settings.hpp"
#include "study/measurement.hpp"

namespace ede::study {

// What the whole study runs; ede-bench fills it from the command line (full, or quick_plan for --quick).
struct StudyPlan {
  std::string scenes_dir;                // examples/accuracy
  std::vector<std::string> overrides;    // --set key=value, applied to every scene the study loads
  // The error runs (drift, overlap) and the logs of the log part run each scene's own stop.events.
  std::uint64_t timing_events = 2000000; // engine events of each timed run (ns/event); at most stop.events
  int repeat = 3;                        // timed runs per measurement; medians are reported
  int checkpoints = 100;                 // energy and snapshot-overlap checks along each error run
  std::vector<double> reversal_collisions = {5, 10, 20};  // collisions per disk before reversing
  double divergence_cap = 200;           // collisions per disk after which twin runs are given up
  double divergence_step = 0.1;          // collisions per disk between the twins' comparisons
  double ts_collisions = 300;            // mean free times of the collision-rate comparison
  double cooling_collisions = 20;        // initial mean free times of the cooling-curve comparison
  std::vector<double> ts_dt_fractions = {1, 0.3, 0.1, 0.03, 0.01};  // dt in mean free times
  int cooling_points = 20;               // times at which the cooling curves are compared
  std::vector<std::uint64_t> keyframe_intervals = {1u << 14, 1u << 16, 1u << 18, 1u << 20, 1u << 22};
  // __float128 (software arithmetic, 10-40x the time of double per event) on the first scene only: the
  // smoke run's choice, where its two other scenes' rows took 2/3 of the time.
  bool float128_first_scene_only = false;
  std::string tmp_dir;                   // where the logs go (deleted as soon as read)

  std::string scene(const std::string& name) const { return scenes_dir + "/" + name + ".toml"; }
  // The scene `name` with the setting and the plan's overrides (and `more`) applied.
  Result<StudyScene> load(const std::string& name, const Setting& setting, std::vector<std::string> more = {}) const {
    std::vector<std::string> all = overrides;
    all.insert(all.end(), more.begin(), more.end());
    return load_study_scene(scene(name), setting, std::move(all));
  }
  // Engine events of a long run of `s` (its stop.events) and of a timed run (timing_events, at most that).
  static std::uint64_t long_events(const StudyScene& s) { return s.scene.stop.events.value_or(0); }
  std::uint64_t timed_events(const StudyScene& s) const { return std::min(timing_events, long_events(s)); }
};

// The scenes of the engine measurements (examples/accuracy/NAME.toml).
const std::vector<std::string>& engine_scenes();

// ------------------------------------------------------------------------------- accuracy_engine.cpp

struct EngineRow {
  Setting setting;
  std::string scene;
  std::string failure;
  double disks = 0, events = 0, collisions = 0, timing_events = 0;
  double ns_per_event = 0;                 // median over the timed runs of the event loop's wall time / events
  std::vector<double> ns_runs;             // each timed run's ns/event
  double drift = 0, drift_max = 0;         // |E - E0| / E0 at the end, largest at the checkpoints
  double drift_at_timing = -1;             // the error run's drift after timing_events events
  double overlap = 0;                      // largest at a pair collision, fraction of the contact distance
  double overlap_snapshot = 0;             // largest over all near pairs at the checkpoints
  bool repeats_agree = true;               // the timed runs' drift equals the error run's (determinism)
  double log_bytes_per_event = -1;         // -1: no log for this type
  // accuracy_chaos.cpp
  std::vector<double> reversal_rms;        // per StudyPlan::reversal_collisions, in diameters
  std::vector<double> reversal_returned;   // fraction of disks back within a diameter
  // Collisions per disk until some disk is a mean free path (free_path), or a diameter, from its twin one
  // ulp apart; -1: not within divergence_cap.
  double free_path = 0, divergence_path = -1, divergence_diameter = -1;
};

// Runs body.template operator()<T>(scene, out) in a child process, with the row's scene loaded for its
// setting and T its precision: the shape of every per-row measurement of the engine study.
template <class Body>
ChildMeasurement in_child(const StudyPlan& plan, const EngineRow& row, Body body) {
  return run_child_measurement([&](std::string& out) {
    auto s = plan.load(row.scene, row.setting);
    if (!s) return out = s.error().message, 1;
    return with_precision(row.setting.precision,
                          [&]<class T>() { return body.template operator()<T>(s.value(), out); });
  });
}

// The error run (drift, overlap), then one run with the log on (bytes per event).
void measure_engine_errors(const StudyPlan& plan, EngineRow& row);
// One timed run, appended to row.ns_runs (ns_per_event: their median so far).
void measure_engine_time(const StudyPlan& plan, EngineRow& row);

// --------------------------------------------------------------------------------- accuracy_chaos.cpp

void measure_chaos(const StudyPlan& plan, EngineRow& row);

// ------------------------------------------------------------------------- accuracy_time_stepped.cpp

struct SteppedRow {
  std::string method;        // "event-driven", "event-driven (other seed)" or "time-stepped"
  double dt_over_tau = 0;    // time-stepped: dt in mean free times (gas)
  double dt = 0;
  double step_over_diameter = 0;  // v_rms dt / d: how far a disk moves in one step, in diameters (gas)
  double cpu_seconds = 0;    // median over repeats, the run to the same time (gas)
  double cpu_ratio = 0;      // cpu_seconds / the event-driven run's
  double pair_collisions = 0;
  double rate_error = 0;     // |rate / event-driven rate - 1|, elastic gas
  double energy_drift = 0;   // |E - E0| / E0 at the end, elastic gas
  double overlap = 0;        // largest overlap seen (elastic gas), fraction of the contact distance
  double cooling_cpu_seconds = 0;
  double cooling_cpu_ratio = 0;
  double cooling_error = 0;  // max over the comparison times of |E / E_event-driven - 1|, inelastic gas
  std::string failure;
};

struct SteppedStudy {
  double tau = 0, tau_cooling = 0;   // mean free times (time per collision per disk) of the two gases
  double diameter = 0, v_rms = 0;    // of the elastic gas
  double span = 0, cooling_span = 0;
  double rate = 0, rate_stderr = 0;  // event-driven pair collisions per disk per time, and its block error
  double energy_end = 0;             // event-driven E/E0 at the end of the cooling run
  std::vector<SteppedRow> rows;
};

SteppedStudy measure_time_stepped(const StudyPlan& plan);

// ------------------------------------------------------------------------------------ accuracy_log.cpp

struct LogRow {
  std::string label;
  std::uint64_t interval = 0;  // 0: log off
  bool rebuilds = false;
  double ns_per_event = 0, ratio_to_off = 0, bytes_per_event = 0, keyframe_share = 0;
  double seek_median = 0, seek_max = 0;  // seconds
  std::string failure;
};

std::vector<LogRow> measure_log(const StudyPlan& plan);

}  // namespace ede::study
