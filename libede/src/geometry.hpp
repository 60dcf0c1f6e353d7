// Pure geometry of straight-line motion: when two disks touch, when a disk reaches a wall or a line.
//
// No state, no side effects: every function maps numbers to a time, so each is tested on its own. Times
// returned are durations from the moment the inputs describe; +infinity means "never".
// The pair formula is the cancellation-free root of DESIGN.md section 5: with b = dx.dv < 0 (approaching),
// the earlier root of a t^2 + 2 b t + c = 0 is t = c / (-b + sqrt(b^2 - a c)), which stays accurate for
// grazing (d -> 0 is fine: no subtraction of nearly equal numbers) and near-contact (c -> 0) pairs, where
// the textbook (-b - sqrt(d)) / a adds a cancellation of its own. Rejected: the textbook form (kept only
// as pair_contact_time_textbook for the accuracy study).
// Round-off floor on b: positions carry an absolute rounding error of about eps * L (L the box size), so
// b = dx.dv is only known to about eps * L * |dv|. A pair whose b lies inside that noise is neither
// approaching nor receding as far as the arithmetic can tell; we treat it as not approaching. Without
// this, a disk pressed against a wall (or a cluster at rest) by a sliding neighbour can "collide" again
// and again at one instant, each collision regenerating the noise the next one feeds on. Treating it as
// sliding lets the pair overlap by at most ~eps * L over a free flight: below anything measurable.
#pragma once

#include <cmath>
#include <limits>

namespace ede {

template <class T>
constexpr T kNever = std::numeric_limits<T>::infinity();

// Disks at relative position (dx, dy) = x_j - x_i and relative velocity (dvx, dvy) = v_j - v_i, touching
// at distance s = r_i + r_j. Returns the time until contact, 0 if they overlap (by round-off) while
// approaching, or kNever if they are not approaching (b >= 0, or b^2 <= b_noise2 * |dv|^2: see above) or
// miss each other (d <= 0). b_noise2 = (k eps L)^2, from b_noise2_for(); 0 disables the floor.
template <class T>
inline T pair_contact_time(T dx, T dy, T dvx, T dvy, T s, T b_noise2 = T(0)) {
  const T b = dx * dvx + dy * dvy;
  if (!(b < 0)) return kNever<T>;  // also rejects NaN
  const T a = dvx * dvx + dvy * dvy;
  if (b * b <= b_noise2 * a) return kNever<T>;  // approach speed lost in round-off: sliding
  const T c = (dx * dx + dy * dy) - s * s;
  if (c <= 0) return T(0);  // in contact or overlapping and approaching: collide now
  const T d = b * b - a * c;
  if (!(d > 0)) return kNever<T>;  // the relative path misses (or grazes) the contact circle
  return c / (-b + std::sqrt(d));
}

// The round-off floor for b in a box of largest side `length`: positions are exact to ~eps * length.
template <class T>
inline T b_noise2_for(T length) {
  const T floor = T(8) * std::numeric_limits<T>::epsilon() * length;
  return floor * floor;
}

// The textbook root (-b - sqrt(d)) / a: only for the accuracy study, never used by the engine.
template <class T>
inline T pair_contact_time_textbook(T dx, T dy, T dvx, T dvy, T s) {
  const T b = dx * dvx + dy * dvy;
  if (!(b < 0)) return kNever<T>;
  const T c = (dx * dx + dy * dy) - s * s;
  if (c <= 0) return T(0);
  const T a = dvx * dvx + dvy * dvy;
  const T d = b * b - a * c;
  if (!(d > 0)) return kNever<T>;
  const T t = (-b - std::sqrt(d)) / a;
  return t > 0 ? t : T(0);
}

// Time for a coordinate x moving at speed v to reach the line at `target`. The caller picks the line
// ahead of the motion (the right wall for v > 0); if x is already at or past it (round-off) the answer is
// 0, "now". v == 0 never reaches anything.
template <class T>
inline T time_to_reach(T x, T v, T target) {
  if (v > 0) {
    const T gap = target - x;
    return gap > 0 ? gap / v : T(0);
  }
  if (v < 0) {
    const T gap = x - target;
    return gap > 0 ? gap / -v : T(0);
  }
  return kNever<T>;
}

}  // namespace ede
