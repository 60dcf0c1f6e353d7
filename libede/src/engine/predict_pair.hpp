// Predicting a pair collision from the two disks' lazy states.
//
// Both disks are brought to the common time `now` with the shared drift function, then the pure contact
// time of geometry.hpp applies. `shift_x/_y` place disk j's periodic image (0 in a walled box).
#pragma once

#include "core/drift.hpp"
#include "core/geometry.hpp"
#include "core/particles.hpp"
#include "engine/effects.hpp"

namespace ede {

template <class T>
struct Position2 {
  T x, y;
};

template <class T>
inline Position2<T> position_at(const Disk<T>& d, T t) {
  return {drift(d.x, d.vx, d.t, t), drift(d.y, d.vy, d.t, t)};
}

// Absolute time at which disks i (at pi, now) and j touch, or kNever, by Contact's root (effects.hpp).
// b_noise2: see geometry.hpp.
template <class Contact = StableContact, class T>
inline T predict_pair(const Disk<T>& di, Position2<T> pi, const Disk<T>& dj, T shift_x, T shift_y, T now,
                      T b_noise2) {
  const Position2<T> pj = position_at(dj, now);
  const T dt = Contact::time((pj.x + shift_x) - pi.x, (pj.y + shift_y) - pi.y, dj.vx - di.vx, dj.vy - di.vy,
                             di.r + dj.r, b_noise2);
  return now + dt;
}

}  // namespace ede
