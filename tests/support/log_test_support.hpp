// Helpers for log tests: run an engine with a LogWriter (and a Recorder) in-process; scratch files are
// temp_path's (tool_runner.hpp).
#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "ede/log.hpp"
#include "log/log_reader.hpp"
#include "log/log_writer.hpp"
#include "replay/replay.hpp"
#include "engine_test_support.hpp"
#include "tool_runner.hpp"  // temp_path

namespace ede::test {

template <class T>
struct LoggedRun {
  std::unique_ptr<EngineApi<T>> engine;
  std::unique_ptr<Recorder<T>> recorder = std::make_unique<Recorder<T>>();
  RunStatus status = RunStatus::Running;
  std::string path;
};

template <class T>
LoggedRun<T> run_logged(const InitialState& s, const EngineOptions& o, const std::string& file,
                        LogSettings settings = {}) {
  LoggedRun<T> r;
  r.path = temp_path(file);
  r.engine = engine<T>(s, o);
  LogRunInfo info;
  info.lx = s.lx;
  info.ly = s.ly;
  info.boundary = o.boundary;
  info.species_names = s.species_names;
  info.set_restitution(o.physics);
  info.rebuild_interval = o.rebuild_interval;
  info.tc_model = o.physics.tc > 0 && !o.physics.elastic();
  info.gx = o.physics.gravity[0];
  info.gy = o.physics.gravity[1];
  info.rotation = uses_rotation(o);
  info.steps = o.physics.has_steps();  // step events need format version 3
  info.engine_constants = true;     // all of the above, as the engine has them (run/log_run_info.cpp)
  settings.check_exactness = true;  // and every vouch of the engine's recomputed
  auto writer = LogWriter<T>::create(r.path, info, settings);
  if (!writer) throw std::runtime_error(writer.error().message);
  r.recorder->keep_states = true;
  r.engine->add_sink(writer.value().get());
  r.engine->add_sink(r.recorder.get());
  r.status = r.engine->run();
  if (!writer.value()->error().empty()) throw std::runtime_error(writer.value()->error());
  return r;
}

inline std::shared_ptr<LogReader> open_log(const std::string& path) {
  auto log = LogReader::open(path);
  if (!log) throw std::runtime_error(log.error().message);
  return log.value();
}

// The same log through the public face, for the analyses (they take a const Log&).
inline Log open_public_log(const std::string& path) {
  auto log = Log::open(path);
  if (!log) throw std::runtime_error(log.error().message);
  return std::move(log).value();
}

template <class T>
std::unique_ptr<Replay<T>> replay_of(const std::string& path) {
  auto r = Replay<T>::create(open_log(path));
  if (!r) throw std::runtime_error(r.error().message);
  return std::move(r).value();
}

}  // namespace ede::test
