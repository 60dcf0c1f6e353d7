// Calling a templated piece of tool code with the scalar type a scene or a log asks for.
//
// f is a generic lambda `[&]<class T>() { ... }`; the switch happens once per run, so the event loop
// inside runs the instantiation for T with no further dispatch. with_scalar knows the three types a log
// can hold; with_engine_scalar adds __float128 where the library has that engine (EDE_HAVE_FLOAT128), for
// the tools that run an engine without a log. A tool taking a scene calls the first only after refusing
// ScalarKind::Float128 with a message of its own; reaching it there is a bug, reported and aborted.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <type_traits>
#include <utility>

#include "ede/scene.hpp"

namespace ede {

// The scalar types of logs, replay and everything downstream of them.
template <class T>
constexpr bool kLogScalar = std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, long double>;

[[noreturn]] inline void unsupported_scalar(ScalarKind kind) {
  std::fprintf(stderr, "ede: internal error: no code for scalar type %s here\n", to_string(kind));
  std::abort();
}

template <class F>
decltype(auto) with_scalar(ScalarKind kind, F&& f) {
  switch (kind) {
    case ScalarKind::Float: return f.template operator()<float>();
    case ScalarKind::LongDouble: return f.template operator()<long double>();
    case ScalarKind::Double: break;
    case ScalarKind::Float128: unsupported_scalar(kind);
  }
  return f.template operator()<double>();
}

template <class F>
decltype(auto) with_engine_scalar(ScalarKind kind, F&& f) {
#if EDE_HAVE_FLOAT128
  if (kind == ScalarKind::Float128) return f.template operator()<__float128>();
#endif
  return with_scalar(kind, std::forward<F>(f));
}

}  // namespace ede
