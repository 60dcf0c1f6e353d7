// The engine's interface inside the library: options, and EngineApi<T>, created by make_engine<T>().
//
// make_engine looks at the effects a scene uses (walls or periodic; elastic or dissipative; gravity) once,
// and returns the Engine instantiation with the fewest effects compiled in that computes the run (the
// table: EngineKind, engine_factory.hpp): an elastic gas runs code in which restitution and TC do not
// exist. The virtual calls here happen per run() call, never per event. The scalar type T (float, double,
// long double) is the caller's choice; where the library was built with EDE_HAVE_FLOAT128, __float128 too
// (engine only: the log and replay do not know it).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/initial_state.hpp"
#include "core/energy.hpp"
#include "core/particles.hpp"
#include "ede/error.hpp"
#include "ede/events.hpp"
#include "ede/scene.hpp"
#include "core/sink.hpp"
#include "engine/thermostat.hpp"

namespace ede {

enum class Algorithm {
  Cells,     // uniform grid + per-particle lazy state + one event per particle: O(log N) per event
  AllPairs,  // the naive baseline: after each event, the disks involved are checked against all N others
};

struct EngineOptions {
  BoundaryKind boundary = BoundaryKind::Walls;
  PhysicsSpec physics;
  StopSpec stop;
  std::optional<double> sample_interval;
  std::optional<double> sample_collisions;  // or samples every this many collisions per disk (Scene::sample_collisions)
  std::vector<ActionSpec> actions;      // sorted by time (or all by collisions_per_disk, sorted by it)
  Algorithm algorithm = Algorithm::Cells;
  // Every this many events the predictions are rebuilt from the state alone, a point a run can be resumed
  // from bit for bit (0: only at start and after actions). Changes round-off, so it is part of a run's
  // definition; engine_options_from() takes it from the scene (automatic: auto_rebuild_interval).
  std::uint64_t rebuild_interval = 0;
  // Give up (RunStatus::Stalled) after this many consecutive events at one and the same time
  // (0: max(10^6, 100 N)).
  std::uint64_t stall_limit = 0;
  // The disks carry omega (Scene::rotates: some beta > -1 or some species spins): a rough engine runs.
  bool rotation = false;
  // A speed choice only, the same events either way: up to this many disks the neighbour scan tests pairs
  // without branches (engine_core.hpp, consider_pair). Faster while the disks' records stay in the L2/L3
  // caches (measured +7 to +18 % at 10^4-4*10^4 disks), slower once every scan waits on memory (10^5,
  // 10^6: -5 to -15 %), where the branches let the core run ahead to the next neighbours' loads. The
  // all-pairs baseline (Algorithm::AllPairs) always branches: most of its pairs are far and receding.
  std::size_t branch_free_scan_up_to = 65536;
  // Also a speed choice only: from this many disks on, the engine prefetches the records of the next few
  // events' disks (the queue's next buckets), of their partners and of their neighbours while it processes
  // the current event (engine_core.hpp, prefetch_upcoming). Measured +12 % at 10^5 and 10^6 disks for the
  // first stages and +6 to +19 % more at 10^6 for the neighbours, nothing at 10^4 where every record is in
  // the cache anyway; from 2^15 on, like the replay's lookahead.
  std::size_t prefetch_upcoming_from = 32768;
  // The Andersen thermostat: the species' own ([species.thermostat]; physics.thermostat covers the rest)
  // and the scene's seed, from which its draws are made (room_thermostat.hpp).
  std::vector<SpeciesThermostat> species_thermostats;
  std::uint64_t seed = 1;
  // A Lees-Edwards box (boundary Periodic, Scene::shear_rate): the images above and below slide in x at
  // +-shear_rate * ly (lees_edwards.hpp). Absent: an ordinary periodic or walled box.
  std::optional<double> shear_rate;
};

// The TC model is on when a scene dissipates and sets tc > 0 (an elastic scene's tc changes nothing).
inline bool uses_tc_model(const PhysicsSpec& ph) { return ph.tc > 0 && !ph.elastic(); }
// A run needs a rough engine: the disks spin, or some contact is rough.
inline bool uses_rotation(const EngineOptions& o) { return o.rotation || o.physics.rough(); }
// A run needs the sheared engine: a Lees-Edwards box.
inline bool uses_shear(const EngineOptions& o) { return o.shear_rate.has_value(); }
// A run needs a thermostat engine: [thermostat], or some species' own with a rate above 0.
inline bool uses_thermostat(const EngineOptions& o) {
  bool any = o.physics.thermostat.has_value();
  for (const SpeciesThermostat& s : o.species_thermostats) any = any || s.rate > 0;
  return any;
}

// The engine options a scene asks for; `disks` sizes the automatic rebuild interval.
EngineOptions engine_options_from(const Scene& scene, std::size_t disks);
// max(2^20, 16 N) events: rebuilding costs ~N predictions, so this keeps it under ~1% of the run, and a
// killed run loses at most a few seconds of work.
std::uint64_t auto_rebuild_interval(std::size_t disks);


// Where a resumed run starts: a rebuild point as the log stored it. The disks' positions, velocities and
// times, their last partners and TC times, and the engine's counters; radius, mass and species come from
// the scene's initial state.
template <class T>
struct ResumePoint {
  T time{};
  std::vector<Disk<T>> disks;     // x, y, vx, vy, t and last_partner are used
  std::vector<T> last_collision;  // TC model only
  std::vector<T> omega;           // rough engines: each disk's angular velocity (empty: as the initial state)
  EventCounts counts;
  std::uint64_t next_sample_index = 0;
  std::uint64_t next_action_index = 0;
  std::uint64_t same_time_events = 0;
  double initial_energy = 0;
};

template <class T>
class EngineApi {
 public:
  virtual ~EngineApi() = default;
  // Sinks are called in the order added; the caller keeps them alive for the engine's lifetime.
  virtual void add_sink(Sink<T>* sink) = 0;
  // Processes events until a stop condition holds (returns it) or max_events more events and samples were
  // processed (returns Running). The first call reports the initial state to sinks (on_start).
  virtual RunStatus run(std::uint64_t max_events = std::numeric_limits<std::uint64_t>::max()) = 0;
  // The same, but pausing at time `until`: every event, sample and action at or before it is processed,
  // then the clock stands at `until` (returns Running) unless a stop condition held first. Pausing changes
  // nothing that happens later: a paused run produces the events an unpaused one does.
  virtual RunStatus run_until(T until, std::uint64_t max_events) = 0;
  virtual T time() const = 0;
  virtual const Particles<T>& particles() const = 0;
  virtual const EventCounts& counts() const = 0;
  virtual std::string effects() const = 0;        // e.g. "walls, inelastic (xi=0.5, xi_w=1), TC (tc=1e-4)"
  virtual std::string stall_message() const = 0;  // why the run stalled or came to rest, and what to do
  virtual std::size_t memory_bytes() const = 0;   // bytes held by the engine's own arrays
  virtual double initial_kinetic_energy() const = 0;
  // The potential energy of the pairs inside steps of a stepped potential (0 for hard disks).
  virtual double potential_energy() const = 0;
  // Debug and test aid, O(N): pairs overlapping by more than `tolerance` of their contact distance and
  // predictions in the past, described; empty when all is well.
  virtual std::string check_invariants(double tolerance) const = 0;
  // The largest overlap between two disks at the current time, as a fraction of their contact distance
  // (0 when no pair overlaps). O(N) with the grid. Round-off leaves ~1e-15 in double.
  virtual double largest_overlap() const = 0;
};

// The engines the library builds, for each scalar type (engine_factory.hpp: the table, and why these).
enum class EngineKind {
  PeriodicElastic,      // an elastic gas in a periodic box
  PeriodicDissipative,  // restitution below 1 and/or the TC model, periodic box
  WallsElastic,         // an elastic gas in a walled box
  WallsDissipative,     // restitution below 1 (pairs or walls) and/or the TC model, walled box
  WallsGravity,         // gravity, elastic or not (walls only); computes any walled run without segments
  WallsSegments,        // wall segments inside a walled box, elastic or not, without gravity
  PeriodicRough,        // rough or spinning disks (omega, I, beta), periodic box
  WallsRough,           // rough or spinning disks, walled box (no gravity, no segments)
  PeriodicSteps,        // a stepped potential (square wells, shoulders: Stepped), periodic box
  WallsSteps,           // a stepped potential, walled box, without gravity
  WallsGravitySteps,    // a stepped potential under gravity (walls)
  PeriodicThermostat,   // the Andersen thermostat, periodic box, elastic or not
  WallsThermostat,      // the Andersen thermostat, walled box (no gravity, no segments, no rotation)
  Sheared,              // a Lees-Edwards box (sliding images above and below), elastic or not
};
const char* to_string(EngineKind kind);  // "walls, dissipative", ...

// The engine a run needs: the one with the fewest effects compiled in that computes it.
EngineKind engine_kind_for(const EngineOptions& options);
// Whether engine `kind` computes the run `options` describes (the boundary matches, gravity only in
// WallsGravity, restitution below 1 or TC not in an elastic engine, segments only in WallsSegments, a
// stepped potential only in the *Steps engines).
bool engine_can_run(EngineKind kind, const EngineOptions& options);

// A new engine for `initial`; with `resume`, the engine continues from that rebuild point instead, and
// produces exactly the events the original run produced after it.
template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_engine(const InitialState& initial, const EngineOptions& options,
                                                  const ResumePoint<T>* resume = nullptr);
// The same with the engine named instead of chosen, e.g. WallsGravity for a walled run without gravity:
// what ede-bench effects compares a specialized engine with. An error if it cannot compute the run.
template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_engine_as(EngineKind kind, const InitialState& initial,
                                                     const EngineOptions& options,
                                                     const ResumePoint<T>* resume = nullptr);


}  // namespace ede
