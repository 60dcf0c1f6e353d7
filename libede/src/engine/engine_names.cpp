// Names of enums for messages and summaries, and the scene -> engine options mapping.
#include "engine/engine.hpp"
#include "core/event.hpp"

#include <algorithm>

namespace ede {

const char* to_string(EventKind k) {
  switch (k) {
    case EventKind::Pair: return "pair";
    case EventKind::Wall: return "wall";
    case EventKind::Cell: return "cell";
    case EventKind::Wrap: return "wrap";
    case EventKind::Action: return "action";
    case EventKind::Sample: return "sample";
  }
  return "?";
}

const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::Running: return "running";
    case RunStatus::ReachedTime: return "reached stop.time";
    case RunStatus::ReachedEvents: return "reached stop.events";
    case RunStatus::ReachedCollisions: return "reached stop.collisions_per_particle";
    case RunStatus::ReachedEnergy: return "reached stop.energy_fraction";
    case RunStatus::NoMoreEvents: return "no more events (nothing will collide again)";
    case RunStatus::Stalled: return "stalled (inelastic collapse)";
    case RunStatus::CameToRest: return "came to rest (speeds below what the scalar type resolves)";
  }
  return "?";
}

bool is_finished(RunStatus s) { return s != RunStatus::Running; }

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
  o.actions = scene.actions;
  return o;
}

}  // namespace ede
