// Simulation (ede/simulation.hpp): the public face over Simulation::Impl (simulation_impl.hpp).
#include "ede/simulation.hpp"

#include <chrono>

#include "core/seconds_since.hpp"
#include "log/log_reader.hpp"
#include "run/run_resume.hpp"
#include "run/simulation_impl.hpp"

namespace ede {

Simulation::Simulation(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
Simulation::~Simulation() {
  if (impl_) (void)close();
}

// setup_seconds covers placement too (plan_run), not only the engine and the log writer.
Result<Simulation> Simulation::create(const Scene& scene, const SimulationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto plan = plan_run(scene);
  if (!plan) return plan.error();
  const double placement = seconds_since(start);
  auto impl = make_simulation_impl(std::move(plan).value(), nullptr, options);
  if (!impl) return impl.error();
  impl.value()->setup_seconds += placement;
  return Simulation(std::move(impl).value());
}

Result<Simulation> Simulation::resume(const std::string& log_path, const SimulationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto resumed = plan_resumed_run(log_path);
  if (!resumed) return resumed.error();
  const double reading = seconds_since(start);
  SimulationOptions o = options;
  o.log_path.clear();  // the log being resumed is the log
  auto impl = make_simulation_impl(std::move(resumed.value().plan), resumed.value().log, o);
  if (!impl) return impl.error();
  impl.value()->setup_seconds += reading;
  return Simulation(std::move(impl).value());
}

RunStatus Simulation::run(std::uint64_t max_events) {
  if (impl_->closed) return impl_->status;
  return impl_->drive(max_events, std::nullopt);
}

Result<RunStatus> Simulation::advance_to(Time t) {
  if (!(t >= impl_->time()))
    return Error{"advance_to(" + exact_text(t, impl_->scene.scalar) + "): the run is already at t = " +
                 exact_text(impl_->time(), impl_->scene.scalar) + "; a run only goes forward"};
  if (impl_->closed) return impl_->status;
  if (is_finished(impl_->status)) return impl_->status;
  return impl_->drive(std::numeric_limits<std::uint64_t>::max(), t);
}

void Simulation::interrupt() { impl_->interrupt_requested.store(true, std::memory_order_relaxed); }
bool Simulation::interrupted() const { return impl_->was_interrupted; }
RunStatus Simulation::status() const { return impl_->status; }
Time Simulation::time() const { return impl_->time(); }
State Simulation::state() const { return impl_->state(); }
const Scene& Simulation::scene() const { return impl_->scene; }
EventCounts Simulation::counts() const { return impl_->counts(); }
RunSummary Simulation::summary() const { return impl_->summary(); }
std::string Simulation::message() const { return impl_->message(); }
Status Simulation::write_state_csv(const std::string& path) const { return impl_->write_state_csv(path); }

Status Simulation::finish() {
  if (!impl_->closed) {
    impl_->interrupt_requested.store(false, std::memory_order_relaxed);  // the events due now are processed
    impl_->finish_here();
  }
  return close();
}

ImpulseSums Simulation::impulses() const { return impl_->impulses(); }

Status Simulation::close() {
  if (!impl_->close_result) {
    impl_->closed = true;
    impl_->close_result = impl_->close_log();
  }
  return *impl_->close_result;
}

Result<LogKept> Simulation::log_kept() const {
  if (impl_->log_path.empty()) return Error{"this run writes no log"};
  if (!impl_->closed) return Error{"the log is still being written: close() the Simulation first"};
  auto log = LogReader::open(impl_->log_path);
  if (!log) return log.error();
  const LogReader& r = *log.value();
  LogKept k;
  k.path = impl_->log_path;
  k.events = r.total_events();
  k.complete = r.complete();
  k.bytes = r.file_size();
  k.last_event_time = r.chunks().empty() ? r.keyframes().front().time_first : r.chunks().back().time_last;
  if (!r.complete())
    if (auto kf = r.last_resumable_keyframe()) {
      k.resumable = true;
      k.resume_event = r.keyframes()[kf.value()].first_event;
      k.resume_time = r.keyframes()[kf.value()].time_first;
    }
  return k;
}

}  // namespace ede
