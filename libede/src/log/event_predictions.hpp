// What replay predicts of a logged event from the replayed state just before it (format version 2,
// schema/FORMAT.md "Predictions"): the post-event velocities by the engine's own collision rules, and
// the event's time by the engine's own contact, wall and cell-exit time functions. Writer and reader call
// these same functions with the same inputs, so a prediction is the same bits on both sides; the log
// stores only the residual against it, which is 0 (one byte, compressed to almost nothing) whenever the
// engine computed exactly this.
//
// The rules are the engine's (engine/collide.hpp, engine/predict_pair.hpp, core/geometry.hpp), called, not
// copied: when the engine changes a rule, old logs still decode (the residuals carry the difference) and
// new logs simply grow until the predictor follows. What the engine knows and replay does not is either
// in the header (restitution per species pair and per wall) or in the event itself (the TC model's
// "this collision was made elastic" flag, one bit of the kind byte), so no prediction needs history.
// A pair's time is predicted at now = the later of the two records' times, which is when the engine
// predicted it unless it did so at a cell crossing, a rebuild or before a periodic wrap of one of them:
// then the residual is a few ulps (a few bytes), never wrong.
// Rejected: tracking TC collision times in replay (non-resumable keyframes do not carry them, so a seek
// would have to start at a resumable one) and storing the engine's prediction time with each event (as
// large as the time residual it would save).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/drift.hpp"
#include "core/event.hpp"
#include "core/geometry.hpp"
#include "core/particles.hpp"
#include "core/segment.hpp"
#include "engine/collide.hpp"
#include "engine/predict_pair.hpp"

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
  // Wall segments, built by make_segment from the header's scalars as the engine builds them from the
  // scene's doubles converted to T (the same values, so the same unit vectors).
  std::vector<Segment<T>> segments;
  // Rough runs (the header's onePlusBeta; the replayed state then has omega and inertia): 1 + beta per
  // species pair, row-major like one_plus_xi, and of the box walls.
  std::vector<T> one_plus_beta{T(0)};
  T wall_one_plus_beta = 0;

  // The box as the engine sets it up (engine_core.hpp: lx_, half_lx_, b_noise2_).
  static EventPhysics box(double lx, double ly, bool periodic, T gx, T gy) {
    EventPhysics p;
    p.lx = T(lx), p.ly = T(ly);
    p.half_lx = p.lx / 2, p.half_ly = p.ly / 2;
    p.periodic = periodic;
    p.gx = gx, p.gy = gy;
    p.b_noise2 = b_noise2_for(std::max(p.lx, p.ly));
    return p;
  }
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

// What the predictors read of a state: replay's Particles<T> through these (references into it, so replay's
// code is what it was), the log writer's CoderState<T> (log/coder_state.hpp: x, y, vx, vy, t per disk)
// through its own overloads, found by argument-dependent lookup when a predictor is instantiated.
template <class T>
[[gnu::always_inline]] inline const Disk<T>& record_of(const Particles<T>& p, std::size_t i) {
  return p.disk[i];
}
template <class T>
[[gnu::always_inline]] inline T mass_of(const Particles<T>& p, std::size_t i) {
  return p.mass(i);
}
template <class T>
[[gnu::always_inline]] inline std::int32_t species_of(const Particles<T>& p, std::size_t i) {
  return p.species_of(i);
}

// Post-collision velocities of pair (i, j) at time t, as Engine::resolve_pair computes them: both records
// brought to t, the separation with the nearest periodic image, the collision rule with 1 + xi of the
// pair (2 when the TC model made it elastic). `a` and `b` are the records of i and j already brought to t
// (advance_disk): replay keeps them and stores them with the new velocities instead of advancing twice.
// Rough runs (p.omega not empty): the tangential part too (Engine::resolve_pair: after the normal rule, from
// the velocities and spins before the collision, skipped when the TC model made it elastic), and the
// spins after it in w[0], w[1] when w is given.
template <class T, class S>
inline void predict_pair_velocities(const EventPhysics<T>& ph, const S& p, std::int32_t i, std::int32_t j,
                                    const Disk<T>& a, const Disk<T>& b, bool tc_elastic, T v[4], T* w = nullptr) {
  T dx = b.x - a.x, dy = b.y - a.y;
  if (ph.periodic) {
    if (dx > ph.half_lx) dx -= ph.lx; else if (dx < -ph.half_lx) dx += ph.lx;
    if (dy > ph.half_ly) dy -= ph.ly; else if (dy < -ph.half_ly) dy += ph.ly;
  }
  const T opx = tc_elastic ? T(2) : ph.pair_one_plus_xi(species_of(p, std::size_t(i)), species_of(p, std::size_t(j)));
  v[0] = a.vx, v[1] = a.vy, v[2] = b.vx, v[3] = b.vy;
  collide_pair(dx, dy, mass_of(p, std::size_t(i)), mass_of(p, std::size_t(j)), opx, v[0], v[1], v[2], v[3]);
  if (p.omega.empty()) return;
  const std::size_t si = std::size_t(i), sj = std::size_t(j);
  T wi = p.omega[si], wj = p.omega[sj];
  const T opb = tc_elastic ? T(0) : ph.pair_one_plus_beta(species_of(p, si), species_of(p, sj));
  collide_pair_tangential(dx, dy, b.vx - a.vx, b.vy - a.vy, mass_of(p, si), mass_of(p, sj), a.r, b.r, p.inertia[si],
                          p.inertia[sj], opb, v[0], v[1], v[2], v[3], wi, wj);
  if (w) w[0] = wi, w[1] = wj;
}

template <class T, class S>
inline void predict_pair_velocities(const EventPhysics<T>& ph, const S& p, std::int32_t i, std::int32_t j, T t,
                                    bool tc_elastic, T v[4], T* w = nullptr) {
  Disk<T> a = record_of(p, std::size_t(i)), b = record_of(p, std::size_t(j));
  advance_disk(a, t, ph.gx, ph.gy);
  advance_disk(b, t, ph.gx, ph.gy);
  predict_pair_velocities(ph, p, i, j, a, b, tc_elastic, v, w);
}

// Velocity after disk i hits `wall` at time t (Engine::resolve_wall). With xi_w = 1 collide_wall computes
// exactly what collide_wall_elastic does (a multiplication by 1 and a negation are exact).
// Rough runs: then the wall's tangential part (not when TC-elastic), the spin after it in *w if given.
template <class T, class S>
inline void predict_wall_velocity(const EventPhysics<T>& ph, const S& p, std::int32_t i, std::int32_t wall, T t,
                                  bool tc_elastic, T v[2], T* w = nullptr) {
  v[0] = p.vx_at(std::size_t(i), t), v[1] = p.vy_at(std::size_t(i), t);
  const T vx0 = v[0], vy0 = v[1];
  const bool vertical = wall == kWallLeft || wall == kWallRight;
  if (tc_elastic)
    collide_wall_elastic(vertical, v[0], v[1]);
  else
    collide_wall(vertical, ph.xi_wall[wall & 3], v[0], v[1]);
  if (p.omega.empty()) return;
  static constexpr int kNormal[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};  // Engine::kWallNormal
  const std::size_t si = std::size_t(i);
  T wi = p.omega[si];
  collide_wall_tangential(T(kNormal[wall & 3][0]), T(kNormal[wall & 3][1]), vx0, vy0, mass_of(p, si), record_of(p, si).r,
                          p.inertia[si], tc_elastic ? T(0) : ph.wall_one_plus_beta, v[0], v[1], wi);
  if (w) *w = wi;
}

// Velocity after disk i hits segment s at time t (Engine::resolve_segment): a copy of the record brought
// to t, then the segment's rule with its 1 + xi (2 with the TC flag).
template <class T, class S>
inline void predict_segment_velocity(const EventPhysics<T>& ph, const S& p, std::int32_t i, std::int32_t s, T t,
                                     bool tc_elastic, T v[2]) {
  Disk<T> d = record_of(p, std::size_t(i));
  advance_disk(d, t, ph.gx, ph.gy);
  v[0] = d.vx, v[1] = d.vy;
  if (s < 0 || std::size_t(s) >= ph.segments.size()) return;  // a version 1 log's header lists no segments
  const Segment<T>& g = ph.segments[std::size_t(s)];
  collide_segment(g, d.x, d.y, tc_elastic ? T(2) : g.one_plus_xi, v[0], v[1]);
}

// Time disk i hits segment s, from its record alone (Engine::scan_segments without the clamp to now).
template <class T>
inline T predict_segment_time(const EventPhysics<T>& ph, const Disk<T>& d, std::int32_t s) {
  if (s < 0 || std::size_t(s) >= ph.segments.size()) return kNever<T>;
  const T dt = segment_contact_time(ph.segments[std::size_t(s)], d.x, d.y, d.vx, d.vy, d.r, ph.b_noise2);
  return dt == kNever<T> ? kNever<T> : d.t + dt;
}

// Time of pair (i, j): predicted by the disk whose record is later (i on a tie), at now = that record's
// time, against the partner's image nearest at now (Engine::pair_time; predict_pair without gravity).
// kGravity = false is for callers that know the header has no gravity (gx = gy = 0): the same bits, with
// the gravity branches compiled out (replay's decoder; position_along with g = 0 is drift exactly).
template <class T, bool kGravity = true, class S>
[[gnu::always_inline]] inline T predict_pair_time(const EventPhysics<T>& ph, const S& p, std::int32_t i,
                                                  std::int32_t j) {
  // References (to the records, or to the writer's materialised copies: lifetime extended).
  const Disk<T>& ri = record_of(p, std::size_t(i));
  const Disk<T>& rj = record_of(p, std::size_t(j));
  const Disk<T>* di = &ri;
  const Disk<T>* dj = &rj;
  if (dj->t > di->t) std::swap(di, dj);
  const T now = di->t;
  const T gx = kGravity ? ph.gx : T(0), gy = kGravity ? ph.gy : T(0);
  const T pix = position_along(di->x, di->vx, gx, di->t, now), piy = position_along(di->y, di->vy, gy, di->t, now);
  const T pjx = position_along(dj->x, dj->vx, gx, dj->t, now), pjy = position_along(dj->y, dj->vy, gy, dj->t, now);
  T sx = 0, sy = 0;
  if (ph.periodic) {
    const T ex = pjx - pix, ey = pjy - piy;
    sx = ex > ph.half_lx ? -ph.lx : ex < -ph.half_lx ? ph.lx : T(0);
    sy = ey > ph.half_ly ? -ph.ly : ey < -ph.half_ly ? ph.ly : T(0);
  }
  if (gx == T(0) && gy == T(0))
    return predict_pair<StableContact>(*di, Position2<T>{pix, piy}, *dj, sx, sy, now, ph.b_noise2);
  const T vix = velocity_along(di->vx, gx, di->t, now), viy = velocity_along(di->vy, gy, di->t, now);
  const T vjx = velocity_along(dj->vx, gx, dj->t, now), vjy = velocity_along(dj->vy, gy, dj->t, now);
  return now + StableContact::time((pjx + sx) - pix, (pjy + sy) - piy, vjx - vix, vjy - viy, di->r + dj->r,
                                   ph.b_noise2);
}

// Time disk i hits `wall`, from its record alone (predict_wall; predict_wall_accelerated at now = the
// record's time).
template <class T>
inline T predict_wall_time(const EventPhysics<T>& ph, const Disk<T>& d, std::int32_t wall) {
  if (ph.gx == T(0) && ph.gy == T(0)) {
    switch (wall) {
      case kWallRight: return d.vx > 0 ? d.t + time_to_reach(d.x, d.vx, ph.lx - d.r) : kNever<T>;
      case kWallLeft: return d.vx < 0 ? d.t + time_to_reach(d.x, d.vx, d.r) : kNever<T>;
      case kWallTop: return d.vy > 0 ? d.t + time_to_reach(d.y, d.vy, ph.ly - d.r) : kNever<T>;
      case kWallBottom: return d.vy < 0 ? d.t + time_to_reach(d.y, d.vy, d.r) : kNever<T>;
      default: return kNever<T>;
    }
  }
  T dt = kNever<T>;
  switch (wall) {
    case kWallLeft: dt = time_to_reach_accelerated(d.x - d.r, d.vx, ph.gx, T(0)); break;
    case kWallRight: dt = time_to_reach_accelerated((ph.lx - d.r) - d.x, -d.vx, -ph.gx, T(0)); break;
    case kWallBottom: dt = time_to_reach_accelerated(d.y - d.r, d.vy, ph.gy, T(0)); break;
    case kWallTop: dt = time_to_reach_accelerated((ph.ly - d.r) - d.y, -d.vy, -ph.gy, T(0)); break;
    default: break;
  }
  return dt == kNever<T> ? kNever<T> : d.t + dt;
}

// Time disk i crosses the periodic edge `dir` (predict_crossing against the grid's outer sides, which are
// exactly 0 and the box length).
template <class T>
inline T predict_wrap_time(const EventPhysics<T>& ph, const Disk<T>& d, std::int32_t dir) {
  switch (dir) {
    case kWrapRight: return d.vx > 0 ? d.t + time_to_reach(d.x, d.vx, ph.lx) : kNever<T>;
    case kWrapLeft: return d.vx < 0 ? d.t + time_to_reach(d.x, d.vx, T(0)) : kNever<T>;
    case kWrapTop: return d.vy > 0 ? d.t + time_to_reach(d.y, d.vy, ph.ly) : kNever<T>;
    case kWrapBottom: return d.vy < 0 ? d.t + time_to_reach(d.y, d.vy, T(0)) : kNever<T>;
    default: return kNever<T>;
  }
}

}  // namespace ede
