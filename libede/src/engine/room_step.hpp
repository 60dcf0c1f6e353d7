// The step room: two disks reaching a step of their stepped potential (square wells and shoulders outside
// the hard core: step_table.hpp). Its prediction is part of the pair scan (room_pair.hpp, consider_pair):
// a pair `depth` steps deep can enter the next step inwards (or, innermost, hit the hard core) and leave the
// step it is in; its resolution crosses the step when the kinetic energy of the motion along the line of
// centres pays for the potential energy's change (energy conserved), else bounces off it like a hard wall.
//
// Times: entering a step of radius R is the hard core's root with R for the contact distance (the smaller
// root, pair_contact_time of geometry.hpp, without cancellation: DESIGN.md section 5); leaving it is the
// larger root of |dx + dv t|^2 = R^2, written per sign of b so that no two terms of nearly equal size are
// subtracted: (-b + sqrt(d)) / a for b <= 0, and -c / (b + sqrt(d)) for b > 0 (the same root: the product
// of the two forms' numerators is -a c). Which step an event is at is decided at the event by the distance
// (the nearer of the two radii the pair sits between), not stored in the prediction: the two radii are far
// apart against round-off, where the sign of b at a grazing event is not.
// Rejected: a separate event kind for entering and leaving (one kind, one log rule), and deriving the depth
// from positions at each prediction (step_table.hpp says why).
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include "core/geometry.hpp"
#include "core/scalar_math.hpp"
#include "engine/engine_state.hpp"
#include "engine/neighbours.hpp"

namespace ede {

// Time until a pair inside a circle of radius R (relative position dx, dy, velocity dvx, dvy) reaches it
// on the way out: the larger root; 0 if it is already outside (round-off) and receding, kNever at rest.
template <class T>
T step_leave_time(T dx, T dy, T dvx, T dvy, T radius) {
  const T a = dvx * dvx + dvy * dvy;
  if (a == T(0)) return kNever<T>;
  const T b = dx * dvx + dy * dvy;
  const T c = (dx * dx + dy * dy) - radius * radius;
  if (c >= T(0) && b > T(0)) return T(0);
  const T d = b * b - a * c;
  const T root = d > T(0) ? ede::sqrt(d) : T(0);
  if (b <= T(0)) return (-b + root) / a;
  return -c / (b + root);
}

// The pair (i, k's image shifted by sx, sy) in a stepped engine: its core collision (only when it is
// inside every step of its species pair, and not if it has just collided: skip_core) or its next step
// event, into `best`.
template <class S, class T = typename S::Scalar>
void consider_stepped_pair(const S& s, std::int32_t i, Position2<T> pi, Position2<T> vi, std::int32_t k, T sx, T sy,
                           bool skip_core, Candidate<T>& best) {
  using Contact = typename S::Effects::Contact;
  const auto& table = s.steps;
  const Disk<T>& di = s.p.disk[i];
  const Disk<T>& dk = s.p.disk[k];
  const Position2<T> pk = s.pos_at(dk), vk = s.vel_at(dk);
  const T dx = (pk.x + sx) - pi.x, dy = (pk.y + sy) - pi.y, dvx = vk.x - vi.x, dvy = vk.y - vi.y;
  const auto range = table.steps_of(s.p, i, k);
  const std::int32_t depth = range.count ? table.depth(i, k) : 0;
  const auto offer = [&](T dt, EventKind kind) {
    if (dt == kNever<T>) return;
    const Candidate<T> c{s.now + dt, kind, k};
    if (c.before(best)) best = c;
  };
  if (depth == std::int32_t(range.count)) {
    if (!skip_core) offer(Contact::time(dx, dy, dvx, dvy, di.r + dk.r, s.b_noise2), EventKind::Pair);
  } else {
    offer(pair_contact_time(dx, dy, dvx, dvy, table.radius[range.first + std::uint32_t(depth)], s.b_noise2),
          EventKind::Step);
  }
  if (depth > 0)
    offer(step_leave_time(dx, dy, dvx, dvy, table.radius[range.first + std::uint32_t(depth - 1)]), EventKind::Step);
}

// The change of the normal relative velocity vn (along n, from i to j; < 0 approaching) when a pair of
// reduced mass mu meets a step whose crossing changes the potential energy by du: crossing keeps the energy
// (1/2 mu vn'^2 = 1/2 mu vn^2 - du) when that is positive, else the pair bounces (vn' = -vn). `inward`:
// the side it tries to reach, which sets the signs whatever round-off did to vn's. Returns vn' - vn.
template <class T>
T step_velocity_change(T vn, T mu, T du, bool inward, bool& crossed) {
  const T square = vn * vn - T(2) * du / mu;
  crossed = square > T(0);
  const T after = crossed ? (inward ? -ede::sqrt(square) : ede::sqrt(square))
                          : (inward ? ede::abs(vn) : -ede::abs(vn));
  return after - vn;
}

// Every pair's depth from the positions at now (step_table.hpp): at the start of a run and at a resumed
// run's rebuild point. Needs the grid filled (rebuild_predictions calls it after inserting the disks).
template <class S>
void init_depths(S& s) {
  using T = typename S::Scalar;
  auto& table = s.steps;
  table.bonds.assign(s.p.size(), {});
  table.potential = 0;
  for (std::size_t n = 0; n < s.p.size(); ++n) {
    const std::int32_t i = std::int32_t(n);
    const Disk<T>& di = s.p.disk[n];
    const Position2<T> pi = s.pos_at(di), vi = s.vel_at(di);
    for_each_neighbour(s, i, s.grid.cell_of(i), [&](std::int32_t k, T sx, T sy) {
      if (k < i) return;  // each pair once
      const auto range = table.steps_of(s.p, i, k);
      if (!range.count) return;
      const Position2<T> pk = s.pos_at(s.p.disk[std::size_t(k)]), vk = s.vel_at(s.p.disk[std::size_t(k)]);
      const T dx = (pk.x + sx) - pi.x, dy = (pk.y + sy) - pi.y;
      const T b = dx * (vk.x - vi.x) + dy * (vk.y - vi.y);
      const std::int32_t depth = table.depth_at(range, dx * dx + dy * dy, b);
      if (depth == 0) return;
      table.set_depth(i, k, depth);
      table.potential += table.energy_at_depth(range, depth);
    });
  }
  table.depths_known = true;
}

// Disks i and k at a step. Resolved in the order (lower id, higher id), as a pair collision is.
template <class S>
void resolve_step(S& s, std::int32_t i, std::int32_t j) {
  using T = typename S::Scalar;
  using Fx = typename S::Effects;
  if (j < i) std::swap(i, j);
  auto& table = s.steps;
  const RecordBefore<T> before_i = record_before(s.p.disk[i]), before_j = record_before(s.p.disk[j]);
  s.advance(i);
  s.advance(j);
  Disk<T>& a = s.p.disk[i];
  Disk<T>& b = s.p.disk[j];
  const T vix0 = a.vx, viy0 = a.vy, vjx0 = b.vx, vjy0 = b.vy;
  T dx, dy;
  separation(s, a, b, dx, dy);
  const auto range = table.steps_of(s.p, i, j);
  const std::int32_t depth = table.depth(i, j);
  const T d2 = dx * dx + dy * dy;
  // The radius the pair is at: the next one in (depth < count) or the one it is in (depth > 0), the nearer.
  bool inward = depth < std::int32_t(range.count);
  if (inward && depth > 0) {
    const T inner = table.radius[range.first + std::uint32_t(depth)];
    const T outer = table.radius[range.first + std::uint32_t(depth - 1)];
    inward = ede::abs(d2 - inner * inner) < ede::abs(d2 - outer * outer);
  }
  const std::uint32_t step = range.first + std::uint32_t(inward ? depth : depth - 1);
  const T du = inward ? table.energy[step] : -table.energy[step];
  const T mi = s.p.mass(i), mj = s.p.mass(j), m = mi + mj;
  const T dist = ede::sqrt(d2);
  const T nx = dx / dist, ny = dy / dist;
  const T vn = (b.vx - a.vx) * nx + (b.vy - a.vy) * ny;
  bool crossed = false;
  const T dvn = step_velocity_change(vn, mi * mj / m, du, inward, crossed);
  const T ki = dvn * mj / m, kj = dvn * mi / m;
  const double ke_before = s.disk_energy(i) + s.disk_energy(j);
  a.vx -= ki * nx, a.vy -= ki * ny;
  b.vx += kj * nx, b.vy += kj * ny;
  if (crossed) {
    table.set_depth(i, j, depth + (inward ? 1 : -1));
    table.potential += double(du);
  }
  if constexpr (Fx::kDissipative) s.dissipation.ke += s.disk_energy(i) + s.disk_energy(j) - ke_before;
  ++a.counter;
  ++b.counter;
  // Their velocities changed: a core collision between them is possible again at once (a bounce off a
  // well's edge brings them straight back), so they are no longer each other's last partner.
  if (a.last_partner == j) a.last_partner = -1;
  if (b.last_partner == i) b.last_partner = -1;
  ++s.counts.by_kind[int(EventKind::Step)];
  if (!s.sinks.empty())
    s.emit({s.now, EventKind::Step, false, i, j, a.vx, a.vy, b.vx, b.vy, vix0, viy0, vjx0, vjy0, T(0), T(0), T(0),
            T(0), before_i, before_j, false, false});
  predict_disk(s, i);
  predict_disk(s, j);
}

}  // namespace ede
