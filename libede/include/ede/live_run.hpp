// LiveRun: one Simulation driven by a worker thread of its own, at full speed or at a chosen pace in
// simulated time per second, controlled from other threads (go, pause, reverse time, finish) and
// publishing its latest state for them to read: the run control behind a live view (ede-view).
//
// The worker alone touches the Simulation. It advances in slices of ~1/60 s of wall time and publishes a
// copy of the state only when a reader has asked for one since the last copy (request_state, or every
// 0.25 s), so a page polling at its display rate sees states sampled at display times and the engine
// never waits for it; with nobody watching it copies nothing. Every live run writes its event log, so
// what was seen can be analysed afterwards with the other tools; finish() or the LiveRun's end close it
// with Simulation::finish, complete at the time the run was at (a run that never moved removes its log).
// The published status carries the run's impulse sums (Simulation::impulses) for a pressure monitor.
// Reverse time (GasLab's button) is a scheduled reverse_velocities action at the current time: the run is
// made again from its scene with that action added and replayed to it at full speed, so the one log holds
// the whole story, reversal included, and `ede-replay verify` still holds. The reversal joins the scene's
// own schedule: by time, or, when the scene's actions are by collisions per disk (a scene cannot mix
// both), right after the latest pair collision before the press. Slicing and pausing never change the
// events (Simulation::run continues exactly where it stopped); only a reversal, recorded in the log's
// scene, depends on when it was asked for.
// Rejected: a new run started from the reversed current state (a second log, and a setup check that would
// refuse disks touching at that instant); a reversal hook inside the engine (its determinism rests on
// actions being part of the scene); and this control living in ede-view (a tool is a thin main).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/scene.hpp"
#include "ede/simulation.hpp"
#include "ede/state.hpp"

namespace ede {

struct LiveRunSetup {
  std::string scene_path;              // a scene file
  std::vector<std::string> overrides;  // key=value, as --set takes them
  double until = 100;                  // the run's stop.time (its other stop conditions are lifted)
  std::string log_path;                // where its event log goes
};

// What the worker published last.
struct LiveRunStatus {
  std::shared_ptr<const State> state;  // the latest published state (the initial one until the run moves)
  std::uint64_t collisions = 0;        // pair collisions up to `state`
  ImpulseSums impulses;                // of `state`
  double events_per_second = 0;
  double pace = 0.25;                  // simulated time per second (0: as fast as the engine goes)
  std::string status = "paused";       // "paused", "running", "finishing", "reversing: ...", "ended: ..."
  std::string message;                 // why it ended, or why a reversal could not be made
  bool running = false;                // GO was pressed and the run has not ended or paused
  bool catching_up = false;            // replaying to the time of a reversal
  bool ended = false;
  std::vector<double> reversals;              // the times reverse was pressed at
  std::vector<std::uint64_t> reversal_pairs;  // and the pair collisions they followed (actions by collisions)
};

class LiveRun {
 public:
  // The scene a live run of `setup` runs: the file with its overrides, stop.time = until, its other stop
  // conditions lifted far past any live run, and small log chunks (a run stopped by its end keeps its
  // complete chunks only). Loading it allocates no disks: a front end checks its size before start().
  static Result<Scene> scene_for(const LiveRunSetup& setup);
  // Starts the run of `scene` (scene_for's), paused at t = 0, writing its log at setup.log_path.
  static Result<std::unique_ptr<LiveRun>> start(const LiveRunSetup& setup, const Scene& scene);
  ~LiveRun();  // stop()
  // Stops the worker and ends the log where the run was (see above). Idempotent; status() still reads
  // the last published state after it, and the controls change nothing more.
  void stop();
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;

  Status go();
  Status pause();
  Status reverse();
  Status finish();                            // ends the run here: its log complete at the current time
  void set_pace(double sim_time_per_second);  // 0: as fast as the engine goes
  void request_state();                       // publish the next state the worker reaches
  LiveRunStatus status() const;
  const Scene& scene() const;
  const LiveRunSetup& setup() const;

  struct Impl;

 private:
  explicit LiveRun(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace ede
