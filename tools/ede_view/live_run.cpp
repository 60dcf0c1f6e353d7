// LiveRuns; see live_run.hpp for the design. Locks: LiveRuns::mutex_ guards which run is current;
// Run::m guards what the worker publishes and the requests it reads (running, pace, reverse); Run::sim_m
// guards the Simulation's address, so interrupt() from another thread never meets a Simulation being
// replaced by a reversal. The worker never holds Run::m while it simulates.
#include "live_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

namespace ede::view {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct LiveRuns::Run {
  Scene scene;
  LiveSetup setup;
  std::string log_path;
  std::vector<double> reversals;              // the times reverse was pressed at
  std::vector<std::uint64_t> reversal_pairs;  // ... and the pair collisions they followed (by collisions)

  std::mutex sim_m;
  std::unique_ptr<Simulation> sim;

  std::mutex m;
  std::condition_variable cv;
  bool running = false, quit = false, reverse_requested = false, finish_requested = false, ended = false,
       catching_up = false;
  double pace = 0.25;
  std::shared_ptr<const State> state;
  Reference reference;
  std::uint64_t collisions = 0;
  ImpulseSums impulses;  // of `state`, for the pressure monitor
  double events_per_second = 0;
  std::string status = "paused", message;
  std::atomic<bool> wanted{false};
  std::thread worker;

  // The last frame packed, for the state and monitors it was packed from: tabs (or one tab polling faster
  // than the worker publishes) asking again get these bytes instead of the statistics over every disk again.
  std::mutex frame_m;
  std::shared_ptr<const State> framed_state;
  std::string framed_extras;
  std::shared_ptr<const std::string> framed;
  FrameRequest framed_request;
  // The statistics of the last frame packed, reused for newer states of a large running run (below).
  FrameStatistics statistics;
  std::shared_ptr<const State> statistics_state;
  Clock::time_point statistics_wall{};
  double statistics_seconds = 0;  // what computing them took
};

namespace {

SimulationOptions log_options(const std::string& path) {
  SimulationOptions o;
  o.log_path = path;
  o.impulses = true;  // the page's pressure monitor
  return o;
}

constexpr std::size_t kFreshStatisticsDisks = 20000;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string text_of(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The overrides that make a scene a live run: stop at `until`, other stop conditions lifted far away.
std::vector<Override> live_overrides(const Scene& base, const LiveSetup& setup) {
  std::vector<Override> o;
  for (const std::string& s : setup.overrides) o.push_back({s});
  o.push_back({"stop.time=" + text_of(setup.until)});
  // A run stopped by a new SETUP or by the server's end keeps its complete chunks only: small chunks lose
  // at most 1024 events (the log's bytes per event barely change).
  if (!base.log.chunk_events) o.push_back({"log.chunk_events=1024"});
  // Lifted far past any live run, yet within what the run checks allow with samples by collisions per
  // disk (1e8 samples: 1e15 with samples every 5 collisions per disk was refused as endless sampling).
  if (base.stop.collisions_per_particle)
    o.push_back({"stop.collisions_per_particle=" +
                 text_of(base.sample_collisions ? std::min(1e15, 1e8 * *base.sample_collisions) : 1e15)});
  if (base.stop.events) o.push_back({"stop.events=1000000000000000000"});
  return o;
}

// The scene's actions are scheduled by collisions per disk (the loader refuses a mix with time actions).
bool actions_by_collisions(const Scene& scene) {
  return !scene.actions.empty() && scene.actions.front().collisions_per_disk.has_value();
}

// The collisions per disk c whose action fires right after pair collision number `pairs` of a run of n
// disks: the engine fires it at the first P >= ceil(c n / 2) (computed in double), so c is moved by
// one double at a time until that is exactly `pairs` (2 pairs / n alone can round either way).
double collisions_per_disk_for(std::uint64_t pairs, std::size_t n) {
  const auto target = [n](double c) { return std::uint64_t(std::ceil(c * double(n) / 2)); };
  double c = 2.0 * double(pairs) / double(n);
  while (target(c) > pairs) c = std::nextafter(c, 0.0);
  while (target(c) < pairs) c = std::nextafter(c, HUGE_VAL);
  return c;
}

// actions = the scene's own plus the reversals asked for, in one schedule: by time (a reversal at each
// time in `times`) when the scene's actions are by time or it has none, else by collisions per disk (a
// reversal right after each pair collision number in `pairs`, of a run of n disks).
Override actions_override(const Scene& scene, const std::vector<double>& times, const std::vector<std::uint64_t>& pairs,
                          std::size_t n) {
  const bool by_collisions = actions_by_collisions(scene);
  std::vector<double> when = by_collisions ? std::vector<double>() : times;
  for (std::uint64_t p : pairs) when.push_back(collisions_per_disk_for(p, n));
  for (const ActionSpec& a : scene.actions) when.push_back(a.collisions_per_disk.value_or(a.time));
  std::sort(when.begin(), when.end());
  const std::string key = by_collisions ? "{collisions_per_disk=" : "{time=";
  std::string text = "actions=[";
  for (std::size_t k = 0; k < when.size(); ++k)
    text += (k ? "," : "") + key + text_of(when[k]) + ",kind=\"reverse_velocities\"}";
  return {text + "]"};
}

}  // namespace

namespace {

void publish(LiveRuns::Run& r, Simulation& sim, double events_per_second) {
  auto state = std::make_shared<const State>(sim.state());
  const EventCounts counts = sim.counts();
  const ImpulseSums impulses = sim.impulses();
  std::lock_guard lock(r.m);
  r.state = std::move(state);
  r.impulses = impulses;
  r.collisions = counts.of(EventKind::Pair);
  r.events_per_second = events_per_second;
}

// Why a reversal cannot be scheduled now, or "": an action needs a time > 0, or, in a scene whose actions
// are by collisions per disk, a pair collision to follow.
std::string cannot_reverse(const Scene& scene, double time, std::uint64_t pairs) {
  if (actions_by_collisions(scene) && pairs == 0)
    return "this scene schedules its actions by collisions per disk, so a reversal is one too (right after the "
           "latest pair collision): there has been none yet. Fix: press GO, then reverse";
  if (!actions_by_collisions(scene) && !(time > 0))
    return "a reversal is an action at the current time, which must be after t = 0. Fix: press GO, then reverse";
  return "";
}

// Makes the run again with a reversal at its current time (by collisions per disk: right after its latest
// pair collision) and replays it there (live_run.hpp). The new scene is loaded before the run is
// replaced, so a reversal that cannot be made leaves the run as it was, with the reason in its message.
void do_reverse(LiveRuns::Run& r) {
  const double t_r = double(r.sim->time());
  const EventCounts before = r.sim->counts();
  const std::uint64_t pairs = before.of(EventKind::Pair);
  std::vector<double> times = r.reversals;
  std::vector<std::uint64_t> pair_list = r.reversal_pairs;
  times.push_back(t_r);
  if (actions_by_collisions(r.scene)) pair_list.push_back(pairs);
  std::vector<Override> o = live_overrides(r.scene, r.setup);
  o.push_back(actions_override(r.scene, actions_by_collisions(r.scene) ? std::vector<double>() : times, pair_list,
                               r.reference.x0.size()));
  std::string error = cannot_reverse(r.scene, t_r, pairs);
  Result<Scene> scene = error.empty() ? load_scene_file(r.setup.scene_path, o) : Result<Scene>(Error{error});
  if (!scene) {
    std::lock_guard lock(r.m);
    r.message = "reverse time: " + scene.error().message;
    return;
  }
  {
    std::lock_guard lock(r.m);
    r.catching_up = true;
    r.status = "reversing: replaying to t = " + text_of(t_r);
    r.message.clear();
  }
  {
    std::lock_guard lock(r.sim_m);
    (void)r.sim->close();  // the new run rewrites the same log from the start
    r.sim.reset();
    auto sim = Simulation::create(scene.value(), log_options(r.log_path));
    if (sim)
      r.sim = std::make_unique<Simulation>(std::move(sim).value());
    else
      error = sim.error().message;
  }
  if (r.sim) {
    auto reached = r.sim->advance_to(t_r);
    if (!reached) error = reached.error().message;
    // The replay is the same run with one more action: every action so far, and this one, happened.
    else if (r.sim->counts().of(EventKind::Action) != before.of(EventKind::Action) + 1)
      error = "the replayed run holds " + std::to_string(r.sim->counts().of(EventKind::Action)) +
              " actions at t = " + text_of(t_r) + ", not " + std::to_string(before.of(EventKind::Action) + 1);
  }
  std::lock_guard lock(r.m);
  r.catching_up = false;
  r.reversals = times;
  r.reversal_pairs = pair_list;
  if (!error.empty() || !r.sim) {
    r.running = false;
    r.ended = true;
    r.status = "ended: the reversal failed";
    r.message = error;
  } else {
    r.status = r.running ? "running" : "paused";
  }
}

void work(LiveRuns::Run& r) {
  Clock::time_point last_publish = Clock::now(), rate_time = Clock::now(), anchor_wall{};
  std::uint64_t rate_events = 0, batch = 2000;
  long double anchor_t = 0;
  bool anchored = false;
  double rate = 0;
  for (;;) {
    double pace = 0;
    bool reverse = false, finish = false;
    {
      std::unique_lock lock(r.m);
      if (!r.running) anchored = false;
      r.cv.wait(lock, [&] { return r.quit || r.running || r.reverse_requested || r.finish_requested; });
      if (r.quit) return;
      pace = r.pace;
      reverse = r.reverse_requested;
      finish = r.finish_requested;
      r.reverse_requested = r.finish_requested = false;
    }
    if (finish && r.sim) {  // FINISH: the log ends here, complete (Simulation::finish)
      const Status finished = r.sim->finish();
      publish(r, *r.sim, rate);
      std::lock_guard lock(r.m);
      r.running = false;
      r.ended = true;
      r.status = "ended: finished here at t = " + text_of(double(r.sim->time()));
      r.message = finished ? "" : finished.error().message;
      continue;
    }
    if (reverse) {
      do_reverse(r);
      anchored = false;
      if (r.sim) publish(r, *r.sim, rate);
      continue;
    }
    if (!r.sim) return;
    Simulation& sim = *r.sim;
    const Clock::time_point t0 = Clock::now();
    RunStatus status = RunStatus::Running;
    if (pace > 0) {
      if (!anchored) anchor_t = sim.time(), anchor_wall = t0, anchored = true;
      long double target = anchor_t + (long double)pace * seconds_since(anchor_wall);
      const long double cap = sim.time() + (long double)pace * 0.1L;
      if (target > cap) target = cap, anchor_t = cap, anchor_wall = t0;  // the engine is behind: keep up
      if (target > sim.time()) {
        auto reached = sim.advance_to(target);
        status = reached ? reached.value() : RunStatus::NonFinite;
      }
    } else {
      status = sim.run(batch);
      const double took = seconds_since(t0);
      if (took < 0.008) batch = std::min<std::uint64_t>(batch * 2, 1u << 26);
      if (took > 0.03 && batch > 256) batch /= 2;
    }
    const std::uint64_t events = sim.counts().events();
    if (seconds_since(rate_time) >= 0.25) {
      rate = double(events - std::min(events, rate_events)) / seconds_since(rate_time);
      rate_events = events;
      rate_time = Clock::now();
    }
    if (status != RunStatus::Running && !sim.interrupted()) {
      const Status closed = sim.close();
      publish(r, sim, rate);
      std::lock_guard lock(r.m);
      r.running = false;
      r.ended = true;
      r.status = std::string("ended: ") + to_string(status);
      r.message = closed ? sim.message() : closed.error().message;
      continue;
    }
    bool paused = false;
    {
      std::lock_guard lock(r.m);
      paused = !r.running;
    }
    if (paused || r.wanted.exchange(false) || seconds_since(last_publish) > 0.25) {  // paused: its exact state
      publish(r, sim, rate);
      last_publish = Clock::now();
    }
    if (pace > 0) std::this_thread::sleep_until(t0 + std::chrono::milliseconds(16));
  }
}

}  // namespace

LiveRuns::LiveRuns(fs::path out_dir, std::uint64_t max_disks) : out_dir_(std::move(out_dir)), max_disks_(max_disks) {}

LiveRuns::~LiveRuns() { stop_current(); }

void LiveRuns::stop_current() {
  std::shared_ptr<Run> run;
  {
    std::lock_guard lock(mutex_);
    run = std::move(run_);
  }
  if (!run) return;
  {
    std::lock_guard lock(run->m);
    run->quit = true;
  }
  run->cv.notify_all();
  {
    std::lock_guard lock(run->sim_m);
    if (run->sim) run->sim->interrupt();
  }
  if (run->worker.joinable()) run->worker.join();
  if (!run->sim) return;
  const bool never_ran = run->sim->counts().events() == 0 && run->reversals.empty();
  // A live run's log ends where the run was: complete, verifiable (Simulation::finish).
  if (never_ran)
    (void)run->sim->close();
  else
    (void)run->sim->finish();
  std::error_code ec;
  if (never_ran) fs::remove(run->log_path, ec);  // SETUP without GO: nothing worth keeping
}

Result<std::string> LiveRuns::setup(const LiveSetup& setup) {
  auto base = load_scene_file(setup.scene_path);
  if (!base) return base.error();
  auto scene = load_scene_file(setup.scene_path, live_overrides(base.value(), setup));
  if (!scene) return scene.error();
  std::uint64_t disks = 0;
  for (const SpeciesSpec& s : scene.value().species) disks += std::uint64_t(std::max<std::int64_t>(s.count, 0));
  if (disks > max_disks_)
    return Error{"a live run of " + std::to_string(disks) + " disks is more than this server allows (" +
                 std::to_string(max_disks_) + ", ede-view --max-disks)"};
  stop_current();
  auto run = std::make_shared<Run>();
  run->scene = scene.value();
  run->setup = setup;
  {
    std::lock_guard lock(mutex_);
    std::error_code ec;
    fs::create_directories(out_dir_, ec);
    const std::string stem = fs::path(setup.scene_path).stem().string();
    do {
      run->log_path = (out_dir_ / ("live-" + std::to_string(++counter_) + "-" + stem + ".ede")).string();
    } while (fs::exists(run->log_path));
  }
  auto sim = Simulation::create(run->scene, log_options(run->log_path));
  if (!sim) return sim.error();
  run->sim = std::make_unique<Simulation>(std::move(sim).value());
  const State initial = run->sim->state();
  run->reference = make_reference(initial);
  run->state = std::make_shared<const State>(initial);
  Run& r = *run;
  run->worker = std::thread([&r] { work(r); });
  {
    std::lock_guard lock(mutex_);
    run_ = run;
  }
  return status_json();
}

Status LiveRuns::go() {
  std::lock_guard lock(mutex_);
  if (!run_) return Error{"no run: press SETUP first"};
  {
    std::lock_guard run_lock(run_->m);
    if (run_->ended) return Error{"the run has ended (" + run_->status + "): press SETUP for a new one"};
    run_->running = true;
    if (!run_->catching_up) run_->status = "running";
  }
  run_->cv.notify_all();
  return Ok{};
}

Status LiveRuns::pause() {
  std::lock_guard lock(mutex_);
  if (!run_) return Error{"no run: press SETUP first"};
  std::lock_guard run_lock(run_->m);
  run_->running = false;
  run_->wanted = true;
  if (!run_->ended && !run_->catching_up) run_->status = "paused";
  return Ok{};
}

Status LiveRuns::finish() {
  std::lock_guard lock(mutex_);
  if (!run_) return Error{"no run: press SETUP first"};
  {
    std::lock_guard run_lock(run_->m);
    if (run_->ended) return Error{"the run has ended already (" + run_->status + ")"};
    run_->running = false;
    run_->finish_requested = true;
    run_->status = "finishing";
  }
  run_->cv.notify_all();
  return Ok{};
}

Status LiveRuns::reverse() {
  std::lock_guard lock(mutex_);
  if (!run_) return Error{"no run: press SETUP first"};
  {
    std::lock_guard run_lock(run_->m);
    if (run_->ended) return Error{"the run has ended: press SETUP for a new one"};
    // Paused, the published state is the run's own: say at once why it cannot be reversed (a running
    // run is checked by its worker, which then leaves the reason in the status's message).
    if (const std::string why = cannot_reverse(run_->scene, run_->state ? double(run_->state->time) : 0.0,
                                               run_->collisions);
        !run_->running && !why.empty())
      return Error{"reverse time: " + why};
    run_->reverse_requested = true;
  }
  run_->cv.notify_all();
  return Ok{};
}

void LiveRuns::set_pace(double pace) {
  std::lock_guard lock(mutex_);
  if (!run_) return;
  std::lock_guard run_lock(run_->m);
  run_->pace = pace;
}

std::shared_ptr<const std::string> LiveRuns::frame(const FrameRequest& request) {
  std::shared_ptr<Run> run;
  {
    std::lock_guard lock(mutex_);
    run = run_;
  }
  if (!run) return nullptr;
  std::shared_ptr<const State> state;
  FrameExtras extras;
  bool running = false;
  {
    std::lock_guard lock(run->m);
    state = run->state;
    running = run->running && !run->catching_up;
    extras.collisions = double(run->collisions);
    const ImpulseSums& p = run->impulses;
    extras.json_fields = "\"impulses\":" +
                         nlohmann::json{{"time", p.time}, {"wall", p.wall}, {"virial", p.virial},
                                        {"pair_collisions", p.pair_collisions}, {"wall_collisions", p.wall_collisions}}
                             .dump() +
                         ",\"events_per_second\":" + nlohmann::json(run->events_per_second).dump() +
                         ",\"status\":" + nlohmann::json(run->status).dump() +
                         ",\"message\":" + nlohmann::json(run->message).dump() +
                         ",\"log\":" + nlohmann::json(fs::path(run->log_path).filename().string()).dump() +
                         segments_field(run->scene);
  }
  run->wanted = true;
  if (!state) return nullptr;
  std::lock_guard lock(run->frame_m);
  if (state != run->framed_state || !(request == run->framed_request) || extras.json_fields != run->framed_extras) {
    // The statistics pass over every disk: for every frame up to 20 000 disks and of a run that is not
    // running (a paused or ended run's frame is exact), else at most every 0.1 s of wall time (the page
    // redraws its histograms and monitors at most 10 times a second anyway) and at most 10 % of the time
    // (the pass takes ~30 ms at 10^5 disks, ~0.3 s at 10^6 on a loaded machine: then every 0.3 s, 3 s).
    const bool fresh = state->size() <= kFreshStatisticsDisks || !running || !run->statistics_state ||
                       seconds_since(run->statistics_wall) >= std::max(0.1, 10 * run->statistics_seconds);
    if (state != run->statistics_state && fresh) {
      const Clock::time_point t0 = Clock::now();
      run->statistics = frame_statistics(*state, run->reference);
      run->statistics_state = state;
      run->statistics_wall = Clock::now();
      run->statistics_seconds = seconds_since(t0);
    }
    run->framed = std::make_shared<const std::string>(pack_frame(*state, run->reference, extras, request, run->statistics));
    run->framed_state = state;
    run->framed_request = request;
    run->framed_extras = extras.json_fields;
  }
  return run->framed;
}

std::string LiveRuns::status_json() {
  std::shared_ptr<Run> run;
  {
    std::lock_guard lock(mutex_);
    run = run_;
  }
  if (!run) return nlohmann::json{{"status", "none"}}.dump();
  std::lock_guard lock(run->m);
  return nlohmann::json{{"status", run->status},
                        {"scene", run->setup.scene_label},
                        {"log", fs::path(run->log_path).filename().string()},
                        {"log_path", run->log_path},
                        {"time", run->state ? double(run->state->time) : 0.0},
                        {"events", run->state ? run->state->events : 0},
                        {"disks", run->state ? run->state->size() : 0},
                        {"events_per_second", run->events_per_second},
                        {"pace", run->pace},
                        {"reversals", run->reversals},
                        {"reversal_pairs", run->reversal_pairs},
                        {"message", run->message}}
      .dump();
}

}  // namespace ede::view
