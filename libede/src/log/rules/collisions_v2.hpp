// The collision rules of format version 2's predicted velocities (schema/FORMAT.md, "Predicted velocities"
// and "Rotation"), frozen with that version: a pair, a box wall and a wall segment, smooth and rough.
//
// Written from FORMAT.md, operation by operation. The engine resolves collisions with its own functions
// (engine/collide.hpp), which tests/log/test_format_rules.cpp shows give these bits, so an ordinary run's
// residuals are 0; an engine that changed its rule would make its logs larger, never wrong (a residual
// carries any difference), and a rule that follows it would be a new format version. Includes only the
// standard library and the other rules (see state_update.hpp).
#pragma once

#include <cmath>
#include <cstdint>

#include "log/rules/geometry_v2.hpp"
#include "log/rules/state_update.hpp"

namespace ede::rules::v2 {

// Pair (i, j) with relative position (dx, dy) = x_j - x_i at the event, k = 1 + xi (2 with the TC flag).
template <class T>
inline void pair_rule(T dx, T dy, T mi, T mj, T k, T& vix, T& viy, T& vjx, T& vjy) {
  const T dist = std::sqrt(dx * dx + dy * dy);
  const T nx = dx / dist;
  const T ny = dy / dist;
  const T vn = (vjx - vix) * nx + (vjy - viy) * ny;
  const T impulse = k * vn / (mi + mj);
  const T ki = impulse * mj;
  const T kj = impulse * mi;
  vix = vix + ki * nx;
  viy = viy + ki * ny;
  vjx = vjx - kj * nx;
  vjy = vjy - kj * ny;
}

// The rough pair's tangential part, after pair_rule, with (dvx, dvy) = v_j - v_i and the spins before the
// collision; k_b = 1 + beta (0: nothing is computed, the spins are predicted unchanged).
template <class T>
inline void pair_rule_tangential(T dx, T dy, T dvx, T dvy, T mi, T mj, T ri, T rj, T inertia_i, T inertia_j, T k_b,
                                 T& vix, T& viy, T& vjx, T& vjy, T& wi, T& wj) {
  if (k_b == T(0)) return;
  const T dist = std::sqrt(dx * dx + dy * dy);
  const T tx = -(dy / dist), ty = dx / dist;
  const T gt = (dvx * tx + dvy * ty) - (ri * wi + rj * wj);
  const T kk = ((T(1) / mi + T(1) / mj) + ri * ri / inertia_i) + rj * rj / inertia_j;
  const T p = k_b * gt / kk;
  vix = vix + (p / mi) * tx;
  viy = viy + (p / mi) * ty;
  vjx = vjx - (p / mj) * tx;
  vjy = vjy - (p / mj) * ty;
  wi = wi + ri * p / inertia_i;
  wj = wj + rj * p / inertia_j;
}

// A box wall: with the TC flag the elastic reflection, else (-xi vx, xi vy) at a vertical wall and
// (xi vx, -xi vy) at a horizontal one (-xi computed first).
template <class T>
inline void wall_rule(std::int32_t wall, bool tc_elastic, T xi, T& vx, T& vy) {
  const bool vertical = wall == kLeft || wall == kRight;
  if (tc_elastic) {
    if (vertical)
      vx = -vx;
    else
      vy = -vy;
    return;
  }
  if (vertical) {
    vx = -xi * vx;
    vy = xi * vy;
  } else {
    vx = xi * vx;
    vy = -xi * vy;
  }
}

// The rough wall's tangential part, after wall_rule, from the velocity (vx0, vy0) before the collision.
template <class T>
inline void wall_rule_tangential(std::int32_t wall, T vx0, T vy0, T m, T r, T inertia, T k_b, T& vx, T& vy, T& w) {
  if (k_b == T(0)) return;
  static constexpr int kNormal[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};  // left, right, bottom, top
  const T nx = T(kNormal[wall & 3][0]), ny = T(kNormal[wall & 3][1]);
  const T tx = -ny, ty = nx;
  const T gt = (T(0) - (vx0 * tx + vy0 * ty)) - r * w;
  const T kk = T(1) / m + r * r / inertia;
  const T p = k_b * gt / kk;
  vx = vx + (p / m) * tx;
  vy = vy + (p / m) * ty;
  w = w + r * p / inertia;
}

// v' = v - k (v.m) m along a unit direction (mx, my).
template <class T>
inline void reflect(T mx, T my, T k, T& vx, T& vy) {
  const T vn = (T(0) - vx) * mx + (T(0) - vy) * my;
  const T q = k * vn;
  vx = vx + q * mx;
  vy = vy + q * my;
}

// A disk at (x, y) at the event hits segment s: the body or the near end point, by the rule of FORMAT.md.
template <class T>
inline void segment_rule(const Segment<T>& s, T x, T y, T k, T& vx, T& vy) {
  const T u = along(s, x, y);
  const bool below = height(s, x, y) < T(0);
  const T bx = below ? s.nx : -s.nx, by = below ? s.ny : -s.ny;
  const bool body_in = vx * bx + vy * by > T(0);
  const bool on_body = u > T(0) && u < s.length;
  if (on_body && body_in) return reflect(bx, by, k, vx, vy);
  const bool near_a = u < s.length / T(2);
  const T dx = (near_a ? s.ax : s.bx) - x, dy = (near_a ? s.ay : s.by) - y;
  const T d = std::sqrt(dx * dx + dy * dy);
  const T ex = dx / d, ey = dy / d;
  if (vx * ex + vy * ey > T(0)) return reflect(ex, ey, k, vx, vy);
  if (!on_body && body_in) reflect(bx, by, k, vx, vy);
}

}  // namespace ede::rules::v2
