// LiveRuns; see live_runs.hpp. Locks: LiveRuns::mutex_ guards which run is current; Run::frame_m the frame
// cache. The LiveRun guards its own state (ede/live_run.hpp).
#include "live_runs.hpp"

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>

namespace ede::view {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct LiveRuns::Run {
  std::unique_ptr<LiveRun> live;
  std::string scene_label;
  Reference reference;  // of the initial state

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

constexpr std::size_t kFreshStatisticsDisks = 20000;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

LiveRuns::LiveRuns(fs::path out_dir, std::uint64_t max_disks) : out_dir_(std::move(out_dir)), max_disks_(max_disks) {}

LiveRuns::~LiveRuns() { stop_current(); }

std::shared_ptr<LiveRuns::Run> LiveRuns::current() {
  std::lock_guard lock(mutex_);
  return run_;
}

// Stops its worker and ends its log where the run was; a request still holding the run reads its last state.
void LiveRuns::stop_current() {
  std::shared_ptr<Run> run;
  {
    std::lock_guard lock(mutex_);
    run = std::move(run_);
  }
  if (run) run->live->stop();
}

Result<std::string> LiveRuns::setup(const LiveSetup& setup) {
  LiveRunSetup live{setup.scene_path, setup.overrides, setup.until, ""};
  auto scene = LiveRun::scene_for(live);
  if (!scene) return scene.error();
  std::uint64_t disks = 0;
  for (const SpeciesSpec& s : scene.value().species) disks += std::uint64_t(std::max<std::int64_t>(s.count, 0));
  if (disks > max_disks_)
    return Error{"a live run of " + std::to_string(disks) + " disks is more than this server allows (" +
                 std::to_string(max_disks_) + ", ede-view --max-disks)"};
  stop_current();
  {
    std::lock_guard lock(mutex_);
    std::error_code ec;
    fs::create_directories(out_dir_, ec);
    const std::string stem = fs::path(setup.scene_path).stem().string();
    do {
      live.log_path = (out_dir_ / ("live-" + std::to_string(++counter_) + "-" + stem + ".ede")).string();
    } while (fs::exists(live.log_path));
  }
  auto started = LiveRun::start(live, scene.value());
  if (!started) return started.error();
  auto run = std::make_shared<Run>();
  run->live = std::move(started).value();
  run->scene_label = setup.scene_label;
  run->reference = make_reference(*run->live->status().state, run->live->scene().physics.steps);
  {
    std::lock_guard lock(mutex_);
    run_ = run;
  }
  return status_json();
}

// One of the LiveRun's controls on the current run.
Status LiveRuns::control(Status (LiveRun::*act)()) {
  const auto run = current();
  return run ? ((*run->live).*act)() : Error{"no run: press SETUP first"};
}

Status LiveRuns::go() { return control(&LiveRun::go); }
Status LiveRuns::pause() { return control(&LiveRun::pause); }
Status LiveRuns::finish() { return control(&LiveRun::finish); }
Status LiveRuns::reverse() { return control(&LiveRun::reverse); }

void LiveRuns::set_pace(double pace) {
  if (const auto run = current()) run->live->set_pace(pace);
}

std::string LiveRuns::refused(const FrameRequest& request) {
  const auto run = current();
  return run ? colouring_refused(request, run->reference) : "";
}

std::shared_ptr<const std::string> LiveRuns::frame(const FrameRequest& request) {
  const auto run = current();
  if (!run) return nullptr;
  const LiveRunStatus s = run->live->status();
  const std::string& log_path = run->live->setup().log_path;
  const bool running = s.running && !s.catching_up;
  FrameExtras extras;
  extras.collisions = double(s.collisions);
  const ImpulseSums& p = s.impulses;
  extras.json_fields = "\"impulses\":" +
                       nlohmann::json{{"time", p.time}, {"wall", p.wall}, {"virial", p.virial},
                                      {"pair_collisions", p.pair_collisions}, {"wall_collisions", p.wall_collisions}}
                           .dump() +
                       ",\"events_per_second\":" + nlohmann::json(s.events_per_second).dump() +
                       ",\"status\":" + nlohmann::json(s.status).dump() +
                       ",\"message\":" + nlohmann::json(s.message).dump() +
                       ",\"log\":" + nlohmann::json(fs::path(log_path).filename().string()).dump() +
                       segments_field(run->live->scene());
  run->live->request_state();
  const std::shared_ptr<const State>& state = s.state;
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
  const auto run = current();
  if (!run) return nlohmann::json{{"status", "none"}}.dump();
  const LiveRunStatus s = run->live->status();
  const std::string& log_path = run->live->setup().log_path;
  return nlohmann::json{{"status", s.status},
                        {"scene", run->scene_label},
                        {"log", fs::path(log_path).filename().string()},
                        {"log_path", log_path},
                        {"time", s.state ? double(s.state->time) : 0.0},
                        {"events", s.state ? s.state->events : 0},
                        {"disks", s.state ? s.state->size() : 0},
                        {"events_per_second", s.events_per_second},
                        {"pace", s.pace},
                        {"reversals", s.reversals},
                        {"reversal_pairs", s.reversal_pairs},
                        {"clusters_unavailable", clusters_unavailable(run->reference.bonds)},
                        {"message", s.message}}
      .dump();
}

}  // namespace ede::view
