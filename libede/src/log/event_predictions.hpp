// What format version 2 predicts of a logged event (schema/FORMAT.md, "Predicted times" and "Predicted
// velocities"): its time from the records of its disks just before it, and the velocities (and spins) after
// it by the collision rules, with the header's physics. The log stores only the residual against each
// prediction: 0 (one byte, compressed to almost nothing) when the engine computed exactly this.
//
// The arithmetic is the format's own, frozen with version 2 (log/rules/: written from FORMAT.md, including
// nothing of the engine's), so a version 2 log decodes to the same states whatever a later engine does; the
// engine keeps its own functions, and tests/log/test_format_rules.cpp shows where they agree bit for bit (a
// residual is 0 there). What the engine knows and replay does not is either in the header (restitution per
// species pair and per wall, segments, roughness) or in the event itself (the TC model's "made elastic"
// flag, one bit of the kind byte), so no prediction needs history.
// The predictors read records (any type with x, y, vx, vy, t and r: replay's Disk<T>, or the copies the
// engine hands the log writer with each event, log/logged_event.hpp), so the writer needs no copy of the
// state. A pair's time is predicted at now = the later of the two records' times, which is when the engine
// predicted it unless it did so at a cell crossing, a rebuild or before a periodic wrap of one of them:
// then the residual is a few ulps (a few bytes), never wrong.
// Rejected: the engine's own functions as predictors (version 2 did so until issue 33: a one-bit change to
// a collision rule would have changed what every existing log decodes to), tracking TC collision times in
// replay (non-resumable keyframes do not carry them) and storing the engine's prediction time with each
// event (as large as the time residual it would save).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "ede/events.hpp"
#include "log/rules/collisions_v2.hpp"
#include "log/rules/geometry_v2.hpp"
#include "log/rules/state_update.hpp"

namespace ede {

// The header's physics, in the run's scalar type, as the predictors need it.
template <class T>
struct EventPhysics {
  T lx = 1, ly = 1, half_lx = T(0.5), half_ly = T(0.5);
  bool periodic = false;
  T gx = 0, gy = 0;
  T b_noise2 = 0;
  std::size_t species = 1;
  std::vector<T> one_plus_xi{T(2)};  // species x species, row-major: 1 + xi of the pair
  T xi_wall[4] = {1, 1, 1, 1};
  bool tc_model = false;  // writer only: the run may make collisions elastic (ChunkEncoder's TC flag)
  std::vector<rules::v2::Segment<T>> segments;  // from the header's scalars (FORMAT.md "Wall segments")
  // Rough runs (the header's onePlusBeta): 1 + beta per species pair, row-major, and of the box walls.
  std::vector<T> one_plus_beta{T(0)};
  T wall_one_plus_beta = 0;
  bool rough = false;  // a rough log (the header has moments of inertia): spins are coded and predicted

  static EventPhysics box(double lx, double ly, bool periodic, T gx, T gy) {
    EventPhysics p;
    p.lx = T(lx), p.ly = T(ly);
    p.half_lx = p.lx / 2, p.half_ly = p.ly / 2;
    p.periodic = periodic;
    p.gx = gx, p.gy = gy;
    p.b_noise2 = rules::v2::noise_floor2(p.lx, p.ly);
    return p;
  }
  bool gravity() const { return gx != T(0) || gy != T(0); }
  T pair_one_plus_xi(std::int32_t si, std::int32_t sj) const {
    const std::size_t a = std::size_t(si), b = std::size_t(sj);
    if (a >= species || b >= species) return one_plus_xi[0];
    return one_plus_xi[a * species + b];
  }
  T pair_one_plus_beta(std::int32_t si, std::int32_t sj) const {
    const std::size_t a = std::size_t(si), b = std::size_t(sj);
    if (a >= species || b >= species || one_plus_beta.size() != species * species) return one_plus_beta[0];
    return one_plus_beta[a * species + b];
  }
};

// What the velocity predictors read of a disk besides its record: mass and species, and in a rough log
// its spin before the event and its moment of inertia.
template <class T>
struct DiskTraits {
  T mass{};
  std::int32_t species = 0;
  T omega{}, inertia{};
};

// Time of pair (i, j) from their records a (of i) and b (of j): predicted by the disk whose record is
// later (i on a tie), at now = that record's time, against the partner's image nearest at now.
// kGravity = false is for callers that know the header has no gravity: the same bits, with the gravity
// branches compiled out (replay's decoder; position_along with g = 0 is drift exactly).
template <class T, bool kGravity = true, class R>
[[gnu::always_inline]] inline T predict_pair_time(const EventPhysics<T>& ph, const R& a, const R& b) {
  const R* di = &a;
  const R* dj = &b;
  if (dj->t > di->t) std::swap(di, dj);
  const T now = di->t;
  const T gx = kGravity ? ph.gx : T(0), gy = kGravity ? ph.gy : T(0);
  const T pix = rules::position_along(di->x, di->vx, gx, di->t, now);
  const T piy = rules::position_along(di->y, di->vy, gy, di->t, now);
  const T pjx = rules::position_along(dj->x, dj->vx, gx, dj->t, now);
  const T pjy = rules::position_along(dj->y, dj->vy, gy, dj->t, now);
  T sx = 0, sy = 0;
  if (ph.periodic) {
    const T ex = pjx - pix, ey = pjy - piy;
    sx = ex > ph.half_lx ? -ph.lx : ex < -ph.half_lx ? ph.lx : T(0);
    sy = ey > ph.half_ly ? -ph.ly : ey < -ph.half_ly ? ph.ly : T(0);
  }
  const T vix = rules::velocity_along(di->vx, gx, di->t, now), viy = rules::velocity_along(di->vy, gy, di->t, now);
  const T vjx = rules::velocity_along(dj->vx, gx, dj->t, now), vjy = rules::velocity_along(dj->vy, gy, dj->t, now);
  return now + rules::v2::contact_time((pjx + sx) - pix, (pjy + sy) - piy, vjx - vix, vjy - viy, di->r + dj->r,
                                       ph.b_noise2);
}

// Time a disk hits `wall`, from its record alone.
template <class T, class R>
inline T predict_wall_time(const EventPhysics<T>& ph, const R& d, std::int32_t wall) {
  using rules::v2::reach;
  constexpr T kNever = rules::v2::kNever<T>;
  if (ph.gx == T(0) && ph.gy == T(0)) {
    switch (wall) {
      case rules::kRight: return d.vx > 0 ? d.t + reach(d.x, d.vx, ph.lx - d.r) : kNever;
      case rules::kLeft: return d.vx < 0 ? d.t + reach(d.x, d.vx, d.r) : kNever;
      case rules::kTop: return d.vy > 0 ? d.t + reach(d.y, d.vy, ph.ly - d.r) : kNever;
      case rules::kBottom: return d.vy < 0 ? d.t + reach(d.y, d.vy, d.r) : kNever;
      default: return kNever;
    }
  }
  T dt = kNever;
  switch (wall) {
    case rules::kLeft: dt = rules::v2::reach_accelerated(d.x - d.r, d.vx, ph.gx); break;
    case rules::kRight: dt = rules::v2::reach_accelerated((ph.lx - d.r) - d.x, -d.vx, -ph.gx); break;
    case rules::kBottom: dt = rules::v2::reach_accelerated(d.y - d.r, d.vy, ph.gy); break;
    case rules::kTop: dt = rules::v2::reach_accelerated((ph.ly - d.r) - d.y, -d.vy, -ph.gy); break;
    default: break;
  }
  return dt == kNever ? kNever : d.t + dt;
}

// Time a disk crosses the periodic edge `dir`, from its record alone.
template <class T, class R>
inline T predict_wrap_time(const EventPhysics<T>& ph, const R& d, std::int32_t dir) {
  using rules::v2::reach;
  constexpr T kNever = rules::v2::kNever<T>;
  switch (dir) {
    case rules::kWrapRight: return d.vx > 0 ? d.t + reach(d.x, d.vx, ph.lx) : kNever;
    case rules::kWrapLeft: return d.vx < 0 ? d.t + reach(d.x, d.vx, T(0)) : kNever;
    case rules::kWrapTop: return d.vy > 0 ? d.t + reach(d.y, d.vy, ph.ly) : kNever;
    case rules::kWrapBottom: return d.vy < 0 ? d.t + reach(d.y, d.vy, T(0)) : kNever;
    default: return kNever;
  }
}

// Time a disk hits segment s, from its record alone.
template <class T, class R>
inline T predict_segment_time(const EventPhysics<T>& ph, const R& d, std::int32_t s) {
  constexpr T kNever = rules::v2::kNever<T>;
  if (s < 0 || std::size_t(s) >= ph.segments.size()) return kNever;
  const T dt = rules::v2::segment_contact_time(ph.segments[std::size_t(s)], d.x, d.y, d.vx, d.vy, d.r, ph.b_noise2);
  return dt == kNever ? kNever : d.t + dt;
}

// Velocities after pair (i, j): `a` and `b` are their records brought to the event's time (rules::bring_to),
// ci and cj what else the rule reads. Rough logs (`rough`): the tangential part too, from the velocities and
// spins before the collision (skipped with the TC flag), and the spins after it in w[0], w[1].
template <class T, class R>
inline void predict_pair_velocities(const EventPhysics<T>& ph, const R& a, const R& b, const DiskTraits<T>& ci,
                                    const DiskTraits<T>& cj, bool rough, bool tc_elastic, T v[4], T w[2]) {
  T dx = b.x - a.x, dy = b.y - a.y;
  if (ph.periodic) {
    if (dx > ph.half_lx) dx -= ph.lx; else if (dx < -ph.half_lx) dx += ph.lx;
    if (dy > ph.half_ly) dy -= ph.ly; else if (dy < -ph.half_ly) dy += ph.ly;
  }
  const T k = tc_elastic ? T(2) : ph.pair_one_plus_xi(ci.species, cj.species);
  v[0] = a.vx, v[1] = a.vy, v[2] = b.vx, v[3] = b.vy;
  rules::v2::pair_rule(dx, dy, ci.mass, cj.mass, k, v[0], v[1], v[2], v[3]);
  if (!rough) return;
  w[0] = ci.omega, w[1] = cj.omega;
  const T k_b = tc_elastic ? T(0) : ph.pair_one_plus_beta(ci.species, cj.species);
  rules::v2::pair_rule_tangential(dx, dy, b.vx - a.vx, b.vy - a.vy, ci.mass, cj.mass, a.r, b.r, ci.inertia,
                                  cj.inertia, k_b, v[0], v[1], v[2], v[3], w[0], w[1]);
}

// Velocity after a disk with record d hits `wall` at time t; rough logs: the spin after it in *w.
template <class T, class R>
inline void predict_wall_velocity(const EventPhysics<T>& ph, const R& d, T t, std::int32_t wall,
                                  const DiskTraits<T>& c, bool rough, bool tc_elastic, T v[2], T* w) {
  v[0] = rules::velocity_along(d.vx, ph.gx, d.t, t), v[1] = rules::velocity_along(d.vy, ph.gy, d.t, t);
  const T vx0 = v[0], vy0 = v[1];
  rules::v2::wall_rule(wall, tc_elastic, ph.xi_wall[wall & 3], v[0], v[1]);
  if (!rough) return;
  *w = c.omega;
  rules::v2::wall_rule_tangential(wall, vx0, vy0, c.mass, d.r, c.inertia, tc_elastic ? T(0) : ph.wall_one_plus_beta,
                                  v[0], v[1], *w);
}

// Velocity after a disk with record d hits segment s at time t: a copy brought to t, then the segment's rule.
template <class T, class R>
inline void predict_segment_velocity(const EventPhysics<T>& ph, const R& d, T t, std::int32_t s, bool tc_elastic,
                                     T v[2]) {
  R at = d;
  rules::bring_to(at, t, ph.gx, ph.gy);
  v[0] = at.vx, v[1] = at.vy;
  if (s < 0 || std::size_t(s) >= ph.segments.size()) return;  // a version 1 log's header lists no segments
  const rules::v2::Segment<T>& g = ph.segments[std::size_t(s)];
  rules::v2::segment_rule(g, at.x, at.y, tc_elastic ? T(2) : g.one_plus_xi, v[0], v[1]);
}

// The time a version 2 log predicts for an event from the records of its disks just before it (a of i, b of
// j for a pair; +infinity: no prediction).
template <class T, class R>
inline T predicted_event_time(const EventPhysics<T>& ph, EventKind kind, const R& a, const R& b, std::int32_t j) {
  switch (kind) {
    case EventKind::Pair: return predict_pair_time(ph, a, b);
    case EventKind::Wall: return predict_wall_time(ph, a, j);
    case EventKind::Wrap:
    case EventKind::Shear: return predict_wrap_time(ph, a, j);  // version 3: reaching the top or bottom edge
    case EventKind::Segment: return predict_segment_time(ph, a, j);
    default: return rules::v2::kNever<T>;
  }
}

}  // namespace ede
