// The geometry of format version 2's predicted times (schema/FORMAT.md, "Predicted times" and "Wall
// segments"), frozen with that version: the pair contact root with its round-off floor, the time to reach
// a line with and without a constant acceleration, and the wall segments built from the header's scalars.
//
// Written from FORMAT.md, operation by operation; the engine has its own (core/geometry.hpp,
// core/segment.hpp), free to change for speed, and tests/log/test_format_rules.cpp shows where the two agree
// bit for bit. Where they do, a version 2 residual is 0; where a later engine differs, its logs grow (the
// residuals carry the difference) but stay exact, and a predictor that follows the engine is a new format
// version. Includes only the standard library (see state_update.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace ede::rules::v2 {

template <class T>
inline constexpr T kNever = std::numeric_limits<T>::infinity();

// beta = (8 eps max(Lx, Ly))^2: 8 eps max first, then squared.
template <class T>
inline T noise_floor2(T lx, T ly) {
  const T floor = T(8) * std::numeric_limits<T>::epsilon() * std::max(lx, ly);
  return floor * floor;
}

// The pair rule's tau for relative position (dx, dy), relative velocity (dvx, dvy) and contact distance s.
template <class T>
inline T contact_time(T dx, T dy, T dvx, T dvy, T s, T beta) {
  const T b = dx * dvx + dy * dvy;
  if (!(b < 0)) return kNever<T>;
  const T a = dvx * dvx + dvy * dvy;
  if (b * b <= beta * a) return kNever<T>;
  const T c = (dx * dx + dy * dy) - s * s;
  if (c <= 0) return T(0);
  const T d = b * b - a * c;
  if (!(d > 0)) return kNever<T>;
  return c / (-b + std::sqrt(d));
}

// reach(x, v, target).
template <class T>
inline T reach(T x, T v, T target) {
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

// The first t >= 0 at which s + u t + a t^2 / 2 falls through 0 (FORMAT.md: time_to_reach_accelerated
// with t_min = 0; the rest of its definition is this function).
template <class T>
inline T reach_accelerated(T s, T u, T a) {
  const T t_min = T(0);
  const T s_now = s + u * t_min + a * t_min * t_min / T(2), u_now = u + a * t_min;
  const bool leaving_outside = s_now < T(0) && (u_now < T(0) || (u_now == T(0) && a < T(0)));
  if (a == T(0)) {
    if (!(u < T(0))) return kNever<T>;
    const T t = s / -u;
    return t >= t_min ? t : (leaving_outside ? t_min : kNever<T>);
  }
  const T d = u * u - T(2) * a * s;
  if (d < T(0) || (d == T(0) && a > T(0))) return leaving_outside ? t_min : kNever<T>;
  const T root = std::sqrt(d);
  const T q = u < T(0) ? (-u + root) / T(2) : -(u + root) / T(2);
  const T r1 = q / (a / T(2));
  const T r2 = q != T(0) ? s / q : r1;
  const T outward = a < T(0) ? std::max(r1, r2) : std::min(r1, r2);
  if (outward >= t_min) return outward;
  return leaving_outside ? t_min : kNever<T>;
}

// A wall segment from the header's five scalars ax, ay, bx, by, xi_s.
template <class T>
struct Segment {
  T ax, ay, bx, by;
  T ux, uy, nx, ny;
  T length;
  T one_plus_xi;
};

template <class T>
inline Segment<T> make_segment(T ax, T ay, T bx, T by, T xi) {
  Segment<T> s{};
  s.ax = ax, s.ay = ay, s.bx = bx, s.by = by;
  const T dx = bx - ax, dy = by - ay;
  s.length = std::sqrt(dx * dx + dy * dy);
  s.ux = dx / s.length;
  s.uy = dy / s.length;
  s.nx = -s.uy;
  s.ny = s.ux;
  s.one_plus_xi = T(1) + xi;
  return s;
}

template <class T>
inline T height(const Segment<T>& s, T x, T y) {
  return (x - s.ax) * s.nx + (y - s.ay) * s.ny;
}
template <class T>
inline T along(const Segment<T>& s, T x, T y) {
  return (x - s.ax) * s.ux + (y - s.ay) * s.uy;
}

// tau of a disk at (x, y) with velocity (vx, vy) and radius r against segment s: body, then end points.
template <class T>
inline T segment_contact_time(const Segment<T>& s, T x, T y, T vx, T vy, T r, T beta) {
  T best = kNever<T>;
  const T h = height(s, x, y);
  const T vn = vx * s.nx + vy * s.ny;
  const T dist = h < T(0) ? -h : h;
  const T approach = h < T(0) ? vn : -vn;
  const T b = dist * -approach;
  if (b < T(0) && b * b > beta * (vx * vx + vy * vy)) {
    const T dt = dist > r ? (dist - r) / approach : T(0);
    const T u = along(s, x + vx * dt, y + vy * dt);
    if (u >= T(0) && u <= s.length) best = dt;
  }
  const T ta = contact_time(s.ax - x, s.ay - y, -vx, -vy, r, beta);
  const T tb = contact_time(s.bx - x, s.by - y, -vx, -vy, r, beta);
  if (ta < best) best = ta;
  if (tb < best) best = tb;
  return best;
}

}  // namespace ede::rules::v2
