// The names of Scene enums as a scene file spells them, so a printed name reads back as the same value.
//
// Kept apart from the loader so that tools printing a Scene need not pull in toml++. Rejected: a generic
// enum-reflection helper, which is more code than these two switches.
#include "ede/scene.hpp"

namespace ede {

const char* to_string(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::Walls: return "walls";
    case BoundaryKind::Periodic: return "periodic";
  }
  return "unknown";
}

const char* to_string(ScalarKind kind) {
  switch (kind) {
    case ScalarKind::Float: return "float";
    case ScalarKind::Double: return "double";
    case ScalarKind::LongDouble: return "long double";
    case ScalarKind::Float128: return "float128";
  }
  return "unknown";
}

}  // namespace ede
