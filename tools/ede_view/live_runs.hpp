// The server's live run: at most one ede::LiveRun at a time (ede/live_run.hpp: the worker thread, pace,
// reversal, finish, the log), made from a scene under a served folder, with its log named in the output
// folder, refused above --max-disks, and its latest state packed as frames (frame.hpp) for any number of
// tabs. A new SETUP ends the current run first (its log complete where it was). The run control itself is
// the library's; this file is what only a server needs: naming, the size limit, frames and JSON.
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ede/ede.hpp"
#include "ede/live_run.hpp"
#include "frame.hpp"

namespace ede::view {

struct LiveSetup {
  std::string scene_path;              // a scene file (already checked to be under a served folder)
  std::string scene_label;             // its name as the page shows it
  std::vector<std::string> overrides;  // key=value, as --set takes them
  double until = 100;                  // the run's stop.time (its other stop conditions are lifted)
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
  // Why the current run's frames cannot be packed as asked (colouring_refused); "" when they can or there is no run.
  std::string refused(const FrameRequest& request);
  std::string status_json();

  struct Run;  // a LiveRun with its label and its frame cache (live_runs.cpp)

 private:
  std::shared_ptr<Run> current();
  Status control(Status (LiveRun::*act)());
  void stop_current();

  std::filesystem::path out_dir_;
  std::uint64_t max_disks_;
  std::mutex mutex_;  // guards run_ (the pointer) and counter_
  std::shared_ptr<Run> run_;
  std::uint64_t counter_ = 0;
};

}  // namespace ede::view
