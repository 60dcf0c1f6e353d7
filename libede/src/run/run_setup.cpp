// setup_new_run, setup_resumed_run and prepare_resumption; see run_setup.hpp.
#include "run/run_setup.hpp"

#include <optional>

#include "replay/replay.hpp"
#include "run/run_checks.hpp"
#include "run/run_start.hpp"
#include "run/scale_checks.hpp"
#include "setup/setup.hpp"

namespace ede {

Result<RunSetup> setup_new_run(const Scene& scene) {
  if (scene.start) {
    auto started = start_from_state(scene);
    if (!started) return started.error();
    StartedRun& s = started.value();
    if (Status c = check_run_can_finish(s.scene, s.initial); !c) return c.error();
    RunSetup r{std::move(s.scene), std::move(s.initial), {}, nullptr};
    r.options = engine_options_from(r.scene, r.initial.size());
    r.options.rotation = r.options.rotation || !r.initial.omega.empty();  // a rough state keeps its spins
    return r;
  }
  if (Status s = check_scene_scales(scene); !s) return s.error();  // before setup computes with them
  auto initial = build_initial_state(scene);
  if (!initial) return initial.error();
  if (Status s = check_run_can_finish(scene, initial.value()); !s) return s.error();
  RunSetup r{scene, std::move(initial).value(), {}, nullptr};
  r.options = engine_options_from(r.scene, r.initial.size());
  return r;
}

Result<RunSetup> setup_resumed_run(const std::string& path) {
  auto log = LogReader::open(path);
  if (!log) return log.error();
  const LogHeaderInfo& h = log.value()->header();
  if (log.value()->complete())
    return Error{path + ": the run already finished (" + log.value()->final_status() + "); nothing to resume"};
  auto scene = parse_scene_text(h.scene_text, h.scene_name);
  if (!scene) return Error{path + ": the scene in the log's header no longer loads: " + scene.error().message};
  auto r = setup_new_run(scene.value());
  if (!r) return r.error();
  if (r.value().initial.size() != h.disks)
    return Error{path + ": setting the scene up again gives " + std::to_string(r.value().initial.size()) +
                 " disks, the log has " + std::to_string(h.disks) + " (a different ede version?)"};
  if (r.value().options.rebuild_interval != h.rebuild_interval)
    return Error{path + ": the rebuild interval differs from the log's (a different ede version?)"};
  r.value().resumed_log = log.value();
  return r;
}

// From the last resumable keyframe; when that one cannot be read back (damaged), from the one before it,
// and so on: a resume from an earlier keyframe redoes more events and still writes the same bytes.
template <class T>
Result<Resumption<T>> prepare_resumption(const std::shared_ptr<LogReader>& log) {
  auto last = log->last_resumable_keyframe();
  if (!last) return last.error();
  auto replay = Replay<T>::create(log);
  if (!replay) return replay.error();
  std::optional<Error> first_error;
  for (std::size_t k = last.value() + 1; k-- > 0;) {
    if (!log->keyframes()[k].resumable) continue;
    auto point = replay.value()->resume_point(k);
    if (point) return Resumption<T>{std::move(point).value(), continuation_from(*log, k)};
    if (!first_error) first_error = point.error();
  }
  return *first_error;
}

template Result<Resumption<float>> prepare_resumption<float>(const std::shared_ptr<LogReader>&);
template Result<Resumption<double>> prepare_resumption<double>(const std::shared_ptr<LogReader>&);
template Result<Resumption<long double>> prepare_resumption<long double>(const std::shared_ptr<LogReader>&);

}  // namespace ede
