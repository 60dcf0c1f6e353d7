// The textbook pair contact root, (-b - sqrt(d)) / a: what the accuracy study (ede-bench accuracy) sets
// against the stable root c / (-b + sqrt(d)) the library's engines use (core/geometry.hpp, which says why).
// Same early outs and round-off floor as pair_contact_time, so that only the root differs. Not in the
// product library: an engine with this root is built only by study/textbook_engine.cpp.
#pragma once

#include "ede/internal/physics.hpp"

namespace ede {

template <class T>
inline T pair_contact_time_textbook(T dx, T dy, T dvx, T dvy, T s, T b_noise2 = T(0)) {
  const T b = dx * dvx + dy * dvy;
  if (!(b < 0)) return kNever<T>;
  const T a = dvx * dvx + dvy * dvy;
  if (b * b <= b_noise2 * a) return kNever<T>;
  const T c = (dx * dx + dy * dy) - s * s;
  if (c <= 0) return T(0);
  const T d = b * b - a * c;
  if (!(d > 0)) return kNever<T>;
  const T t = (-b - ede::sqrt(d)) / a;
  return t > 0 ? t : T(0);
}

// The Contact policy of an Engine (engine/effects.hpp) with the textbook root.
struct TextbookContact {
  static constexpr const char* kLabel = ", textbook contact root";
  template <class T>
  static T time(T dx, T dy, T dvx, T dvy, T s, T b_noise2) {
    return pair_contact_time_textbook(dx, dy, dvx, dvy, s, b_noise2);
  }
};

}  // namespace ede
