// Names of enums for messages and summaries, the scene -> engine options mapping, and which engine of the
// table (engine_factory.hpp) a run needs.
#include "engine/engine.hpp"
#include "core/event.hpp"

#include <algorithm>

namespace ede {

const char* to_string(EventKind k) {
  switch (k) {
#define EDE_EVENT_KIND_NAME(name, value, text) \
  case EventKind::name: return text;
    EDE_EVENT_KINDS(EDE_EVENT_KIND_NAME)
#undef EDE_EVENT_KIND_NAME
  }
  return "?";
}

bool is_event_kind(int value) {
#define EDE_EVENT_KIND_IS(name, v, text) \
  if (value == (v)) return true;
  EDE_EVENT_KINDS(EDE_EVENT_KIND_IS)
#undef EDE_EVENT_KIND_IS
  return false;
}

const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::Running: return "running";
    case RunStatus::ReachedTime: return "reached stop.time";
    case RunStatus::ReachedEvents: return "reached stop.events";
    case RunStatus::ReachedCollisions: return "reached stop.collisions_per_particle";
    case RunStatus::ReachedEnergy: return "reached stop.energy_fraction";
    case RunStatus::NoMoreEvents: return "no more events (nothing will collide again)";
    case RunStatus::Stalled: return "stalled (time stopped advancing)";
    case RunStatus::CameToRest: return "came to rest (speeds below what the scalar type resolves)";
    case RunStatus::NonFinite: return "stopped: a non-finite number (NaN or infinity) appeared";
    case RunStatus::Collapsed: return "inelastic collapse (a cluster slowed below resolvable speeds)";
    case RunStatus::EndedByProgram: return "ended by its program (Simulation::finish)";
    case RunStatus::Inexact: return "stopped: the run outgrew its scalar type (overlapping disks or an overflowing clock)";
  }
  return "?";
}

// A log's status words back to the status. Older words are kept: "stalled (inelastic collapse)" was a
// stall's name before an elastic run's stall (the clock's resolution) was told apart from collapse.
RunStatus status_from_text(const std::string& text) {
  for (int k = 0; k <= int(RunStatus::Inexact); ++k)
    if (text == to_string(RunStatus(k))) return RunStatus(k);
  if (text == "stalled (inelastic collapse)") return RunStatus::Stalled;
  return RunStatus::Running;
}

bool is_finished(RunStatus s) { return s != RunStatus::Running; }

const char* to_string(EngineKind k) {
  switch (k) {
    case EngineKind::PeriodicElastic: return "periodic, elastic";
    case EngineKind::PeriodicDissipative: return "periodic, dissipative";
    case EngineKind::WallsElastic: return "walls, elastic";
    case EngineKind::WallsDissipative: return "walls, dissipative";
    case EngineKind::WallsGravity: return "walls, gravity";
    case EngineKind::WallsSegments: return "walls, segments";
    case EngineKind::PeriodicRough: return "periodic, rough";
    case EngineKind::WallsRough: return "walls, rough";
    case EngineKind::PeriodicSteps: return "periodic, stepped";
    case EngineKind::WallsSteps: return "walls, stepped";
    case EngineKind::WallsGravitySteps: return "walls, gravity, stepped";
    case EngineKind::PeriodicThermostat: return "periodic, thermostat";
    case EngineKind::WallsThermostat: return "walls, thermostat";
    case EngineKind::Sheared: return "lees-edwards";
  }
  return "?";
}

EngineKind engine_kind_for(const EngineOptions& o) {
  const bool elastic = o.physics.elastic();
  // A Lees-Edwards box has one engine, thermostat or not; the scene loader refuses what it lacks (steps,
  // rotation).
  if (uses_shear(o)) return EngineKind::Sheared;
  // No engine has both a thermostat and steps: the scene loader refuses such a scene.
  if (uses_thermostat(o))
    return o.boundary == BoundaryKind::Periodic ? EngineKind::PeriodicThermostat : EngineKind::WallsThermostat;
  if (o.physics.has_steps()) {
    if (o.boundary == BoundaryKind::Periodic) return EngineKind::PeriodicSteps;
    return o.physics.has_gravity() ? EngineKind::WallsGravitySteps : EngineKind::WallsSteps;
  }
  if (uses_rotation(o)) return o.boundary == BoundaryKind::Periodic ? EngineKind::PeriodicRough : EngineKind::WallsRough;
  if (!o.physics.segments.empty()) return EngineKind::WallsSegments;
  if (o.boundary == BoundaryKind::Periodic) return elastic ? EngineKind::PeriodicElastic : EngineKind::PeriodicDissipative;
  if (o.physics.has_gravity()) return EngineKind::WallsGravity;
  return elastic ? EngineKind::WallsElastic : EngineKind::WallsDissipative;
}

bool engine_can_run(EngineKind k, const EngineOptions& o) {
  const bool periodic = o.boundary == BoundaryKind::Periodic, gravity = o.physics.has_gravity();
  const bool elastic = o.physics.elastic(), segments = !o.physics.segments.empty();
  const bool rough = uses_rotation(o), heat = uses_thermostat(o);
  // Hard disks only in the engines without steps, and a stepped potential only in the stepped ones (a
  // stepped engine without steps would run a hard-disk scene, but nothing compares them: not offered).
  const bool steps = o.physics.has_steps();
  const bool stepped_kind =
      k == EngineKind::PeriodicSteps || k == EngineKind::WallsSteps || k == EngineKind::WallsGravitySteps;
  if (steps != stepped_kind) return false;
  // A Lees-Edwards box only in the sheared engine, and that engine only for one: an unsheared periodic
  // scene there would log its vertical wraps as shear events (nothing compares the two: not offered).
  if (uses_shear(o) != (k == EngineKind::Sheared)) return false;
  switch (k) {
    case EngineKind::PeriodicElastic: return periodic && !gravity && elastic && !segments && !rough && !heat;
    case EngineKind::PeriodicDissipative: return periodic && !gravity && !segments && !rough && !heat;
    case EngineKind::WallsElastic: return !periodic && !gravity && elastic && !segments && !rough && !heat;
    case EngineKind::WallsDissipative: return !periodic && !gravity && !segments && !rough && !heat;
    case EngineKind::WallsGravity: return !periodic && !segments && !rough && !heat;
    case EngineKind::WallsSegments: return !periodic && !gravity && !rough && !heat;
    // A smooth scene in a rough engine computes what it computes elsewhere (beta = -1 skips the tangential
    // part), which is what ede-bench effects and the bit-for-bit test compare.
    case EngineKind::PeriodicRough: return periodic && !gravity && !segments && !heat;
    case EngineKind::WallsRough: return !periodic && !gravity && !segments && !heat;
    case EngineKind::PeriodicSteps: return periodic && !gravity && !segments && !rough && !heat;
    case EngineKind::WallsSteps: return !periodic && !gravity && !segments && !rough && !heat;
    case EngineKind::WallsGravitySteps: return !periodic && !segments && !rough && !heat;
    // A scene without a thermostat in a thermostat engine computes what the dissipative engine does (the
    // clock is never due), which is what ede-bench effects compares. Steps are kept out above.
    case EngineKind::PeriodicThermostat: return periodic && !gravity && !segments && !rough;
    case EngineKind::WallsThermostat: return !periodic && !gravity && !segments && !rough;
    case EngineKind::Sheared: return periodic && !gravity && !segments && !rough;
  }
  return false;
}

std::uint64_t auto_rebuild_interval(std::size_t disks) {
  return std::max<std::uint64_t>(std::uint64_t(1) << 20, 16 * std::uint64_t(disks));
}

EngineOptions engine_options_from(const Scene& scene, std::size_t disks) {
  EngineOptions o;
  o.rebuild_interval = scene.rebuild_interval ? scene.rebuild_interval : auto_rebuild_interval(disks);
  o.boundary = scene.boundary;
  o.physics = scene.physics;
  o.stop = scene.stop;
  o.sample_interval = scene.sample_interval;
  o.sample_collisions = scene.sample_collisions;
  o.actions = scene.actions;
  o.rotation = scene.rotates();
  o.seed = scene.seed;
  o.shear_rate = scene.shear_rate;
  for (const SpeciesSpec& sp : scene.species)
    if (sp.thermostat) o.species_thermostats.push_back({sp.name, sp.thermostat->temperature, sp.thermostat->rate});
  return o;
}

}  // namespace ede
