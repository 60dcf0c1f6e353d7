// The format's state update (schema/FORMAT.md, "Rebuilding the state"), frozen with format versions 1 and 2:
// how replay brings a disk's record to a time, wraps it across a periodic edge and reverses it.
//
// A log stores velocities and times, never positions: a replayed position is the record's position
// carried forward by exactly these expressions, in this order, in the run's scalar type, without fused
// multiply-add. They are the format's, not the engine's: the engine has its own (core/drift.hpp,
// core/state_update.hpp) and tests/log/test_format_rules.cpp proves the two give the same bits, because a
// log is exact only while the engine moves disks exactly as its format says. A change here is a new
// format version (the old one's functions stay, for its logs).
// Self-contained on purpose: the files of log/rules/ include the standard library and each other only, so
// nothing the engine or core does can change what an old log decodes to.
// Rejected: calling core's functions (a change made there for the engine's sake would silently change
// every existing log's decoded states).
#pragma once

#include <cstdint>

namespace ede::rules {

// Wall ids and wrap directions as the format numbers them (the partners column).
inline constexpr std::int32_t kLeft = 0, kRight = 1, kBottom = 2, kTop = 3;
inline constexpr std::int32_t kWrapRight = 0, kWrapLeft = 1, kWrapTop = 2, kWrapBottom = 3;

// x + v (t - t0), rounded in that order.
template <class T>
inline T drift(T x, T v, T t0, T t) {
  return x + v * (t - t0);
}

// Under a constant acceleration g along the axis: x + v dt + g dt dt / 2 and v + g dt; drift exactly when
// g is zero.
template <class T>
inline T position_along(T x, T v, T g, T t0, T t) {
  if (g == T(0)) return drift(x, v, t0, t);
  const T dt = t - t0;
  return x + v * dt + g * dt * dt / T(2);
}

template <class T>
inline T velocity_along(T v, T g, T t0, T t) {
  return g == T(0) ? v : v + g * (t - t0);
}

// "Bring a disk to t": any record with members x, y, vx, vy, t (replay's Disk<T>, the writer's copies).
template <class R, class T>
inline void bring_to(R& d, T t, T gx, T gy) {
  d.x = position_along(d.x, d.vx, gx, d.t, t);
  d.y = position_along(d.y, d.vy, gy, d.t, t);
  d.vx = velocity_along(d.vx, gx, d.t, t);
  d.vy = velocity_along(d.vy, gy, d.t, t);
  d.t = t;
}

// A wrap: brought to t (no gravity in a periodic box), then moved by one box length across the edge.
template <class R, class T>
inline void wrap(R& d, T t, std::int32_t dir, T lx, T ly) {
  bring_to(d, t, T(0), T(0));
  switch (dir) {
    case kWrapRight: d.x = d.x - lx; break;
    case kWrapLeft: d.x = d.x + lx; break;
    case kWrapTop: d.y = d.y - ly; break;
    case kWrapBottom: d.y = d.y + ly; break;
    default: break;
  }
}

// The time-reversal action on one disk: brought to t, velocity negated.
template <class R, class T>
inline void reverse(R& d, T t, T gx, T gy) {
  bring_to(d, t, gx, gy);
  d.vx = -d.vx;
  d.vy = -d.vy;
}

}  // namespace ede::rules
