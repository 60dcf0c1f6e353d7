// What the engine requires of its input before an Engine is built: check_engine_input (engine_checks.cpp:
// sizes the queue can index, finite numbers, disks inside the box and apart, a periodic box at least three
// cells wide; it also sizes the grid) and, for a resumed run, check_resume_point. Shared by make_engine
// (engine_factory.hpp) and the code outside the library that builds an Engine itself.
#pragma once

#include <cmath>
#include <string>

#include "engine/engine_core.hpp"

namespace ede {

Status check_engine_input(const InitialState& init, const EngineOptions& options, GridShape& shape);

template <class T>
Status check_resume_point(const InitialState& init, const EngineOptions& options, const ResumePoint<T>& r) {
  if (r.disks.size() != init.size())
    return Error{"the resume point holds " + std::to_string(r.disks.size()) + " disks, the scene " +
                 std::to_string(init.size())};
  if (uses_tc_model(options.physics) && r.last_collision.size() != init.size())
    return Error{"the resume point lacks the TC model's collision times"};
  for (const Disk<T>& d : r.disks) {
    const bool finite = std::isfinite(double(d.x)) && std::isfinite(double(d.y)) && std::isfinite(double(d.vx)) &&
                        std::isfinite(double(d.vy)) && std::isfinite(double(d.t));
    if (!finite || d.last_partner < -1 || d.last_partner >= std::int32_t(init.size()))
      return Error{"the resume point holds a non-finite number or an invalid partner id"};
  }
  return Ok{};
}

// Both checks; the grid shape for the engine.
template <class T>
Result<GridShape> check_engine_start(const InitialState& init, const EngineOptions& options,
                                     const ResumePoint<T>* resume) {
  GridShape shape;
  if (Status s = check_engine_input(init, options, shape); !s) return s.error();
  if (resume)
    if (Status s = check_resume_point(init, options, *resume); !s) return s.error();
  return shape;
}

}  // namespace ede
