// Collision rules: the post-collision velocities of a pair and of a disk at a wall, with restitution.
//
// Pair (the course's rule): with dx = x_j - x_i, dv = v_j - v_i at contact, R = |dx| = r_i + r_j,
//   v_i' = v_i + (1 + xi) m_j / (m_i + m_j) (dv.dx) / R^2 dx,   v_j' = v_j - (1 + xi) m_i / (m_i + m_j) ...
// We evaluate it as an impulse along the unit normal n = dx / |dx| with the measured |dx|:
//   J = (1 + xi) (dv.n) / (m_i + m_j),   v_i' = v_i + J m_j n,   v_j' = v_j - J m_i n.
// At contact this is the course's formula; with the measured |dx| the impulse stays exactly along the
// line of centres when round-off leaves the pair a hair apart or overlapping (an elastic collision keeps
// the energy to the last bits), and for axis-aligned pairs n is exact (sqrt(d*d) == |d| in IEEE
// arithmetic), so a head-on collision with xi = 0 leaves the relative velocity exactly zero.
// Wall (the course's rule, tangential factor included): vertical wall v' = (-xi vx, xi vy), horizontal
// wall v' = (xi vx, -xi vy). The elastic versions are separate functions so the elastic engine carries no
// multiplication by 1.
#pragma once

#include "core/scalar_math.hpp"

namespace ede {

// Applies a pair collision in place. `one_plus_xi` is 2 for an elastic collision.
template <class T>
inline void collide_pair(T dx, T dy, T mi, T mj, T one_plus_xi, T& vix, T& viy, T& vjx, T& vjy) {
  const T dist = ede::sqrt(dx * dx + dy * dy);
  const T nx = dx / dist;
  const T ny = dy / dist;
  const T vn = (vjx - vix) * nx + (vjy - viy) * ny;  // normal relative speed, < 0 when approaching
  const T impulse = one_plus_xi * vn / (mi + mj);
  const T ki = impulse * mj;
  const T kj = impulse * mi;
  vix = vix + ki * nx;
  viy = viy + ki * ny;
  vjx = vjx - kj * nx;
  vjy = vjy - kj * ny;
}

// Wall collisions: `vertical` walls are x = 0 and x = Lx.
template <class T>
inline void collide_wall_elastic(bool vertical, T& vx, T& vy) {
  if (vertical)
    vx = -vx;
  else
    vy = -vy;
}

template <class T>
inline void collide_wall(bool vertical, T xi, T& vx, T& vy) {
  if (vertical) {
    vx = -xi * vx;
    vy = xi * vy;
  } else {
    vx = xi * vx;
    vy = -xi * vy;
  }
}

}  // namespace ede
