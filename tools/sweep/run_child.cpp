// The child process of one run (see sweep.hpp): scene = base scene + the run's overrides, through the
// library (load_scene_file), so a bad point fails exactly as `ede-sim --set` would and becomes a row with
// that message. A log left by a killed process of the same run is resumed from its last resumable
// keyframe (Simulation::resume: the finished log is byte-identical to an uninterrupted run's); a finished
// run whose row was written for another `collect` list is only measured again. The row is written last,
// after the log is closed, measured and digested: its presence means the run is whole.
#include <sys/prctl.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>

#include "ede/ede.hpp"
#include "interrupt.hpp"
#include "sweep.hpp"
#include "sweep_inputs.hpp"

namespace ede::sweep {

namespace {

// The status column's word for a run that ended abnormally (the error column gets the library's words and
// remedy).
std::string status_word(RunStatus s) {
  switch (s) {
    case RunStatus::Stalled: return "stalled";
    case RunStatus::Collapsed: return "collapsed";
    case RunStatus::CameToRest: return "came to rest";
    case RunStatus::NonFinite: return "non-finite";
    case RunStatus::Inexact: return "inexact";
    default: return to_string(s);
  }
}

bool normal_end(RunStatus s) {
  return s == RunStatus::ReachedTime || s == RunStatus::ReachedEvents || s == RunStatus::ReachedCollisions ||
         s == RunStatus::ReachedEnergy || s == RunStatus::NoMoreEvents;
}

// A log an earlier, killed process of this very run left: resumable, and of the same scene.
bool can_resume(const std::string& path, const Scene& scene) {
  if (!std::filesystem::exists(path)) return false;
  auto log = Log::open(path);
  if (!log) return false;
  const LogInfo& info = log.value().info();
  return !info.complete && info.resumable_keyframes > 0 && info.scene_text == scene.source_text;
}

// A finished run of the same point whose row was written for another `collect`: its log is complete and
// still the one the row's digest describes, so measuring it again is enough.
std::optional<std::pair<RunRow, RunSummary>> finished_run(const Sweep& s, const PlannedRun& r, const Log& log,
                                                         const Scene& scene) {
  auto row = read_row_file(row_path(s, r));
  if (!row || row.value().overrides != r.overrides || !final_status(row.value().status) || row.value().digest.empty() ||
      !log.info().complete || log.info().scene_text != scene.source_text)
    return std::nullopt;
  auto summary = summary_from_json(row.value().summary);
  if (!summary) return std::nullopt;
  auto digest = log.content_digest();
  if (!digest || digest.value() != row.value().digest) return std::nullopt;
  return std::make_pair(std::move(row).value(), std::move(summary).value());
}

// The run's values (and notes): the tool's own measurement, or the sweep's quantities.
Result<Measured> measure(const Sweep& s, const PlannedRun& r, const std::string& path, const Log& log,
                         const RunSummary& summary, bool fresh) {
  if (s.measure) return s.measure(RunToMeasure{r, path, log, summary, fresh});
  auto values = collect_quantities(s.spec.collect, summary, log);
  if (!values) return values.error();
  return Measured{std::move(values).value(), {}};
}

}  // namespace

int run_child(const Sweep& s, std::size_t k) {
  // The run ends with the process that waits for it: a worker killed (kill -9, an MPI job aborted) leaves
  // no orphan writing a log that the next execution of the sweep would resume (Linux: PR_SET_PDEATHSIG;
  // SIGTERM stops the run at its next check with its log resumable).
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() == 1) return 143;
  const auto start = std::chrono::steady_clock::now();
  const PlannedRun& r = s.runs[k];
  RunRow row;
  row.index = r.index;
  row.name = r.name;
  row.overrides = r.overrides;
  row.collect = s.spec.collect;
  row.log = log_cell(s, r);
  row.measured_with = s.measured_with;
  row.values.assign(s.spec.collect.size(), std::numeric_limits<double>::quiet_NaN());
  const std::string path = log_path(s, r);
  const auto finish = [&](const std::string& status, const std::string& error) {
    row.status = status;
    row.error = error;
    std::error_code ignored;
    if (!s.keep_logs) std::filesystem::remove(path, ignored);  // measured (or failed): the row only
    if (!std::filesystem::exists(path)) row.log.clear();
    row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Status w = write_row_file(row_path(s, r), row);
    if (!w) std::fprintf(stderr, "ede-sweep: %s\n", w.error().message.c_str());
    return w ? 0 : 1;
  };
  auto scene = scene_of(s, r);
  if (!scene) return finish("failed", scene.error().message);
  if (std::filesystem::exists(path))
    if (auto old = Log::open(path))
      if (auto done = finished_run(s, r, old.value(), scene.value())) {
        auto m = measure(s, r, path, old.value(), done->second, false);
        if (!m) return finish("failed", "measuring the log: " + m.error().message);
        row.values = m.value().values;
        row.notes = m.value().notes;
        row.digest = done->first.digest;
        row.summary = done->first.summary;
        return finish(done->first.status, done->first.error);
      }
  auto sim = can_resume(path, scene.value()) ? Simulation::resume(path) : Simulation::create(scene.value(), {path, {}});
  if (!sim) return finish("failed", sim.error().message);
  RunStatus status;
  {
    tools::InterruptGuard guard(sim.value());
    status = sim.value().run();
  }
  const Status closed = sim.value().close();
  if (sim.value().interrupted()) return tools::InterruptGuard::exit_status();  // no row: the run is not whole
  if (!closed) return finish("failed", closed.error().message);
  auto log = Log::open(path);
  if (!log) return finish("failed", log.error().message);
  auto digest = log.value().content_digest();
  if (!digest) return finish("failed", digest.error().message);
  row.digest = digest.value();
  row.summary = summary_to_json(sim.value().summary());
  auto m = measure(s, r, path, log.value(), sim.value().summary(), true);
  if (!m) return finish("failed", "measuring the log: " + m.error().message);
  row.values = m.value().values;
  row.notes = m.value().notes;
  return normal_end(status) ? finish("ok", "")
                             : finish(status_word(status), std::string(to_string(status)) + ": " + sim.value().message());
}

}  // namespace ede::sweep
