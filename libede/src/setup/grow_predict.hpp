// Contact times of growing disks: the pure geometry of Lubachevsky-Stillinger growth (grow.hpp).
//
// A pair at separation dr, relative velocity dv, contact distance s growing at rate g touches when
// |dr + dv tau| = s + g tau: a tau^2 + 2 b tau + c = 0 with a = dv.dv - g^2, b = dr.dv - s g, c = dr.dr - s^2.
// The wanted root is the earliest one >= 0, always tau = c / (-b + sqrt(b^2 - a c)) when that denominator is
// positive: for a > 0 it is the smaller root of an approaching pair (b < 0); for a < 0 (growth outruns the
// relative speed) the roots have opposite signs and it is the positive one, whatever the sign of b; for
// a = 0 it is the linear root. This form has no cancellation for grazing pairs (the textbook
// (-b - sqrt d) / a loses every digit when a c << b^2, and divides by zero at a = 0). c <= 0 (an overlap of
// round-off size) with a closing gap (b < 0): contact now.
#pragma once

#include <cmath>
#include <limits>

namespace ede::setup_detail {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

inline double grow_pair_time(double dx, double dy, double dvx, double dvy, double s, double g) {
  const double b = dx * dvx + dy * dvy - s * g;
  const double c = dx * dx + dy * dy - s * s;
  if (c <= 0) return b < 0 ? 0.0 : kNever;
  const double a = dvx * dvx + dvy * dvy - g * g;
  const double d = b * b - a * c;
  if (d < 0) return kNever;
  const double den = -b + std::sqrt(d);
  if (!(den > 0)) return kNever;
  return c / den;
}

// A wall: the gap (distance to the wall minus the radius) closing at `closing` = radius growth rate plus
// the speed towards the wall.
inline double grow_wall_time(double gap, double closing) {
  if (!(closing > 0)) return kNever;
  return gap <= 0 ? 0.0 : gap / closing;
}

}  // namespace ede::setup_detail
