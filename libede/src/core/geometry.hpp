// Pure geometry of straight-line motion: when two disks touch, when a disk reaches a wall or a line.
//
// No state, no side effects: every function maps numbers to a time, so each is tested on its own. Times
// returned are durations from the moment the inputs describe; +infinity means "never".
// The pair formula is the cancellation-free root of DESIGN.md section 5: with b = dx.dv < 0 (approaching),
// the earlier root of a t^2 + 2 b t + c = 0 is t = c / (-b + sqrt(b^2 - a c)), which stays accurate for
// grazing (d -> 0 is fine: no subtraction of nearly equal numbers) and near-contact (c -> 0) pairs, where
// the textbook (-b - sqrt(d)) / a adds a cancellation of its own. Rejected: the textbook form (kept only
// in study/textbook_contact.hpp, for the accuracy study).
// Round-off floor on b: positions carry an absolute rounding error of about eps * L (L the box size), so
// b = dx.dv is only known to about eps * L * |dv|. A pair whose b lies inside that noise is neither
// approaching nor receding as far as the arithmetic can tell; we treat it as not approaching. Without
// this, a disk pressed against a wall (or a cluster at rest) by a sliding neighbour can "collide" again
// and again at one instant, each collision regenerating the noise the next one feeds on. Treating it as
// sliding lets the pair overlap by at most ~eps * L over a free flight: below anything measurable.
#pragma once

#include <algorithm>

#include "core/scalar_math.hpp"

namespace ede {

template <class T>
constexpr T kNever = scalar_limits<T>::infinity();

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
  return c / (-b + ede::sqrt(d));
}

// pair_contact_time computed without branches: every quantity is evaluated and the answer selected, so a
// neighbour scan pays no misprediction on the coin flips "approaching?" and "hitting?" (about half of the
// neighbours each; the scan's branches were ~25 % of an event's cycles at 10^4 disks). Returns exactly
// pair_contact_time's value for every input (tests/core/test_geometry.cpp compares the bits): the root is
// the same expression of the same operands, and the selects apply the tests in the same order. The sqrt of
// a missing pair is taken as 0 (std::sqrt of a negative would call the library to set errno), and a
// division by -b + sqrt(...) when b >= 0 gives NaN or inf that is never selected.
template <class T>
inline T pair_contact_time_select(T dx, T dy, T dvx, T dvy, T s, T b_noise2 = T(0)) {
  const T b = dx * dvx + dy * dvy;
  const T a = dvx * dvx + dvy * dvy;
  const T c = (dx * dx + dy * dy) - s * s;
  const T d = b * b - a * c;
  const bool hits = d > 0;
  const T root = c / (-b + ede::sqrt(select_value(hits, d, T(0))));  // not the root of a negative: errno
  T t = select_value(hits, root, kNever<T>);
  t = select_value(c <= 0, T(0), t);
  const bool approaching = (b < 0) & !(b * b <= b_noise2 * a);
  return select_value(approaching, t, kNever<T>);
}

// The round-off floor for b in a box of largest side `length`: positions are exact to ~eps * length.
template <class T>
inline T b_noise2_for(T length) {
  const T floor = T(8) * scalar_limits<T>::epsilon() * length;
  return floor * floor;
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

// Time for a coordinate under constant acceleration to reach a line (walls and cell sides under gravity).
// In terms of s, the signed distance to the line at the record's time, positive on the side the coordinate
// belongs to, with rate u = ds/dt and acceleration a = d^2s/dt^2: the first t >= t_min (t_min = now minus
// the record's time) at which s + u t + a t^2 / 2 falls through 0, i.e. crosses the line outwards. The
// record can predate cell crossings, so the coordinate may have been on the far side then, and the roots
// of the quadratic include crossings already past: only those at or after t_min count. The outward
// crossing is the larger root when a < 0 (s rises, then falls) and the smaller when a > 0. If there is none
// ahead, the answer is t_min ("now") only for a coordinate outside at t_min and still moving outwards
// (round-off put it a hair past the line), else never. Roots from the stable pair
// q = -(u + sign(u) sqrt(d)) / 2: q / (a/2) and s / q, so neither loses digits when s is tiny or the
// discriminant is close to u^2.
// A disk resting exactly on a floor (s = 0, u = 0, a < 0) hits it now, again and again: resting contact is
// not an event-driven notion, which is why gravity with inelastic walls needs restitution above 0 and the
// TC model (else the stall detector ends the run with a message).
template <class T>
inline T time_to_reach_accelerated(T s, T u, T a, T t_min = T(0)) {
  const T s_now = s + u * t_min + a * t_min * t_min / T(2), u_now = u + a * t_min;
  const bool leaving_outside = s_now < T(0) && (u_now < T(0) || (u_now == T(0) && a < T(0)));
  if (a == T(0)) {
    if (!(u < T(0))) return kNever<T>;  // moving inwards or along the line
    const T t = s / -u;
    return t >= t_min ? t : (leaving_outside ? t_min : kNever<T>);
  }
  const T d = u * u - T(2) * a * s;
  // d < 0: the line is never reached again. d == 0 with a > 0: it is only touched (s >= 0 throughout), not
  // crossed; counting the touch as a crossing sent a disk at rest exactly on a cell side back and forth
  // between the two cells at one instant, forever (found with the projectile of a crater under gravity).
  if (d < T(0) || (d == T(0) && a > T(0))) return leaving_outside ? t_min : kNever<T>;
  const T root = ede::sqrt(d);
  const T q = u < T(0) ? (-u + root) / T(2) : -(u + root) / T(2);  // q = -(u + sign(u) sqrt(d)) / 2
  const T r1 = q / (a / T(2));
  const T r2 = q != T(0) ? s / q : r1;  // q == 0 only when u == 0 and d == 0: the double root 0
  const T outward = a < T(0) ? std::max(r1, r2) : std::min(r1, r2);
  if (outward >= t_min) return outward;
  return leaving_outside ? t_min : kNever<T>;
}

}  // namespace ede
