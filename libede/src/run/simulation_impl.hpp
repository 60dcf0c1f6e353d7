// Simulation::Impl: the type-erased face of a run, and SimulationOf<T>, the run in scalar type T.
//
// The public Simulation holds an Impl; create() and resume() pick SimulationOf<T> once, for the scalar the
// scene asks for, so everything below runs in T with no further dispatch. The engine is driven in slices
// (run_slice events at a time): between slices interrupt() is noticed and progress is reported. Slicing
// never changes what happens (EngineApi::run continues exactly where it stopped).
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "ede/simulation.hpp"
#include "log/log_reader.hpp"
#include "run/run_plan.hpp"

namespace ede {

struct Simulation::Impl {
  virtual ~Impl() = default;
  virtual RunStatus drive(std::uint64_t max_events, std::optional<Time> until) = 0;
  virtual Time time() const = 0;
  virtual State state() const = 0;
  virtual EventCounts counts() const = 0;
  virtual RunSummary summary() const = 0;
  virtual std::string message() const = 0;
  virtual Status write_state_csv(const std::string& path) const = 0;
  virtual Status close_log() = 0;
  virtual void finish_here() = 0;  // Simulation::finish before close_log
  virtual ImpulseSums impulses() const = 0;

  Scene scene;
  SimulationOptions options;
  std::string log_path;  // "" without a log
  std::atomic<bool> interrupt_requested{false};
  bool was_interrupted = false;
  RunStatus status = RunStatus::Running;
  double setup_seconds = 0, wall_seconds = 0;
  std::uint64_t events_before = 0;  // resumed: events processed before this process took the run up
  std::uint64_t collisions_before = 0;
  std::string write_error;  // the log's first write error: the run stopped there
  bool closed = false;
  std::optional<Status> close_result;
};

// Makes the Impl for a planned run; `resumed`: the log it continues (null for a new run).
Result<std::unique_ptr<Simulation::Impl>> make_simulation_impl(RunPlan plan, std::shared_ptr<LogReader> resumed,
                                                               const SimulationOptions& options);

}  // namespace ede
