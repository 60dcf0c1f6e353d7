// What a Simulation needs before its engine exists: the scene, the initial state and the engine options,
// from a scene (a new run) or from a log (a resumed one), plus the resume point for the latter.
//
// A resumed run sets the log's own scene up again (setup is deterministic) and checks it against the
// header's per-disk data; the engine then continues from the last resumable keyframe and writes exactly
// the events an uninterrupted run writes after it.
#pragma once

#include <memory>
#include <string>

#include "core/initial_state.hpp"
#include "ede/scene.hpp"
#include "engine/engine.hpp"
#include "log/log_reader.hpp"
#include "log/log_writer.hpp"

namespace ede {

struct RunSetup {
  Scene scene;
  InitialState initial;
  EngineOptions options;
  std::shared_ptr<LogReader> resumed_log;  // set when resuming
};

Result<RunSetup> setup_new_run(const Scene& scene);
Result<RunSetup> setup_resumed_run(const std::string& log_path);

template <class T>
struct Resumption {
  ResumePoint<T> point;
  LogContinuation continuation;
};

// The resume point and log continuation of the last resumable keyframe (T: the log's scalar type).
template <class T>
Result<Resumption<T>> prepare_resumption(const std::shared_ptr<LogReader>& log);

}  // namespace ede
