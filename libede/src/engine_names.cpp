// Names of enums for messages and summaries, and the scene -> engine options mapping.
#include "ede/engine.hpp"
#include "ede/event.hpp"

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
  }
  return "?";
}

bool is_finished(RunStatus s) { return s != RunStatus::Running; }

EngineOptions engine_options_from(const Scene& scene) {
  EngineOptions o;
  o.boundary = scene.boundary;
  o.physics = scene.physics;
  o.stop = scene.stop;
  o.sample_interval = scene.sample_interval;
  o.actions = scene.actions;
  return o;
}

}  // namespace ede
