// plan_resumed_run, prepare_resumption and resume_point_at; see run_resume.hpp.
#include "run/run_resume.hpp"

#include <optional>

namespace ede {

Result<ResumedRun> plan_resumed_run(const std::string& path) {
  auto log = LogReader::open(path);
  if (!log) return log.error();
  const LogHeaderInfo& h = log.value()->header();
  if (log.value()->complete())
    return Error{path + ": the run already finished (" + log.value()->final_status() + "); nothing to resume"};
  auto scene = parse_scene_text(h.scene_text, h.scene_name);
  if (!scene) return Error{path + ": the scene in the log's header no longer loads: " + scene.error().message};
  auto plan = plan_run(scene.value());
  if (!plan) return plan.error();
  if (plan.value().initial.size() != h.disks)
    return Error{path + ": setting the scene up again gives " + std::to_string(plan.value().initial.size()) +
                 " disks, the log has " + std::to_string(h.disks) + " (a different ede version?)"};
  if (plan.value().options.rebuild_interval != h.rebuild_interval)
    return Error{path + ": the rebuild interval differs from the log's (a different ede version?)"};
  return ResumedRun{std::move(plan).value(), log.value()};
}

// The engine's ResumePoint and the log's StoredRebuildPoint hold the same fields; they are two types
// because they live on two floors (the engine's input, the log's record), and only run/ sees both.
template <class T>
Result<ResumePoint<T>> resume_point_at(const Replay<T>& replay, std::size_t keyframe) {
  auto stored = replay.rebuild_point(keyframe);
  if (!stored) return stored.error();
  StoredRebuildPoint<T>& s = stored.value();
  ResumePoint<T> r;
  r.time = s.time;
  r.disks = std::move(s.disks);
  r.last_collision = std::move(s.last_collision);
  r.omega = std::move(s.omega);
  r.counts = s.counts;
  r.next_sample_index = s.next_sample_index;
  r.next_action_index = s.next_action_index;
  r.same_time_events = s.same_time_events;
  r.initial_energy = s.initial_energy;
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
    auto point = resume_point_at(*replay.value(), k);
    if (point) return Resumption<T>{std::move(point).value(), continuation_from(*log, k), log->header().format_version};
    if (!first_error) first_error = point.error();
  }
  return *first_error;
}

template Result<Resumption<float>> prepare_resumption<float>(const std::shared_ptr<LogReader>&);
template Result<Resumption<double>> prepare_resumption<double>(const std::shared_ptr<LogReader>&);
template Result<Resumption<long double>> prepare_resumption<long double>(const std::shared_ptr<LogReader>&);
template Result<ResumePoint<float>> resume_point_at<float>(const Replay<float>&, std::size_t);
template Result<ResumePoint<double>> resume_point_at<double>(const Replay<double>&, std::size_t);
template Result<ResumePoint<long double>> resume_point_at<long double>(const Replay<long double>&, std::size_t);

}  // namespace ede
