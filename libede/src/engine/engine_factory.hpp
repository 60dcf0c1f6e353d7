// make_engine<T> and the engine table: which Engine instantiations the library builds, and why these.
//
//   EngineKind           Boundary  Dissipation  Field           runs
//   PeriodicElastic      periodic  Elastic      NoField         elastic scenes in a periodic box
//   PeriodicDissipative  periodic  Dissipative  NoField         restitution < 1 and/or TC, periodic box
//   WallsElastic         walls     Elastic      NoField         elastic scenes in a walled box
//   WallsDissipative     walls     Dissipative  NoField         restitution < 1 (pairs or walls) and/or TC, walls
//   WallsGravity         walls     Dissipative  UniformGravity  every scene with gravity, elastic ones too
//   WallsSegments        walls     Dissipative  NoField         every scene with wall segments (WithSegments)
//   PeriodicRough        periodic  Dissipative  NoField         rough or spinning disks (Rough), periodic box
//   WallsRough           walls     Dissipative  NoField         rough or spinning disks (Rough), walled box
//   PeriodicSteps        periodic  Dissipative  NoField         a stepped potential (Stepped), periodic box
//   WallsSteps           walls     Dissipative  NoField         a stepped potential (Stepped), walled box
//   WallsGravitySteps    walls     Dissipative  UniformGravity  a stepped potential under gravity
//   PeriodicThermostat   periodic  Dissipative  NoField         the Andersen thermostat (Andersen), periodic box
//   WallsThermostat      walls     Dissipative  NoField         the Andersen thermostat (Andersen), walled box
//   Sheared              lees-edw. Dissipative  NoField         a Lees-Edwards box (sliding images), elastic or not,
//                                                               with or without the thermostat (Andersen)
//
// The three stepped ones carry the step table and the step room (square wells and shoulders); no other
// scene's engine has them compiled in. A scene with both steps and a thermostat is refused by the scene
// loader (no engine combines the two axes).
// The sheared one has the sliding edges' room and realignment clock (room_shear.hpp); no other scene's
// engine has them compiled in. It carries the thermostat's clock too (drawing about the flow), never due
// without a [thermostat]: one comparison per event (measured 1270 -> 1273 instructions per event, a
// sheared elastic gas of 400 disks), where a fifteenth engine would add its build time.
// Fourteen per scalar type (eight before the stepped potential, the thermostat and Lees-Edwards):
// make_engine_as<T> below names them all, and engine_float.cpp, engine_double.cpp,
// engine_long_double.cpp (and engine_float128.cpp where EDE_HAVE_FLOAT128) instantiate it once each, so
// 56 engines (42 without __float128). The two thermostat ones have a clock the loop compares with and a
// room of their own; every other scene's loop has neither. The two rough ones carry omega and the tangential impulse; every
// other scene's engine has neither compiled in. Why not fewer: the elastic gas is what the speed targets are about,
// and it must not pay for restitution, energy accounting or TC (Elastic), for walls in a periodic box
// (Boundary) or for parabolas (Field). Why not more: within Dissipative, restitution, per-pair restitution
// and TC cost nothing measurable (ede-bench effects: 0.98-1.00 x the elastic gas per event), so they are
// runtime values, not types (tc = 0: the TC model is off); under gravity, xi = 1 computes exactly what the
// elastic rule does (1 + xi = 2, a wall multiplies by 1), so an elastic scene under gravity runs the
// Dissipative gravity engine bit for bit as an Elastic one would. Periodic with gravity does not exist
// (check_engine_input refuses it).
// Outside the library: study/textbook_engine.cpp builds the two elastic engines with the textbook
// contact root for float, double and long double (the accuracy study, 6 more), and ede-bench-elastic
// builds WallsElastic<double> alone (the effects study's "only the elastic path compiled in"). Such code
// includes engine_core.hpp and engine_checks.hpp, not this header, and calls the library's make_engine
// and make_engine_as through their declarations (engine.hpp): instantiating them from here would compile
// the whole table again outside the library.
#pragma once

#include <memory>
#include <string>

#include "engine/engine_checks.hpp"
#include "engine/engine_core.hpp"

namespace ede {

template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_engine_as(EngineKind kind, const InitialState& init,
                                                     const EngineOptions& o, const ResumePoint<T>* resume) {
  const Result<GridShape> checked = check_engine_start(init, o, resume);
  if (!checked) return checked.error();
  if (!engine_can_run(kind, o))
    return Error{std::string("the ") + to_string(kind) + " engine cannot run this scene (it needs the " +
                 to_string(engine_kind_for(o)) + " one)"};
  const GridShape shape = checked.value();
  std::unique_ptr<EngineApi<T>> e;
  switch (kind) {
    case EngineKind::PeriodicElastic:
      e = std::make_unique<Engine<T, PeriodicBoundary, Elastic>>(init, o, shape, resume);
      break;
    case EngineKind::PeriodicDissipative:
      e = std::make_unique<Engine<T, PeriodicBoundary, Dissipative>>(init, o, shape, resume);
      break;
    case EngineKind::WallsElastic:
      e = std::make_unique<Engine<T, WallsBoundary, Elastic>>(init, o, shape, resume);
      break;
    case EngineKind::WallsDissipative:
      e = std::make_unique<Engine<T, WallsBoundary, Dissipative>>(init, o, shape, resume);
      break;
    case EngineKind::WallsGravity:
      e = std::make_unique<Engine<T, WallsBoundary, Dissipative, UniformGravity>>(init, o, shape, resume);
      break;
    case EngineKind::WallsSegments:
      e = std::make_unique<Engine<T, WallsBoundary, Dissipative, NoField, StableContact, WithSegments>>(init, o, shape,
                                                                                                     resume);
      break;
    case EngineKind::PeriodicRough:
      e = std::make_unique<Engine<T, PeriodicBoundary, Dissipative, NoField, StableContact, NoSegments, Rough>>(
          init, o, shape, resume);
      break;
    case EngineKind::WallsRough:
      e = std::make_unique<Engine<T, WallsBoundary, Dissipative, NoField, StableContact, NoSegments, Rough>>(
          init, o, shape, resume);
      break;
    case EngineKind::PeriodicSteps:
      e = std::make_unique<
          Engine<T, PeriodicBoundary, Dissipative, NoField, StableContact, NoSegments, Smooth, Stepped>>(
          init, o, shape, resume);
      break;
    case EngineKind::WallsSteps:
      e = std::make_unique<Engine<T, WallsBoundary, Dissipative, NoField, StableContact, NoSegments, Smooth, Stepped>>(
          init, o, shape, resume);
      break;
    case EngineKind::WallsGravitySteps:
      e = std::make_unique<
          Engine<T, WallsBoundary, Dissipative, UniformGravity, StableContact, NoSegments, Smooth, Stepped>>(
          init, o, shape, resume);
      break;
    case EngineKind::PeriodicThermostat:
      e = std::make_unique<
          Engine<T, PeriodicBoundary, Dissipative, NoField, StableContact, NoSegments, Smooth, HardCore, Andersen>>(
          init, o, shape, resume);
      break;
    case EngineKind::Sheared:
      e = std::make_unique<
          Engine<T, LeesEdwardsBoundary, Dissipative, NoField, StableContact, NoSegments, Smooth, HardCore, Andersen>>(
          init, o, shape, resume);
      break;
    case EngineKind::WallsThermostat:
      e = std::make_unique<
          Engine<T, WallsBoundary, Dissipative, NoField, StableContact, NoSegments, Smooth, HardCore, Andersen>>(
          init, o, shape, resume);
      break;
  }
  return e;
}

template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_engine(const InitialState& init, const EngineOptions& options,
                                                  const ResumePoint<T>* resume) {
  return make_engine_as<T>(engine_kind_for(options), init, options, resume);
}

}  // namespace ede
