// Simulation: a scene run by the event-driven engine, with its event log, from a program.
//
//   ede::Scene scene = ede::load_scene_file("gas.toml").value();
//   ede::Simulation sim = ede::Simulation::create(scene, {.log_path = "gas.ede"}).value();
//   sim.run();                      // to the scene's stop condition
//   std::printf("%s", ede::to_text(sim.summary()).c_str());
//
// create() sets the scene up (placement, velocities; deterministic from the scene's seed), picks the
// engine built for exactly the effects the scene uses and the scalar type it asks for, and, with a
// log_path, records every event there (schema/FORMAT.md). run() goes to the scene's stop condition;
// advance_to(t) stops at a time and state() shows the disks there, for interactive use; both can be
// called again to go on. A run, its pauses and its log are the same events bit for bit whatever the
// slices: pausing never changes what happens. resume() continues a killed run from its log, in place,
// and the log it finishes is byte-identical to an uninterrupted run's.
// One thread at a time per Simulation; interrupt() alone may be called from another thread or a signal
// handler.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/events.hpp"
#include "ede/scene.hpp"
#include "ede/state.hpp"

namespace ede {

// What a finished (or interrupted) run reports: counts, times, energies, memory, effects.
struct RunSummary {
  std::string scene;          // the scene's name (its file)
  std::string scalar;         // "double", ...
  std::string effects;        // the engine instantiation's effects, e.g. "walls, elastic, grid 20x20"
  std::string status;         // why the run ended (to_string(RunStatus)), or "interrupted"
  std::string stall_message;  // why it stalled or came to rest, and what to do; else empty
  std::string setup_note;     // what setup did beyond placing (a [grow] run: the packing fraction reached); else empty
  std::uint64_t seed = 0;
  std::uint64_t disks = 0;
  EventCounts counts;
  double collisions_per_particle = 0;  // 2 * pair collisions / N
  double sim_time = 0;
  double wall_seconds = 0;             // time spent in the event loop by this process (setup excluded)
  double setup_seconds = 0;            // placement, first predictions (resume: reading the log back)
  std::uint64_t events_before = 0;     // a resumed run: events processed before this process took it up
  std::uint64_t collisions_before = 0; // ... and collisions among them
  double energy_initial = 0, energy_final = 0;  // kinetic
  double potential_final = 0;  // a stepped potential's energy at the end (0 for hard disks)
  bool stepped = false;        // the scene has a stepped potential (the summary shows the potential energy)
  double momentum_initial[2] = {0, 0}, momentum_final[2] = {0, 0};
  std::uint64_t engine_bytes = 0;      // the engine's own arrays
  std::uint64_t peak_rss_bytes = 0;    // the whole process, from getrusage

  // Rates of this process: events processed in wall_seconds (a resumed run's earlier events excluded).
  double events_per_second() const;      // every processed event (pair, wall, cell, wrap, action)
  double collisions_per_second() const;  // pair + wall 
};
std::string to_text(const RunSummary& s);  // aligned lines for people
std::string to_json(const RunSummary& s);  // one JSON object (stable keys) for scripts

// How far a run is, for progress displays.
struct Progress {
  double fraction = 0;       // towards the nearest stop condition, in [0, 1]
  std::uint64_t events = 0;  // processed so far
  double time = 0;           // simulated time
  double wall_seconds = 0;   // in the event loop so far
};

struct SimulationOptions {
  // Record every event here ("" = no log); an existing file is replaced, unless another run is writing it
  // or an ede tool is reading it (both hold a lock on it): then create() fails, naming the file.
  std::string log_path;
  // Called every 2^18 events or so (a few times a second) from run() and advance_to(), and once as they
  // return (fraction 1 when a stop condition was reached).
  std::function<void(const Progress&)> progress;
  // Keep running sums of the impulses the disks give the walls and each other (Simulation::impulses), for
  // a live pressure monitor. Off by default: it costs one more call per event.
  bool impulses = false;
  // The log writer recomputes every prediction the engine vouches for (a pair collision's time and
  // velocities are coded as exact without computing them: schema/FORMAT.md, "Versioning and the promise")
  // and the run fails with an error at the first that differs. Slower; the same bytes. The tests run every
  // example scene with it (ede-sim --check-exactness).
  bool check_exactness = false;
};

// Running sums over every event this process ran (SimulationOptions::impulses), exactly as
// ede/pressure.hpp sums them over a window of a log (the same formulas, in long double): the pressures of
// a window (t0, t1] come from the differences of two of these, taken at t0 and t1:
//   P_wall(w) = d wall[w] / (wall length * (t1 - t0))   (wall length Ly left and right, Lx bottom and top)
//   P_wall    = d (sum of wall[]) / (perimeter * (t1 - t0))
//   P_virial  = (K + d virial / (2 (t1 - t0))) / A_v     (K, A_v as in ede/pressure.hpp)
// 2D pressure is a force per unit length: the scene's mass / time^2.
struct ImpulseSums {
  double time = 0;                  // the run's time when taken
  std::array<double, 4> wall{};     // sum of |dp_n| per wall (WallId order: left, right, bottom, top)
  double virial = 0;                // W = sum over pair collisions of r_ij . dp_i (minimum image if periodic)
  std::uint64_t pair_collisions = 0, wall_collisions = 0;
};

// What the log of an interrupted or finished run holds, read back from the file.
struct LogKept {
  std::string path;
  std::uint64_t events = 0;                 // readable events
  double last_event_time = 0;
  bool complete = false;                    // closed by its index: the run finished
  bool resumable = false;                   // ede-sim --resume can continue it
  std::uint64_t resume_event = 0;           // the resume would restart from this event
  double resume_time = 0;                   // ... at this time
  std::uint64_t bytes = 0;
};

class Simulation {
 public:
  // A new run of `scene`. Fails with the scene's problem (overlaps, a packing that cannot be placed, ...)
  // or the log's (cannot write the file).
  static Result<Simulation> create(const Scene& scene, const SimulationOptions& options = {});
  // Continues the run logged in `log_path` (killed before it finished) from its last resumable keyframe,
  // writing the rest of the log in place. options.log_path is ignored.
  static Result<Simulation> resume(const std::string& log_path, const SimulationOptions& options = {});

  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;
  ~Simulation();  // closes the log (see close())

  // Runs until a stop condition of the scene holds (returns it), `max_events` more events were processed,
  // or interrupt() was called (both return Running). After close(), runs nothing and returns status().
  RunStatus run(std::uint64_t max_events = std::numeric_limits<std::uint64_t>::max());
  // Processes every event up to time t (not beyond) and leaves the state at t: returns Running, or the
  // stop condition met before t. Fails for a t before the current time.
  Result<RunStatus> advance_to(Time t);
  // Makes run() or advance_to() return at the next check (every few thousand events). Async-signal-safe.
  void interrupt();
  bool interrupted() const;

  RunStatus status() const;             // Running until a stop condition held
  Time time() const;                    // the current time
  State state() const;                  // every disk at the current time
  const Scene& scene() const;
  EventCounts counts() const;
  RunSummary summary() const;
  std::string message() const;          // why the run stalled or came to rest (what to do), else ""
  // The current state as exact CSV, in the run's own precision (float128 runs: 36 digits).
  Status write_state_csv(const std::string& path) const;

  // Ends the run here, as if a stop condition held now: processes the events still due at exactly the
  // current time, then closes the log the way a finished run's is closed (every event, the index, the
  // final time; status RunStatus::EndedByProgram), so every tool reads the log as complete,
  // `ede-replay verify` re-runs it to this time and `ede-replay --at end` is this state. Unlike close()
  // on an unfinished run, the log cannot be resumed afterwards. Then as close(). Idempotent.
  Status finish();
  // The impulse sums up to now; all zero unless SimulationOptions::impulses was set.
  ImpulseSums impulses() const;

  // Closes the log: a finished run's log gets its index; an unfinished one keeps every complete record
  // (ede-sim --resume continues it). Returns the first I/O error of the whole run, if any. Idempotent.
  Status close();
  // The log as it stands on disk after close(): what it holds and whether it can be resumed. Fails without
  // a log.
  Result<LogKept> log_kept() const;

  struct Impl;

 private:
  explicit Simulation(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Peak resident memory of this process so far (getrusage).
std::uint64_t peak_rss_bytes();

// Roughly the peak memory a run of `scene` takes (engine, setup, and with a log its writer), from the
// bytes per disk measured at 10^6 disks (docs/reliability.md): for refusing a run that cannot fit before
// it starts, with the number in the message.
inline constexpr std::uint64_t kBytesPerDiskWithLog = 400, kBytesPerDiskNoLog = 300;
std::uint64_t estimated_memory_bytes(const Scene& scene, bool with_log);

// The scene that continues the run logged in `log_path` from its state at time `at` (default: the log's
// end): the log's own scene with its [[species]] and [[actions]] replaced by [start] from = the log's
// absolute path, then `overrides` (e.g. physics.restitution=0.9, physics.gravity=[0,-1],
// start.reverse_velocities=true, stop.time=2). The run it makes starts at t = 0 and records the source
// log's content digest and the time in its own scene text (so in its log). ede-sim --continue uses it.
Result<Scene> continuation_scene(const std::string& log_path, std::optional<double> at = std::nullopt,
                                 const std::vector<Override>& overrides = {});

// Doubts about a valid scene (a run that may take very long, ...): one sentence each, naming the file, the
// key and what would be faster. The tools print them as warnings and go on. Empty for most scenes.
// (What can never work is refused by load_scene_file or Simulation::create instead.)
std::vector<std::string> scene_warnings(const Scene& scene);

}  // namespace ede
