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
// Segment (a straight wall of any direction, core/segment.hpp): the disk-disk rule with the segment as an
// infinite mass at rest, v' = v - (1 + xi) (v.n) n: the normal component reversed and scaled by xi, the
// tangential one kept (unlike the box walls' course rule, which scales it by xi too: a segment is the
// limit of a disk, and that is what its tests compare with). On the body n is the segment's own unit
// normal (exact reflection angles, no measured direction); at an end point, n = (E - x) / |E - x| with
// the measured distance, computed as collide_pair computes it, so an end point is bit for bit a disk of
// mass 2^60 times the disk's at rest there.
// Rough disks (Smooth/Rough, effects.hpp): the standard rough-sphere rule in 2D, as in S. Luding,
// M. Huthmann, S. McNamara, A. Zippelius, "Homogeneous cooling of rough, dissipative particles: theory and
// simulations", Phys. Rev. E 58, 3416 (1998), eqs. (1)-(4), with omega a scalar (counter-clockwise). With
// n the unit normal from i to j and t = (-n_y, n_x), disk i's contact point moves at v_i + r_i w_i t and
// j's at v_j - r_j w_j t, so the relative contact velocity (j against i) has the tangential part
//   g_t = (v_j - v_i).t - (r_i w_i + r_j w_j).
// The rule reverses and scales it by beta: g_t' = -beta g_t (beta = -1 smooth, +1 perfectly rough), by a
// tangential impulse P_t t on i (-P_t t on j), whose torque is r_i P_t on i and r_j P_t on j:
//   P_t = (1 + beta) g_t / K,   K = 1/m_i + 1/m_j + r_i^2/I_i + r_j^2/I_j,
//   v_i' = v_i + (P_t/m_i) t,  v_j' = v_j - (P_t/m_j) t,  w_i' = w_i + r_i P_t/I_i,  w_j' = w_j + r_j P_t/I_j,
// after the normal impulse of collide_pair (unchanged, xi as for smooth disks). g_t is taken before the
// collision (the normal impulse does not change it). With I = q m r^2 and equal disks this is Luding's
// eta_t = q (1 + beta) / (2 (1 + q)). Energy: with xi = 1 and beta = +-1 nothing is lost; otherwise the
// loss is (1 - xi^2) mu g_n^2 / 2 + (1 - beta^2) g_t^2 / (2 K). beta = -1 skips the tangential part, so a
// smooth pair in a rough engine computes bit for bit what collide_pair does.
// A box wall is a partner of infinite mass and inertia at rest: g_t = -v.t - r w, K = 1/m + r^2/I, with n
// the wall's outward normal; it acts after the course's wall rule (which scales the tangential velocity
// by xi_w too), so beta_w = -1 leaves that rule exactly as it is.
#pragma once

#include "core/scalar_math.hpp"
#include "core/segment.hpp"

namespace ede {

// These rules are format version 2's (log/rules/collisions_v2.hpp; tests/log/test_format_rules.cpp checks
// the bits): the engine tells the log writer so with every collision (EventOutcome::v2_velocities_exact), and
// the writer codes residuals of 0 without recomputing them. A change to a rule here sets this false (its
// logs then grow) until a format version follows it.
inline constexpr bool kRulesAreFormatV2 = true;

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

// The tangential impulse of a rough pair (the rule above), applied after collide_pair. (nx, ny) is the
// normal from i to j, measured as collide_pair measures it; dv = v_j - v_i and the spins are pre-collision.
template <class T>
inline void collide_pair_tangential(T dx, T dy, T dvx, T dvy, T mi, T mj, T ri, T rj, T inertia_i, T inertia_j,
                                    T one_plus_beta, T& vix, T& viy, T& vjx, T& vjy, T& wi, T& wj) {
  if (one_plus_beta == T(0)) return;  // smooth: nothing changes, not even the sign of a zero
  const T dist = ede::sqrt(dx * dx + dy * dy);
  const T tx = -(dy / dist), ty = dx / dist;
  const T gt = (dvx * tx + dvy * ty) - (ri * wi + rj * wj);
  const T k = ((T(1) / mi + T(1) / mj) + ri * ri / inertia_i) + rj * rj / inertia_j;
  const T pt = one_plus_beta * gt / k;
  vix = vix + (pt / mi) * tx;
  viy = viy + (pt / mi) * ty;
  vjx = vjx - (pt / mj) * tx;
  vjy = vjy - (pt / mj) * ty;
  wi = wi + ri * pt / inertia_i;
  wj = wj + rj * pt / inertia_j;
}

// The tangential impulse of a rough wall: (nx, ny) the wall's outward unit normal (from the disk to the
// wall), (vx0, vy0) the velocity before the collision; applied after the wall's own rule.
template <class T>
inline void collide_wall_tangential(T nx, T ny, T vx0, T vy0, T m, T r, T inertia, T one_plus_beta, T& vx, T& vy,
                                    T& w) {
  if (one_plus_beta == T(0)) return;
  const T tx = -ny, ty = nx;
  const T gt = (T(0) - (vx0 * tx + vy0 * ty)) - r * w;
  const T k = T(1) / m + r * r / inertia;
  const T pt = one_plus_beta * gt / k;
  vx = vx + (pt / m) * tx;
  vy = vy + (pt / m) * ty;
  w = w + r * pt / inertia;
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

// v' = v - k (v.n) n along a unit normal (nx, ny), k = 1 + xi.
template <class T>
inline void reflect_unit(T nx, T ny, T one_plus_xi, T& vx, T& vy) {
  const T vn = (T(0) - vx) * nx + (T(0) - vy) * ny;  // collide_pair's dv.n with v_j = 0
  const T k = one_plus_xi * vn;
  vx = vx + k * nx;
  vy = vy + k * ny;
}

// A disk whose centre is at (x, y) at contact hits segment s: on its body when the centre projects
// strictly between the end points, else at the nearer end point; but if the disk is not moving towards
// that part (v.m <= 0) and is moving towards the other one (the body, or the end point nearer by the
// projection), the other one. Only round-off makes the two differ: a grazing hit within ~1e-9 r of an end
// point is predicted at the end point while the centre projects onto the body; reflecting a receding disk
// off the body would turn it into the segment. Neither approached: the velocity is kept. `one_plus_xi`
// is the segment's (or 2 when the TC model makes the collision elastic).
template <class T>
inline void collide_segment(const Segment<T>& s, T x, T y, T one_plus_xi, T& vx, T& vy) {
  const T along = segment_along(s, x, y);
  const bool below = segment_height(s, x, y) < T(0);
  const T bx = below ? s.nx : -s.nx, by = below ? s.ny : -s.ny;  // the body's normal, towards the line
  const bool body_in = vx * bx + vy * by > T(0);
  const bool on_body = along > T(0) && along < s.length;
  if (on_body && body_in) return reflect_unit(bx, by, one_plus_xi, vx, vy);
  const bool near_a = along < s.length / T(2);
  const T dx = (near_a ? s.ax : s.bx) - x, dy = (near_a ? s.ay : s.by) - y;
  const T dist = ede::sqrt(dx * dx + dy * dy);
  const T ex = dx / dist, ey = dy / dist;  // towards the end point
  if (vx * ex + vy * ey > T(0)) return reflect_unit(ex, ey, one_plus_xi, vx, vy);
  if (!on_body && body_in) reflect_unit(bx, by, one_plus_xi, vx, vy);
}

}  // namespace ede
