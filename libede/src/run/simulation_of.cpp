// SimulationOf<T>: a run in scalar type T behind Simulation::Impl (simulation_impl.hpp).
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/seconds_since.hpp"
#include "core/state_csv.hpp"
#include "core/state_of.hpp"
#include "run/end_check.hpp"
#include "run/finite_guard.hpp"
#include "run/impulse_meter.hpp"
#include "run/progress_fraction.hpp"
#include "run/run_resume.hpp"
#include "run/run_summary.hpp"
#include "run/simulation_impl.hpp"

namespace ede {

namespace {

// Events per slice: interrupt() is noticed within a slice (~50 ms at 1 M events/s), and progress is
// reported every kSlicesPerProgress slices.
constexpr std::uint64_t kSlice = 1u << 16;
constexpr int kSlicesPerProgress = 4;

template <class T>
class SimulationOf final : public Simulation::Impl {
 public:
  // `plan.initial` has given its disks to the engine already (only its species names are left); px0 and
  // py0 are its momentum, taken before.
  SimulationOf(RunPlan plan, RunEngine<T> run, std::uint64_t first_event, double px0, double py0)
      : plan_(std::move(plan)), engine_(std::move(run.engine)), log_(std::move(run.log)), px0_(px0), py0_(py0) {
    Sink<T>* log_sink = nullptr;
    if constexpr (kLogScalar<T>) log_sink = log_.get();
    // The guard passes every finite outcome on to the log (first, as DESIGN.md orders the sinks), and at
    // the end asks the end check whether the run may end as it did.
    const Scene& sc = plan_.scene;
    EndCheckContext context{sc.source_name, sc.scalar, sc.lx, sc.ly, sc.boundary == BoundaryKind::Periodic,
                            sc.physics.has_gravity(), sc.shear_rate.value_or(0)};
    guard_ = std::make_unique<FiniteGuard<T>>(
        log_sink, first_event, [context](T time, const Particles<T>& p, RunStatus status) {
          return end_of_run_problem(p, time, status, context);
        });
    engine_->add_sink(guard_.get());
  }

  RunStatus drive(std::uint64_t max_events, std::optional<Time> until) override {
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t left = max_events;
    int slices = 0;
    if (is_finished(status) || !write_error.empty()) return status;
    RunStatus s = RunStatus::Running;
    while (left > 0 && !interrupt_requested.load(std::memory_order_relaxed)) {
      const std::uint64_t n = std::min(left, kSlice);
      const std::uint64_t before = engine_->counts().events() + engine_->counts().of(EventKind::Sample);
      s = until ? engine_->run_until(T(*until), n) : engine_->run(n);
      if (guard_->tripped()) {
        s = guard_->stop_status();
        break;
      }
      if (s != RunStatus::Running) break;
      // A log that can no longer be written (a full disk) stops the run: going on would compute events
      // nobody can keep. The log keeps every complete record; close() reports the error.
      if (write_error = log_error(); !write_error.empty()) break;
      const std::uint64_t done = engine_->counts().events() + engine_->counts().of(EventKind::Sample) - before;
      if (until && done < n) break;  // paused at `until`
      left -= std::min(left, n);
      if (options.progress && ++slices % kSlicesPerProgress == 0) report_progress(start);
    }
    if (interrupt_requested.exchange(false)) was_interrupted = true;
    // A last report as the call returns, so a progress display ends where the run did (100 % when a stop
    // condition was reached, not the last periodic report's 90 %).
    if (options.progress) report_progress(start, reached_stop(s));
    wall_seconds += seconds_since(start);
    status = s;
    return s;
  }

  Time time() const override { return Time(engine_->time()); }
  EventCounts counts() const override { return engine_->counts(); }
  std::string message() const override {
    return guard_->tripped() ? guard_->message() : engine_->stall_message();
  }

  State state() const override {
    return state_of(engine_->particles(), engine_->time(), engine_->counts().events(), plan_.scene.lx,
                    plan_.scene.ly, plan_.scene.boundary, plan_.initial.species_names);
  }

  RunSummary summary() const override {
    RunSummary s = summarize(*engine_, px0_, py0_);
    s.scene = plan_.scene.source_name;
    s.seed = plan_.scene.seed;
    s.status = !write_error.empty()                                ? "stopped: the event log could not be written"
               : was_interrupted && status == RunStatus::Running ? "interrupted"
                                                                 : to_string(status);
    if (guard_->tripped()) s.stall_message = guard_->message();
    s.wall_seconds = wall_seconds;
    s.setup_seconds = setup_seconds;
    s.setup_note = plan_.initial.note;
    s.stepped = plan_.scene.physics.has_steps();
    s.events_before = events_before;
    s.collisions_before = collisions_before;
    return s;
  }

  // Through a temporary file renamed into place once complete (a full disk leaves the old file, never a
  // short one under the final name); a device or FIFO is written directly.
  Status write_state_csv(const std::string& path) const override {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
      return write_state_csv_file(path, engine_->particles(), engine_->time(), plan_.initial.species_names);
    const std::string temp = path + ".tmp-" + std::to_string(::getpid());
    Status s = write_state_csv_file(temp, engine_->particles(), engine_->time(), plan_.initial.species_names);
    if (!s) {
      ::unlink(temp.c_str());
      return Error{"cannot write the final state to '" + path + "': " + s.error().message, ErrorKind::Io};
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      ::unlink(temp.c_str());
      return Error{"cannot put the final state in place as '" + path + "': " + why, ErrorKind::Io};
    }
    return Ok{};
  }

  Status close_log() override {
    if constexpr (kLogScalar<T>) {
      if (!log_) return Ok{};
      // A finished run's log was closed by on_finish; destroying the writer of an unfinished one flushes
      // every complete record. The engine keeps a pointer to the sink, so a closed Simulation never runs
      // the engine again (Simulation::run checks).
      const std::string error = log_->error();
      log_.reset();
      if (!error.empty()) return Error{"the event log " + log_path + " is incomplete: " + error, ErrorKind::Io};
    }
    return Ok{};
  }

  // Processes the events still due at the current time (as advance_to(now) would), then has the log
  // written as a finished run's, with status EndedByProgram (Simulation::finish).
  void finish_here() override {
    if (is_finished(status) || !write_error.empty() || guard_->tripped()) return;
    drive(std::numeric_limits<std::uint64_t>::max(), Time(engine_->time()));
    if (is_finished(status) || !write_error.empty() || guard_->tripped()) return;  // it ended on its own
    guard_->on_finish(engine_->time(), engine_->particles(), RunStatus::EndedByProgram);
    status = guard_->tripped() ? guard_->stop_status() : RunStatus::EndedByProgram;
  }

  void measure_impulses() {
    meter_ = std::make_unique<ImpulseMeter<T>>(plan_.scene.boundary == BoundaryKind::Periodic, plan_.scene.lx,
                                               plan_.scene.ly);
    engine_->add_sink(meter_.get());
  }
  ImpulseSums impulses() const override {
    return meter_ ? meter_->sums(double(engine_->time())) : ImpulseSums{double(engine_->time())};
  }

  std::string log_error() const {
    if constexpr (kLogScalar<T>) return log_ ? log_->error() : std::string();
    return {};
  }

  std::uint64_t logged_events() const {
    if constexpr (kLogScalar<T>) return log_ ? log_->events_logged() : 0;
    return 0;
  }

 private:
  static bool reached_stop(RunStatus s) {
    return s == RunStatus::ReachedTime || s == RunStatus::ReachedEvents || s == RunStatus::ReachedCollisions ||
           s == RunStatus::ReachedEnergy;
  }

  void report_progress(std::chrono::steady_clock::time_point start, bool done = false) const {
    const EventCounts& c = engine_->counts();
    double energy_ratio = 1;
    if (plan_.scene.stop.energy_fraction && engine_->initial_kinetic_energy() > 0)
      energy_ratio = kinetic_energy(engine_->particles()) / engine_->initial_kinetic_energy();
    const ProgressInputs now{double(engine_->time()), c.events(), c.of(EventKind::Pair), energy_ratio};
    const double fraction = done ? 1.0 : progress_fraction(plan_.scene.stop, engine_->particles().size(), now);
    options.progress(Progress{fraction, c.events(),
                              double(engine_->time()), wall_seconds + seconds_since(start)});
  }

  RunPlan plan_;
  std::unique_ptr<EngineApi<T>> engine_;
  LogWriterFor<T> log_;
  std::unique_ptr<FiniteGuard<T>> guard_;
  std::unique_ptr<ImpulseMeter<T>> meter_;
  double px0_ = 0, py0_ = 0;
};

template <class T>
Result<std::unique_ptr<Simulation::Impl>> make_in(RunPlan plan, const std::shared_ptr<LogReader>& resumed,
                                                  const SimulationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<Resumption<T>> resumption;
  if constexpr (kLogScalar<T>) {
    if (resumed) {
      auto r = prepare_resumption<T>(resumed);
      if (!r) return r.error();
      resumption = std::move(r).value();
    }
  }
  double px0 = 0, py0 = 0;
  for (std::size_t i = 0; i < plan.initial.size(); ++i) {
    px0 += plan.initial.mass[i] * plan.initial.vx[i];
    py0 += plan.initial.mass[i] * plan.initial.vy[i];
  }
  const std::string log_path = resumed ? resumed->path() : options.log_path;
  auto run = start_run<T>(plan, {log_path, options.check_exactness}, resumption ? &*resumption : nullptr);
  if (!run) return run.error();
  const std::uint64_t before = resumption ? resumption->point.counts.events() : 0;
  const std::uint64_t collisions_before = resumption ? resumption->point.counts.collisions() : 0;
  const std::uint64_t first_logged = resumption ? resumption->continuation.events_before : 0;
  const Scene scene = plan.scene;
  auto impl = std::make_unique<SimulationOf<T>>(std::move(plan), std::move(run).value(), first_logged, px0, py0);
  if (options.impulses) impl->measure_impulses();
  impl->scene = scene;
  impl->options = options;
  impl->log_path = log_path;
  impl->events_before = before;
  impl->collisions_before = collisions_before;
  impl->setup_seconds = seconds_since(start);
  return std::unique_ptr<Simulation::Impl>(std::move(impl));
}

}  // namespace

Result<std::unique_ptr<Simulation::Impl>> make_simulation_impl(RunPlan plan, std::shared_ptr<LogReader> resumed,
                                                               const SimulationOptions& options) {
  if (plan.scene.scalar == ScalarKind::Float128 && !options.log_path.empty())
    return Error{plan.scene.source_name + ": float128 runs are for the accuracy study and write no event log (the "
                     "log format holds float, double and long double): run without a log (no -o)",
                 ErrorKind::Unsupported};
  return with_engine_scalar(plan.scene.scalar,
                            [&]<class T>() { return make_in<T>(std::move(plan), resumed, options); });
}

}  // namespace ede
