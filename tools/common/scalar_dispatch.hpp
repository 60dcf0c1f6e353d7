// Calling a templated piece of tool code with the scalar type a scene asks for.
//
// f is a generic lambda `[&]<class T>() { ... }`; the switch happens once per run, so the event loop
// inside runs the instantiation for T with no further dispatch.
#pragma once

#include "ede/scene.hpp"

namespace ede::tools {

template <class F>
decltype(auto) with_scalar(ScalarKind kind, F&& f) {
  switch (kind) {
    case ScalarKind::Float: return f.template operator()<float>();
    case ScalarKind::LongDouble: return f.template operator()<long double>();
    case ScalarKind::Double: break;
  }
  return f.template operator()<double>();
}

}  // namespace ede::tools
