// Collision records (ede/collision_stats.hpp): the impact parameter, relative speeds and impulse of one
// logged event, from the positions and velocities the event record carries and the disks' radii and
// masses; and the walk over a range that pairs each event with its record.
// Long double throughout, from the log's exact values (widened), so a double log's records carry no
// rounding of their own beyond the final conversion. Rejected: recomputing contact geometry from the
// state (the event already has the positions at contact: the engine's own numbers).
#include <cmath>

#include "ede/collision_stats.hpp"

namespace ede {

namespace {

using LD = long double;

// The nearest periodic image of a separation d in a box of length l.
LD nearest(LD d, double l) { return d - LD(l) * std::round(d / LD(l)); }

void set_impulse(CollisionRecord& r, const Event& e, LD m) {
  const LD jx = m * (e.vix - e.vix_before), jy = m * (e.viy - e.viy_before);
  r.impulse_x = double(jx), r.impulse_y = double(jy), r.impulse = double(std::hypot(jx, jy));
}

void pair_geometry(CollisionRecord& r, const Event& e, const CollisionDisks& d) {
  const auto i = std::size_t(e.i), j = std::size_t(e.j);
  LD rx = e.xi - e.xj, ry = e.yi - e.yj;
  if (d.periodic) rx = nearest(rx, d.lx), ry = nearest(ry, d.ly);
  const LD gx = e.vix_before - e.vjx_before, gy = e.viy_before - e.vjy_before;
  const LD rn = std::hypot(rx, ry), g = std::hypot(gx, gy);
  const LD sigma = d.radius[i] + d.radius[j];
  const LD nx = rn > 0 ? rx / rn : 0, ny = rn > 0 ? ry / rn : 0;
  r.relative_speed = double(g);
  r.normal_speed = double(-(gx * nx + gy * ny));
  r.tangential_speed = double(-gx * ny + gy * nx);
  r.impact_parameter = g > 0 && sigma > 0 ? double((rx * gy - ry * gx) / (g * sigma)) : 0;
  r.reduced_mass = double(d.mass[i] * d.mass[j] / (d.mass[i] + d.mass[j]));
}

// |v_i . n| before: a box wall's normal is an axis; a segment's is the impulse's direction.
double wall_normal_speed(const Event& e, const CollisionRecord& r) {
  if (e.kind == EventKind::Wall) return double(std::fabs(e.j == kWallLeft || e.j == kWallRight ? e.vix_before : e.viy_before));
  if (!(r.impulse > 0)) return 0;
  return std::fabs((double(e.vix_before) * r.impulse_x + double(e.viy_before) * r.impulse_y) / r.impulse);
}

}  // namespace

Result<CollisionDisks> collision_disks(const Log& log) {
  auto s = log.state_at_event(0);
  if (!s) return s.error();
  const State& st = s.value();
  CollisionDisks d;
  d.lx = st.lx, d.ly = st.ly, d.periodic = st.boundary == BoundaryKind::Periodic;
  d.radius.resize(st.size()), d.mass.resize(st.size());
  for (std::size_t k = 0; k < st.size(); ++k) d.radius[k] = st.radius.exact(k), d.mass[k] = st.mass.exact(k);
  return d;
}

CollisionRecord collision_record(const Event& e, const CollisionDisks& d) {
  CollisionRecord r;
  const bool known_i = e.i >= 0 && std::size_t(e.i) < d.mass.size();
  if (e.kind == EventKind::Pair && known_i && e.j >= 0 && std::size_t(e.j) < d.mass.size()) {
    r.pair = true;
    set_impulse(r, e, d.mass[std::size_t(e.i)]);
    pair_geometry(r, e, d);
  } else if ((e.kind == EventKind::Wall || e.kind == EventKind::Segment) && known_i) {
    r.wall = true;
    set_impulse(r, e, d.mass[std::size_t(e.i)]);
    r.normal_speed = wall_normal_speed(e, r);
    r.relative_speed = double(std::hypot(e.vix_before, e.viy_before));
  }
  return r;
}

Status for_each_collision(const Log& log, const EventRange& range,
                          const std::function<bool(const Event&, const CollisionRecord&)>& f) {
  auto disks = collision_disks(log);
  if (!disks) return disks.error();
  const CollisionDisks& d = disks.value();
  return log.for_each_event(range, [&](const Event& e) { return f(e, collision_record(e, d)); });
}

}  // namespace ede
