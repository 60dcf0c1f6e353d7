// Resuming a run from its log: the log's own scene planned again (setup is deterministic) and checked
// against the header's per-disk data, and the engine's resume point at the last resumable keyframe. The
// engine then continues from there and writes exactly the events an uninterrupted run writes after it.
// Also the resume point of any resumable keyframe, which verify compares with the re-run's rebuilds.
#pragma once

#include <memory>
#include <string>

#include "log/log_reader.hpp"
#include "replay/replay.hpp"
#include "run/run_plan.hpp"

namespace ede {

struct ResumedRun {
  RunPlan plan;
  std::shared_ptr<LogReader> log;  // the log to continue
};

Result<ResumedRun> plan_resumed_run(const std::string& log_path);

// The resume point and log continuation of the last resumable keyframe (T: the log's scalar type).
template <class T>
Result<Resumption<T>> prepare_resumption(const std::shared_ptr<LogReader>& log);

// The engine's resume point from what resumable keyframe `keyframe` stores (an error for another).
template <class T>
Result<ResumePoint<T>> resume_point_at(const Replay<T>& replay, std::size_t keyframe);

}  // namespace ede
