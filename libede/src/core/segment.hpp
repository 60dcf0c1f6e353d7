// A straight wall segment and the time a moving disk first touches it: pure geometry, shared by the
// engine (predictions) and the log (replay's predicted event times), so both compute the same bits.
//
// A segment from A to B has a unit tangent u = (B - A) / |B - A| and a unit normal n = (-u_y, u_x), both
// computed once from the end points in the run's scalar type (make_segment). A disk of radius r touches
// it either on its body (its centre at distance r from the line, its projection between A and B) or at
// an end point (its centre at distance r from A or B): the end points are disks of radius zero and
// infinite mass at rest, and use the pair contact time of geometry.hpp. The body time is measured on the
// side of the line the centre is on, so a segment is a wall from both sides (a divider, an obstacle).
// Times are durations from the disk's record (x, v at its time t), never from a drifted position: like the
// box walls, the answer does not depend on when the prediction is made, which is what lets replay
// predict it exactly from the record alone.
// Rejected: a segment as a thin rectangle of four walls (corners become four end points and every hit
// near an end two events) and a capsule with rounded ends of the disks' radius (the end points are then
// no longer the zero-radius disks the pair rule can be compared with).
#pragma once

#include "core/geometry.hpp"
#include "core/scalar_math.hpp"

namespace ede {

template <class T>
struct Segment {
  T ax, ay, bx, by;  // end points A and B
  T ux, uy;          // unit tangent from A to B
  T nx, ny;          // unit normal (-uy, ux)
  T length;          // |B - A|
  T one_plus_xi;     // 1 + the segment's restitution
};

// The segment between (ax, ay) and (bx, by) with restitution xi, in one fixed order of operations.
template <class T>
inline Segment<T> make_segment(T ax, T ay, T bx, T by, T xi) {
  Segment<T> s{};
  s.ax = ax, s.ay = ay, s.bx = bx, s.by = by;
  const T dx = bx - ax, dy = by - ay;
  s.length = ede::sqrt(dx * dx + dy * dy);
  s.ux = dx / s.length;
  s.uy = dy / s.length;
  s.nx = -s.uy;
  s.ny = s.ux;
  s.one_plus_xi = T(1) + xi;
  return s;
}

// Signed distance of (x, y) from the segment's line (positive on the normal's side), and its position
// along the tangent from A (0 at A, length at B).
template <class T>
inline T segment_height(const Segment<T>& s, T x, T y) {
  return (x - s.ax) * s.nx + (y - s.ay) * s.ny;
}
template <class T>
inline T segment_along(const Segment<T>& s, T x, T y) {
  return (x - s.ax) * s.ux + (y - s.ay) * s.uy;
}

// Time until a disk at (x, y) moving at (vx, vy) with radius r first touches the segment (body or an end
// point), 0 if it overlaps while approaching (round-off), kNever if it never does. b_noise2 is the pair
// rule's round-off floor (geometry.hpp): an approach slower than it is sliding, for the body as for the
// end points, so a disk that has just bounced (xi = 0 leaves its normal speed at round-off) does not hit
// the same segment again at once.
template <class T>
inline T segment_contact_time(const Segment<T>& s, T x, T y, T vx, T vy, T r, T b_noise2) {
  T best = kNever<T>;
  const T h = segment_height(s, x, y);
  const T vn = vx * s.nx + vy * s.ny;
  const T dist = ede::abs(h);
  const T approach = h < T(0) ? vn : -vn;  // speed towards the line, > 0 when approaching
  const T b = dist * -approach;             // as the pair rule's b = dx.dv for a point at the foot
  if (b < T(0) && b * b > b_noise2 * (vx * vx + vy * vy)) {
    const T dt = dist > r ? (dist - r) / approach : T(0);
    const T along = segment_along(s, x + vx * dt, y + vy * dt);
    if (along >= T(0) && along <= s.length) best = dt;
  }
  const T ta = pair_contact_time(s.ax - x, s.ay - y, -vx, -vy, r, b_noise2);
  const T tb = pair_contact_time(s.bx - x, s.by - y, -vx, -vy, r, b_noise2);
  if (ta < best) best = ta;
  if (tb < best) best = tb;
  return best;
}

// Distance from (x, y) to the nearest point of the segment (setup's overlap checks; double only).
template <class T>
inline T segment_distance(const Segment<T>& s, T x, T y) {
  const T along = segment_along(s, x, y);
  if (along <= T(0)) return ede::sqrt((x - s.ax) * (x - s.ax) + (y - s.ay) * (y - s.ay));
  if (along >= s.length) return ede::sqrt((x - s.bx) * (x - s.bx) + (y - s.by) * (y - s.by));
  return ede::abs(segment_height(s, x, y));
}

}  // namespace ede
