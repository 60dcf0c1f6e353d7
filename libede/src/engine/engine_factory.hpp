// make_engine<T>: checks what the engine needs of an initial state and picks the Engine instantiation
// for the effects the options call for. Instantiated once per scalar type (engine_float.cpp, ...), so
// each translation unit compiles six engines, not eighteen.
#pragma once

#include <cmath>
#include <memory>
#include <sstream>

#include "engine/engine_core.hpp"

namespace ede {

Status check_engine_input(const InitialState& init, const EngineOptions& options, GridShape& shape);

template <class T, class Boundary, class Field = NoField>
std::unique_ptr<EngineApi<T>> make_engine_for_boundary(const InitialState& init, const EngineOptions& o,
                                                       GridShape shape, const ResumePoint<T>* resume) {
  const PhysicsSpec& ph = o.physics;
  if (ph.elastic()) return std::make_unique<Engine<T, Boundary, Elastic, Field>>(init, o, shape, resume);
  if (ph.tc > 0) return std::make_unique<Engine<T, Boundary, InelasticTc, Field>>(init, o, shape, resume);
  return std::make_unique<Engine<T, Boundary, Inelastic, Field>>(init, o, shape, resume);
}

template <class T>
Status check_resume_point(const InitialState& init, const EngineOptions& options, const ResumePoint<T>& r) {
  if (r.disks.size() != init.size())
    return Error{"the resume point holds " + std::to_string(r.disks.size()) + " disks, the scene " +
                 std::to_string(init.size())};
  const bool tc = options.physics.tc > 0 && !options.physics.elastic();
  if (tc && r.last_collision.size() != init.size())
    return Error{"the resume point lacks the TC model's collision times"};
  for (const Disk<T>& d : r.disks) {
    const bool finite = std::isfinite(double(d.x)) && std::isfinite(double(d.y)) && std::isfinite(double(d.vx)) &&
                        std::isfinite(double(d.vy)) && std::isfinite(double(d.t));
    if (!finite || d.last_partner < -1 || d.last_partner >= std::int32_t(init.size()))
      return Error{"the resume point holds a non-finite number or an invalid partner id"};
  }
  return Ok{};
}

// The study variants of EngineOptions (contact root, all effects): a few instantiations, not all.
template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_study_engine(const InitialState& init, const EngineOptions& o,
                                                        GridShape shape, const ResumePoint<T>* resume) {
  const bool periodic = o.boundary == BoundaryKind::Periodic;
  if (o.all_effects) {
    if (periodic || o.contact != ContactRoot::Stable)
      return Error{"the all-effects engine is built for walls and the stable contact root only"};
    return std::unique_ptr<EngineApi<T>>(
        std::make_unique<Engine<T, WallsBoundary, InelasticTc, UniformGravity>>(init, o, shape, resume));
  }
  if (!o.physics.elastic() || o.physics.has_gravity())
    return Error{"the textbook contact root is built for elastic scenes without gravity only"};
  if (periodic)
    return std::unique_ptr<EngineApi<T>>(
        std::make_unique<Engine<T, PeriodicBoundary, Elastic, NoField, TextbookContact>>(init, o, shape, resume));
  return std::unique_ptr<EngineApi<T>>(
      std::make_unique<Engine<T, WallsBoundary, Elastic, NoField, TextbookContact>>(init, o, shape, resume));
}

template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_engine(const InitialState& init, const EngineOptions& options,
                                                  const ResumePoint<T>* resume) {
  GridShape shape;
  if (Status s = check_engine_input(init, options, shape); !s) return s.error();
  if (resume)
    if (Status s = check_resume_point(init, options, *resume); !s) return s.error();
  if (options.all_effects || options.contact != ContactRoot::Stable)
    return make_study_engine<T>(init, options, shape, resume);
  if (options.boundary == BoundaryKind::Periodic)
    return make_engine_for_boundary<T, PeriodicBoundary>(init, options, shape, resume);
  if (options.physics.has_gravity())
    return make_engine_for_boundary<T, WallsBoundary, UniformGravity>(init, options, shape, resume);
  return make_engine_for_boundary<T, WallsBoundary>(init, options, shape, resume);
}

}  // namespace ede
