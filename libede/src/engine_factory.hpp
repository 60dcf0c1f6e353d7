// make_engine<T>: checks what the engine needs of an initial state and picks the Engine instantiation
// for the effects the options call for. Instantiated once per scalar type (engine_float.cpp, ...), so
// each translation unit compiles six engines, not eighteen.
#pragma once

#include <cmath>
#include <memory>
#include <sstream>

#include "engine_core.hpp"

namespace ede {

Status check_engine_input(const InitialState& init, const EngineOptions& options, GridShape& shape);

template <class T, class Boundary>
std::unique_ptr<EngineApi<T>> make_engine_for_boundary(const InitialState& init, const EngineOptions& o,
                                                       GridShape shape) {
  const PhysicsSpec& ph = o.physics;
  const bool inelastic = ph.restitution != 1.0 || ph.wall_restitution != 1.0;
  if (!inelastic) return std::make_unique<Engine<T, Boundary, Elastic>>(init, o, shape);
  if (ph.tc > 0) return std::make_unique<Engine<T, Boundary, InelasticTc>>(init, o, shape);
  return std::make_unique<Engine<T, Boundary, Inelastic>>(init, o, shape);
}

template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_engine(const InitialState& init, const EngineOptions& options) {
  GridShape shape;
  if (Status s = check_engine_input(init, options, shape); !s) return s.error();
  if (options.boundary == BoundaryKind::Periodic)
    return make_engine_for_boundary<T, PeriodicBoundary>(init, options, shape);
  return make_engine_for_boundary<T, WallsBoundary>(init, options, shape);
}

}  // namespace ede
