// Effects: the small policy types an Engine is instantiated with, one axis per kind of physics a scene
// can switch on: Boundary (walls, periodic, Lees-Edwards), Dissipation, Field, Contact (the pair root), Walls (segments), Spin, Potential
// (square wells and shoulders) and Heat (the thermostat), eight axes; the engine table (engine_factory.hpp)
// builds fourteen combinations per scalar type.
//
// The engine branches on them with `if constexpr`, so code for an effect a scene does not use is not
// compiled into that scene's engine: an elastic gas has no restitution, no TC bookkeeping, no energy
// accounting, and in a periodic box no wall code, in its event loop. Each policy also names the state it
// needs (State<T>), which the engine holds (EngineState, engine_state.hpp): an empty struct, taking no
// room, for the side that needs none, so an elastic gas's engine carries no restitution table either. Within Dissipative the values decide
// at run time (xi, xi_w, per species pair, tc): `ede-bench effects` measured restitution, per-pair
// restitution and the TC model at 0.98-1.00 x the elastic gas's cost per event, so splitting them into
// more instantiations bought nothing but build time.
// Rejected: runtime flags for everything (then every effect costs every scene something, and DESIGN.md
// section 6 asks for "pays nothing"), and virtual policies (a call per event).
#pragma once

#include "core/geometry.hpp"
#include "engine/lees_edwards.hpp"
#include "engine/restitution.hpp"
#include "engine/roughness.hpp"
#include "engine/segment_walls.hpp"
#include "engine/step_table.hpp"
#include "engine/thermostat.hpp"

namespace ede {

// The box's edges: walls, periodic, or periodic with the images above and below sliding (Lees-Edwards,
// lees_edwards.hpp), whose state is the slide's speed and the clock that realigns the boundary rows' scans.
struct WallsBoundary {
  static constexpr bool kPeriodic = false;
  static constexpr bool kSheared = false;
  static constexpr const char* kName = "walls";
  template <class T>
  using State = NoShear;
};
struct PeriodicBoundary {
  static constexpr bool kPeriodic = true;
  static constexpr bool kSheared = false;
  static constexpr const char* kName = "periodic";
  template <class T>
  using State = NoShear;
};
// Lees-Edwards: periodic in x; crossing the top or bottom edge is a shear event (room_shear.hpp), and pairs
// across it meet the sliding image. Sheared engines are Dissipative (a sheared granular gas is the steady
// state the heating needs; xi = 1 computes exactly what Elastic does) and carry the thermostat's clock
// (Andersen, drawing about the flow: room_thermostat.hpp), without gravity, segments, rotation or steps
// (refused by the scene).
struct LeesEdwardsBoundary {
  static constexpr bool kPeriodic = true;
  static constexpr bool kSheared = true;
  static constexpr const char* kName = "lees-edwards";
  template <class T>
  using State = ShearClock<T>;
};

// Every collision elastic: the impulse 2 (dv.n) / (m_i + m_j), walls mirror the velocity.
struct Elastic {
  static constexpr bool kDissipative = false;
  template <class T>
  using State = NoRestitution;
};
// Restitution below 1 for pairs (one value, or per pair of species) or walls, and the TC model when tc > 0;
// the kinetic energy is tracked (stop.energy_fraction) and a run cooled below what T resolves ends.
// With xi = 1 it computes exactly what Elastic does (1 + xi = 2; a wall multiplies by 1, exact), which is
// why an elastic scene under gravity runs the gravity engine, which is Dissipative.
struct Dissipative {
  static constexpr bool kDissipative = true;
  template <class T>
  using State = Restitution<T>;
};

// Fields acting on the disks between events. Without one, disks move in straight lines (drift); with
// uniform gravity (walls only: in a periodic box everything would fall forever), in parabolas, and wall
// and cell-crossing times solve quadratics. Pair times stay those of straight lines: two disks under the
// same g see each other move in a straight line.
struct NoGravity {};
template <class T>
struct Gravity {
  T gx = 0, gy = 0;
};
struct NoField {
  static constexpr bool kGravity = false;
  template <class T>
  using State = NoGravity;
};
struct UniformGravity {
  static constexpr bool kGravity = true;
  template <class T>
  using State = Gravity<T>;
};

// Wall segments inside the box (core/segment.hpp): each disk predicts against the segments listed in its
// cell (segment_cells.hpp) and resolves segment events. Without them (every scene before segments
// existed) none of that is compiled in. One instantiation carries them: walls, Dissipative (an elastic
// segment computes exactly what an elastic rule would: 1 + xi = 2), no gravity (a parabola against a
// slanted segment is a quartic the engine does not solve yet: scenes with both are refused).
struct NoSegments {
  static constexpr bool kSegments = false;
  template <class T>
  using State = NoSegmentWalls;
};
struct WithSegments {
  static constexpr bool kSegments = true;
  template <class T>
  using State = SegmentWalls<T>;
};

// Rough disks (collide.hpp, docs/physics.md): each disk carries an angular velocity omega and a moment of
// inertia, and a collision reverses and scales the contact points' tangential relative velocity by beta
// besides the normal one by xi. Smooth (every scene before rotation existed) compiles none of it: no omega
// array, no tangential impulse. Rough engines are Dissipative (a beta between -1 and 1 loses energy, and
// the energy kept for stop.energy_fraction includes the rotation).
struct Smooth {
  static constexpr bool kRough = false;
  template <class T>
  using State = NoRoughness;
};
struct Rough {
  static constexpr bool kRough = true;
  template <class T>
  using State = Roughness<T>;
};

// The pair potential: hard disks only (every scene before steps existed: none of the rest is compiled in),
// or a stepped potential outside the hard core ([[physics.steps]]: square wells and shoulders), whose
// step events are the step room's (room_step.hpp) and whose pair depths and potential energy the engine
// keeps (step_table.hpp). Stepped engines are Dissipative (a restitution below 1 for the hard core is a
// known model, and 1 + xi = 2 computes the elastic rule exactly), smooth, and without segments.
struct HardCore {
  static constexpr bool kSteps = false;
  template <class T>
  using State = NoSteps;
};
struct Stepped {
  static constexpr bool kSteps = true;
  template <class T>
  using State = StepTable<T>;
};

// The Andersen thermostat (thermostat.hpp, room_thermostat.hpp): velocities redrawn from Maxwell-Boltzmann
// at Poisson times, a kind of event of its own. Without it (every scene before the thermostat existed) the
// loop has no thermostat clock to compare with and nothing of it is compiled in. Thermostat engines are
// Dissipative (a driven granular gas is the point; xi = 1 computes exactly what Elastic does), without
// gravity, segments, rotation or steps (refused by the scene).
struct NoThermostat {
  static constexpr bool kThermostat = false;
  template <class T>
  using State = NoThermostatClock;
};
struct Andersen {
  static constexpr bool kThermostat = true;
  template <class T>
  using State = AndersenClock<T>;
};

// The pair contact-time root: a function, not a flag. The library's engines use the stable form of
// geometry.hpp; study/ adds a textbook one (for the accuracy study) without touching the engine.
struct StableContact {
  static constexpr const char* kLabel = "";  // appended to EngineApi::effects()
  template <class T>
  static T time(T dx, T dy, T dvx, T dvy, T s, T b_noise2) {
    return pair_contact_time(dx, dy, dvx, dvy, s, b_noise2);
  }
};
// The same root computed without branches (geometry.hpp, pair_contact_time_select): the same bits, used by
// the neighbour scan of small systems (room_pair.hpp, consider_pair). Not an engine's policy.
struct StableContactSelect {
  template <class T>
  static T time(T dx, T dy, T dvx, T dvy, T s, T b_noise2) {
    return pair_contact_time_select(dx, dy, dvx, dvy, s, b_noise2);
  }
};

}  // namespace ede
