// The one drift function: where a disk is at time t, given its state (x, v) recorded at time t0 (and, with
// gravity, its velocity then).
//
// The engine and replay both compute positions only through this function, compiled with contraction
// off, so a replayed position is bit-identical to the engine's: x + v * (t - t0), rounded in that order.
// Rejected: storing positions after every event (4x the log size) or letting each caller inline its own
// formula (one a*b+c contracted to an fma in one place and not another breaks bit-exactness).
#pragma once

namespace ede {

template <class T>
inline T drift(T x, T v, T t0, T t) {
  return x + v * (t - t0);
}

// Under a constant acceleration g along the axis (gravity), in this one order of operations:
// x + v dt + g dt dt / 2 and v + g dt. Along an axis without acceleration they are drift() and v exactly,
// so a scene without gravity computes the same bits whichever function a caller uses.
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

}  // namespace ede
