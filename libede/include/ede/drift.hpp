// The one drift function: where a disk is at time t, given its state (x, v) recorded at time t0.
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

}  // namespace ede
