// The engine's pair contact time: geometry.hpp's pair_contact_time computed without its early returns.
//
// A prediction tries every disk of the 3 x 3 cells, and about half of them are receding (b >= 0): in
// pair_contact_time that test is a branch the predictor cannot learn, taken at every neighbour. Here every
// quantity is computed (the square root of a clamped discriminant, so no NaN and no errno call), and the
// same four decisions, in the same order, select the result: the bits are pair_contact_time's for every
// input (tests/engine/test_pair_root.cpp checks that on random, grazing, touching and degenerate pairs).
// Rejected: changing geometry.hpp itself (replay and the studies use that form and gain nothing from it).
#pragma once

#include "core/geometry.hpp"
#include "core/scalar_math.hpp"

namespace ede {

template <class T>
[[gnu::always_inline]] inline T pair_contact_time_unbranched(T dx, T dy, T dvx, T dvy, T s, T b_noise2) {
  const T b = dx * dvx + dy * dvy;
  const T a = dvx * dvx + dvy * dvy;
  const T c = (dx * dx + dy * dy) - s * s;
  const T d = b * b - a * c;
  const T root = ede::sqrt(d > T(0) ? d : T(0));
  const T t = c / (-b + root);
  // pair_contact_time's returns, applied last-first so that the first one that holds there wins here.
  T r = d > T(0) ? t : kNever<T>;
  r = c <= T(0) ? T(0) : r;
  r = b * b <= b_noise2 * a ? kNever<T> : r;
  return b < T(0) ? r : kNever<T>;
}

}  // namespace ede
