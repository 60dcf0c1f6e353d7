// The state changes an event makes to a disk's record, shared by the engine and by replay.
//
// Replay rebuilds the exact state from a log by applying these same functions to the same inputs: the
// engine never moves a disk any other way, so a replayed record is bit-identical to the engine's. None of
// them is collision physics: the velocities come from the event (the engine's collision rules, or the log).
#pragma once

#include "core/drift.hpp"
#include "core/event.hpp"
#include "core/particles.hpp"

namespace ede {

// Brings a disk's record to time t (position by the shared drift function).
template <class T>
inline void advance_disk(Disk<T>& d, T t) {
  d.x = drift(d.x, d.vx, d.t, t);
  d.y = drift(d.y, d.vy, d.t, t);
  d.t = t;
}

// The same under constant gravity (gx, gy): position and velocity at t.
template <class T>
inline void advance_disk(Disk<T>& d, T t, T gx, T gy) {
  d.x = position_along(d.x, d.vx, gx, d.t, t);
  d.y = position_along(d.y, d.vy, gy, d.t, t);
  d.vx = velocity_along(d.vx, gx, d.t, t);
  d.vy = velocity_along(d.vy, gy, d.t, t);
  d.t = t;
}

// A periodic wrap: the record is brought to t, then moved by one box length across the crossed edge.
template <class T>
inline void wrap_disk(Disk<T>& d, T t, std::int32_t dir, T lx, T ly) {
  advance_disk(d, t);
  switch (dir) {
    case kWrapRight: d.x = d.x - lx; break;
    case kWrapLeft: d.x = d.x + lx; break;
    case kWrapTop: d.y = d.y - ly; break;
    case kWrapBottom: d.y = d.y + ly; break;
    default: break;
  }
}

// The time-reversal action on one disk.
template <class T>
inline void reverse_disk(Disk<T>& d, T t) {
  advance_disk(d, t);
  d.vx = -d.vx;
  d.vy = -d.vy;
}

template <class T>
inline void reverse_disk(Disk<T>& d, T t, T gx, T gy) {
  advance_disk(d, t, gx, gy);
  d.vx = -d.vx;
  d.vy = -d.vy;
}

}  // namespace ede
