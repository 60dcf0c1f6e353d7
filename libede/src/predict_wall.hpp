// Predicting a disk's next wall hit in the box [0, lx] x [0, ly] (walls boundary only).
//
// Computed from the stored state (x at time d.t), not from a drifted position: one rounding fewer, and the
// answer does not depend on when the prediction is made. A disk already touching or past a wall while
// moving into it (round-off) hits it now; at a corner both walls are hit at the same time, one after the
// other, vertical first (the candidate order).
#pragma once

#include "candidate.hpp"
#include "ede/event.hpp"
#include "ede/particles.hpp"
#include "geometry.hpp"

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

}  // namespace ede
