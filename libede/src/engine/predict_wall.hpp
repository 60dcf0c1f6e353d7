// Predicting a disk's next wall hit in the box [0, lx] x [0, ly] (walls boundary only).
//
// Computed from the stored state (x at time d.t), not from a drifted position: one rounding fewer, and the
// answer does not depend on when the prediction is made. A disk already touching or past a wall while
// moving into it (round-off) hits it now; at a corner both walls are hit at the same time, one after the
// other, vertical first (the candidate order).
#pragma once

#include "engine/candidate.hpp"
#include "core/event.hpp"
#include "core/particles.hpp"
#include "core/geometry.hpp"

namespace ede {

template <class T>
inline Candidate<T> predict_wall(const Disk<T>& d, T lx, T ly, T now) {
  Candidate<T> best;
  const auto consider = [&](T dt, WallId wall) {
    if (dt == kNever<T>) return;
    T t = d.t + dt;
    if (t < now) t = now;
    const Candidate<T> c{t, EventKind::Wall, wall};
    if (c.before(best)) best = c;
  };
  if (d.vx > 0) consider(time_to_reach(d.x, d.vx, lx - d.r), kWallRight);
  if (d.vx < 0) consider(time_to_reach(d.x, d.vx, d.r), kWallLeft);
  if (d.vy > 0) consider(time_to_reach(d.y, d.vy, ly - d.r), kWallTop);
  if (d.vy < 0) consider(time_to_reach(d.y, d.vy, d.r), kWallBottom);
  return best;
}

// The same under constant gravity (gx, gy): each wall's time from time_to_reach_accelerated, in terms of
// the distance to the wall (positive inside), its rate and its acceleration. A disk thrown towards the
// ceiling may turn back before it (no event); a disk resting on the floor hits it again at once, which is
// why gravity with inelastic walls needs the TC model or restitution above 0 (else the run stalls).
template <class T>
inline Candidate<T> predict_wall_accelerated(const Disk<T>& d, T lx, T ly, T gx, T gy, T now) {
  Candidate<T> best;
  const auto consider = [&](T s, T u, T a, WallId wall) {
    const T dt = time_to_reach_accelerated(s, u, a, now - d.t);
    if (dt == kNever<T>) return;
    T t = d.t + dt;
    if (t < now) t = now;
    const Candidate<T> c{t, EventKind::Wall, wall};
    if (c.before(best)) best = c;
  };
  consider(d.x - d.r, d.vx, gx, kWallLeft);
  consider((lx - d.r) - d.x, -d.vx, -gx, kWallRight);
  consider(d.y - d.r, d.vy, gy, kWallBottom);
  consider((ly - d.r) - d.y, -d.vy, -gy, kWallTop);
  return best;
}

}  // namespace ede
