// A live run: one Simulation driven by a worker thread at full speed (or at a chosen pace in simulated
// time per second), whose latest state is published for any number of tabs to fetch.
//
// The worker alone touches the Simulation. It advances in slices of ~1/60 s of wall time and publishes a
// copy of the state only when a page has asked for one since the last copy (or every 0.25 s for the
// monitors), so a page polling at its display rate sees states sampled at display times and the engine
// never waits for the browser; with nobody watching it copies nothing. Every run writes its event log
// (out-dir/live-N-SCENE.ede), so what was seen can be analysed afterwards with the other tools; FINISH, a
// new SETUP or the server's end close it with Simulation::finish, complete at the time the run was at.
// Frames carry the run's impulse sums (Simulation::impulses) for the page's pressure monitor.
// "Reverse time" (GasLab's button) is a scheduled reverse_velocities action at the current time: the run
// is made again from its scene with that action added and replayed to it at full speed, so the one log
// holds the whole story, reversal included, and `ede-replay verify` still holds. The reversal joins the
// scene's own schedule: by time, or, when the scene's actions are by collisions per disk (a scene cannot
// mix both), right after the latest pair collision before the press. Rejected: a new run
// started from the reversed current state (a second log, and a setup check that would refuse disks
// touching at that instant) and a reversal hook inside the engine (the library's API has none, and the
// engine's determinism rests on actions being part of the scene).
#pragma once

#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ede/ede.hpp"
#include "frame.hpp"

namespace ede::view {

struct LiveSetup {
  std::string scene_path;                // a scene file (already checked to be under a served folder)
  std::string scene_label;               // its name as the page shows it
  std::vector<std::string> overrides;    // key=value, as --set takes them
  double until = 100;                    // the run's stop.time (its other stop conditions are lifted)
};

class LiveRuns {
 public:
  LiveRuns(std::filesystem::path out_dir, std::uint64_t max_disks);
  ~LiveRuns();

  // Replaces the current run with a new one (paused at t = 0); its status as JSON, or the scene's error.
  Result<std::string> setup(const LiveSetup& setup);
  Status go();
  Status pause();
  Status reverse();
  Status finish();  // ends the run here: its log complete at the current time (Simulation::finish)
  void set_pace(double sim_time_per_second);  // 0: as fast as the engine goes
  // The latest published state as a frame (frame.hpp); null before the first SETUP.
  std::shared_ptr<const std::string> frame(const FrameRequest& request);
  std::string status_json();

  struct Run;  // the worker's state (live_run.cpp)

 private:
  void stop_current();

  std::filesystem::path out_dir_;
  std::uint64_t max_disks_;
  std::mutex mutex_;  // guards run_ (the pointer) and counter_
  std::shared_ptr<Run> run_;
  std::uint64_t counter_ = 0;
};

}  // namespace ede::view
