// The wall room: a disk hitting one of the box's four walls. Its prediction (predict_wall.hpp) is from the
// disk's record alone, straight lines or parabolas; its resolution applies the wall's rule (collide.hpp:
// the course's rule with the wall's restitution, the TC model, the rough rule where the engine has them).
#pragma once

#include <cstdint>

#include "engine/collide.hpp"
#include "engine/engine_state.hpp"
#include "engine/predict_wall.hpp"

namespace ede {

// Disk d's earliest wall hit at now (none in a periodic box).
template <class S, class T = typename S::Scalar>
Candidate<T> wall_candidate(const S& s, const Disk<T>& d) {
  if constexpr (S::Effects::kGravity)
    return predict_wall_accelerated(d, s.lx, s.ly, s.field.gx, s.field.gy, s.now);
  else if constexpr (!S::Effects::kPeriodic)
    return predict_wall(d, s.lx, s.ly, s.now);
  else
    return Candidate<T>{};
}

template <class S>
void resolve_wall(S& s, std::int32_t i, std::int32_t wall) {
  using T = typename S::Scalar;
  using Fx = typename S::Effects;
  // The outward normal of each box wall (from a disk to the wall), by WallId.
  static constexpr T kWallNormal[4][2] = {{T(-1), T(0)}, {T(1), T(0)}, {T(0), T(-1)}, {T(0), T(1)}};
  const RecordBefore<T> before = record_before(s.p.disk[i]);
  T wi0 = 0;
  if constexpr (Fx::kRough) wi0 = s.p.omega[i];
  s.advance(i);
  Disk<T>& d = s.p.disk[i];
  const T vx0 = d.vx, vy0 = d.vy;
  const bool vertical = wall == kWallLeft || wall == kWallRight;
  const bool by_tc = s.tc_elastic(i, -1);
  if constexpr (Fx::kDissipative) {
    auto& r = s.dissipation;
    const double ke_before = s.disk_energy(i);
    if (by_tc)
      collide_wall_elastic(vertical, d.vx, d.vy);
    else
      collide_wall(vertical, r.xi_wall[wall], d.vx, d.vy);
    if constexpr (Fx::kRough)
      if (!by_tc)
        collide_wall_tangential(kWallNormal[wall][0], kWallNormal[wall][1], vx0, vy0, s.p.mass(i), d.r, s.p.inertia[i],
                                s.spin.wall_one_plus_beta, d.vx, d.vy, s.p.omega[i]);
    r.ke += s.disk_energy(i) - ke_before;
    if constexpr (!Fx::kGravity) r.note_if_too_slow(s.p, i);
    if (r.tc_model) s.p.last_collision[i] = s.now;
  } else {
    collide_wall_elastic(vertical, d.vx, d.vy);
  }
  ++d.counter;
  d.last_partner = -1;
  ++s.counts.by_kind[int(EventKind::Wall)];
  if (by_tc) ++s.counts.tc_elastic;
  if (!s.sinks.empty()) {
    T wi = 0;
    if constexpr (Fx::kRough) wi = s.p.omega[i];
    s.emit({s.now, EventKind::Wall, by_tc, i, wall, d.vx, d.vy, T(0), T(0), vx0, vy0, T(0), T(0), wi, T(0), wi0, T(0),
            before, before, false, kRulesAreFormatV2});
  }
  predict_disk(s, i);
}

}  // namespace ede
