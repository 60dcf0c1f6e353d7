// LiveRun; see ede/live_run.hpp for the design. Locks: Impl::m guards what the worker publishes and the
// requests it reads (running, pace, reverse, finish); Impl::sim_m guards the Simulation's address, so
// interrupt() from another thread never meets a Simulation being replaced by a reversal. The worker never
// holds Impl::m while it simulates.
#include "ede/live_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <thread>

#include "core/seconds_since.hpp"
#include "ede/number_text.hpp"
#include "run/live_schedule.hpp"

namespace ede {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct LiveRun::Impl {
  Scene scene;
  LiveRunSetup setup;
  std::size_t disks = 0;

  std::mutex sim_m;
  std::unique_ptr<Simulation> sim;

  mutable std::mutex m;
  std::condition_variable cv;
  bool quit = false, reverse_requested = false, finish_requested = false;
  LiveRunStatus published;  // what status() returns
  std::atomic<bool> wanted{false};
  std::thread worker;
  std::once_flag stopped;

  void publish(Simulation& s, double events_per_second);
  void do_reverse();
  void work();
  void stop();
};

namespace {

SimulationOptions log_options(const std::string& path) {
  SimulationOptions o;
  o.log_path = path;
  o.impulses = true;  // a live view's pressure monitor
  return o;
}

}  // namespace

void LiveRun::Impl::publish(Simulation& s, double events_per_second) {
  auto state = std::make_shared<const State>(s.state());
  const EventCounts counts = s.counts();
  const ImpulseSums impulses = s.impulses();
  std::lock_guard lock(m);
  published.state = std::move(state);
  published.impulses = impulses;
  published.collisions = counts.of(EventKind::Pair);
  published.events_per_second = events_per_second;
}

// Makes the run again with a reversal at its current time (by collisions per disk: right after its latest
// pair collision) and replays it there. The new scene is loaded before the run is replaced, so a reversal
// that cannot be made leaves the run as it was, with the reason in its message.
void LiveRun::Impl::do_reverse() {
  const double t_r = double(sim->time());
  const EventCounts before = sim->counts();
  const std::uint64_t pairs = before.of(EventKind::Pair);
  std::vector<double> times;
  std::vector<std::uint64_t> pair_list;
  {
    std::lock_guard lock(m);
    times = published.reversals;
    pair_list = published.reversal_pairs;
  }
  times.push_back(t_r);
  if (actions_by_collisions(scene)) pair_list.push_back(pairs);
  std::vector<Override> o = live_overrides(scene, setup);
  o.push_back(actions_override(scene, actions_by_collisions(scene) ? std::vector<double>() : times, pair_list, disks));
  std::string error = cannot_reverse(scene, t_r, pairs);
  Result<Scene> reversed = error.empty() ? load_scene_file(setup.scene_path, o) : Result<Scene>(Error{error});
  if (!reversed) {
    std::lock_guard lock(m);
    published.message = "reverse time: " + reversed.error().message;
    return;
  }
  {
    std::lock_guard lock(m);
    published.catching_up = true;
    published.status = "reversing: replaying to t = " + exact_number(t_r);
    published.message.clear();
  }
  {
    std::lock_guard lock(sim_m);
    (void)sim->close();  // the new run rewrites the same log from the start
    sim.reset();
    auto made = Simulation::create(reversed.value(), log_options(setup.log_path));
    if (made)
      sim = std::make_unique<Simulation>(std::move(made).value());
    else
      error = made.error().message;
  }
  if (sim) {
    auto reached = sim->advance_to(t_r);
    if (!reached) error = reached.error().message;
    // The replay is the same run with one more action: every action so far, and this one, happened.
    else if (sim->counts().of(EventKind::Action) != before.of(EventKind::Action) + 1)
      error = "the replayed run holds " + std::to_string(sim->counts().of(EventKind::Action)) + " actions at t = " +
              exact_number(t_r) + ", not " + std::to_string(before.of(EventKind::Action) + 1);
  }
  std::lock_guard lock(m);
  published.catching_up = false;
  published.reversals = times;
  published.reversal_pairs = pair_list;
  if (!error.empty() || !sim) {
    published.running = false;
    published.ended = true;
    published.status = "ended: the reversal failed";
    published.message = error;
  } else {
    published.status = published.running ? "running" : "paused";
  }
}

void LiveRun::Impl::work() {
  Clock::time_point last_publish = Clock::now(), rate_time = Clock::now(), anchor_wall{};
  std::uint64_t rate_events = 0, batch = 2000;
  long double anchor_t = 0;
  bool anchored = false;
  double rate = 0;
  for (;;) {
    double pace = 0;
    bool reverse = false, finish = false;
    {
      std::unique_lock lock(m);
      if (!published.running) anchored = false;
      cv.wait(lock, [&] { return quit || published.running || reverse_requested || finish_requested; });
      if (quit) return;
      pace = published.pace;
      reverse = reverse_requested;
      finish = finish_requested;
      reverse_requested = finish_requested = false;
    }
    if (finish && sim) {  // finish(): the log ends here, complete (Simulation::finish)
      const Status finished = sim->finish();
      publish(*sim, rate);
      std::lock_guard lock(m);
      published.running = false;
      published.ended = true;
      published.status = "ended: finished here at t = " + exact_number(double(sim->time()));
      published.message = finished ? "" : finished.error().message;
      continue;
    }
    if (reverse) {
      do_reverse();
      anchored = false;
      if (sim) publish(*sim, rate);
      continue;
    }
    if (!sim) return;
    Simulation& s = *sim;
    const Clock::time_point t0 = Clock::now();
    RunStatus run_status = RunStatus::Running;
    if (pace > 0) {
      if (!anchored) anchor_t = s.time(), anchor_wall = t0, anchored = true;
      long double target = anchor_t + (long double)pace * seconds_since(anchor_wall);
      const long double cap = s.time() + (long double)pace * 0.1L;
      if (target > cap) target = cap, anchor_t = cap, anchor_wall = t0;  // the engine is behind: keep up
      if (target > s.time()) {
        auto reached = s.advance_to(target);
        run_status = reached ? reached.value() : RunStatus::NonFinite;
      }
    } else {
      run_status = s.run(batch);
      const double took = seconds_since(t0);
      if (took < 0.008) batch = std::min<std::uint64_t>(batch * 2, 1u << 26);
      if (took > 0.03 && batch > 256) batch /= 2;
    }
    const std::uint64_t events = s.counts().events();
    if (seconds_since(rate_time) >= 0.25) {
      rate = double(events - std::min(events, rate_events)) / seconds_since(rate_time);
      rate_events = events;
      rate_time = Clock::now();
    }
    if (run_status != RunStatus::Running && !s.interrupted()) {
      const Status closed = s.close();
      publish(s, rate);
      std::lock_guard lock(m);
      published.running = false;
      published.ended = true;
      published.status = std::string("ended: ") + to_string(run_status);
      published.message = closed ? s.message() : closed.error().message;
      continue;
    }
    bool paused = false;
    {
      std::lock_guard lock(m);
      paused = !published.running;
    }
    if (paused || wanted.exchange(false) || seconds_since(last_publish) > 0.25) {  // paused: its exact state
      publish(s, rate);
      last_publish = Clock::now();
    }
    if (pace > 0) std::this_thread::sleep_until(t0 + std::chrono::milliseconds(16));
  }
}

// The worker stopped, the log ended where the run was: complete and verifiable (Simulation::finish), or
// removed when the run never moved (set up, never started: nothing worth keeping).
void LiveRun::Impl::stop() {
  {
    std::lock_guard lock(m);
    quit = true;
  }
  cv.notify_all();
  {
    std::lock_guard lock(sim_m);
    if (sim) sim->interrupt();
  }
  if (worker.joinable()) worker.join();
  if (!sim) return;
  const bool never_ran = sim->counts().events() == 0 && published.reversals.empty();
  if (never_ran)
    (void)sim->close();
  else
    (void)sim->finish();
  std::error_code ec;
  if (never_ran) fs::remove(setup.log_path, ec);
}

Result<Scene> LiveRun::scene_for(const LiveRunSetup& setup) {
  auto base = load_scene_file(setup.scene_path);
  if (!base) return base.error();
  return load_scene_file(setup.scene_path, live_overrides(base.value(), setup));
}

Result<std::unique_ptr<LiveRun>> LiveRun::start(const LiveRunSetup& setup, const Scene& scene) {
  auto impl = std::make_unique<Impl>();
  impl->scene = scene;
  impl->setup = setup;
  auto sim = Simulation::create(scene, log_options(setup.log_path));
  if (!sim) return sim.error();
  impl->sim = std::make_unique<Simulation>(std::move(sim).value());
  impl->published.state = std::make_shared<const State>(impl->sim->state());
  impl->disks = impl->published.state->size();
  Impl& r = *impl;
  impl->worker = std::thread([&r] { r.work(); });
  return std::unique_ptr<LiveRun>(new LiveRun(std::move(impl)));
}

LiveRun::LiveRun(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LiveRun::~LiveRun() { stop(); }
void LiveRun::stop() { std::call_once(impl_->stopped, [this] { impl_->stop(); }); }

Status LiveRun::go() {
  {
    std::lock_guard lock(impl_->m);
    LiveRunStatus& p = impl_->published;
    if (p.ended) return Error{"the run has ended (" + p.status + "): press SETUP for a new one"};
    p.running = true;
    if (!p.catching_up) p.status = "running";
  }
  impl_->cv.notify_all();
  return Ok{};
}

Status LiveRun::pause() {
  std::lock_guard lock(impl_->m);
  LiveRunStatus& p = impl_->published;
  p.running = false;
  impl_->wanted = true;
  if (!p.ended && !p.catching_up) p.status = "paused";
  return Ok{};
}

Status LiveRun::finish() {
  {
    std::lock_guard lock(impl_->m);
    LiveRunStatus& p = impl_->published;
    if (p.ended) return Error{"the run has ended already (" + p.status + ")"};
    p.running = false;
    impl_->finish_requested = true;
    p.status = "finishing";
  }
  impl_->cv.notify_all();
  return Ok{};
}

Status LiveRun::reverse() {
  {
    std::lock_guard lock(impl_->m);
    const LiveRunStatus& p = impl_->published;
    if (p.ended) return Error{"the run has ended: press SETUP for a new one"};
    // Paused, the published state is the run's own: say at once why it cannot be reversed (a running run
    // is checked by its worker, which then leaves the reason in the status's message).
    if (const std::string why = cannot_reverse(impl_->scene, p.state ? double(p.state->time) : 0.0, p.collisions);
        !p.running && !why.empty())
      return Error{"reverse time: " + why};
    impl_->reverse_requested = true;
  }
  impl_->cv.notify_all();
  return Ok{};
}

void LiveRun::set_pace(double pace) {
  std::lock_guard lock(impl_->m);
  impl_->published.pace = pace;
}

void LiveRun::request_state() { impl_->wanted = true; }

LiveRunStatus LiveRun::status() const {
  std::lock_guard lock(impl_->m);
  return impl_->published;
}

const Scene& LiveRun::scene() const { return impl_->scene; }
const LiveRunSetup& LiveRun::setup() const { return impl_->setup; }

}  // namespace ede
