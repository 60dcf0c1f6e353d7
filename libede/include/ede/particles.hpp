// Particles<T>: the engine's state, readable by sinks (log writer, observers) without copying.
//
// The hot fields (x, y, vx, vy, t and the radius) sit together in one record per disk: every prediction
// reads all six of a neighbour picked by space, not by index, so one cache line per disk beats six (one
// per column) at large N. Cold data (mass, species) and bookkeeping sit in their own arrays. This departs
// from DESIGN.md's "structure of arrays" for the hot part; see docs/performance.md.
// A disk's position at time t is drift(x, vx, t_last, t): state is lazy, untouched disks cost nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "ede/drift.hpp"

namespace ede {

template <class T>
struct Disk {
  T x, y;    // position at time t
  T vx, vy;  // velocity since time t
  T t;       // time of the last change of this record
  T r;       // radius
};

template <class T>
struct Particles {
  std::vector<Disk<T>> disk;
  std::vector<T> mass;
  std::vector<std::int32_t> species;
  std::vector<std::uint32_t> counter;  // velocity changes so far; invalidates stale predictions
  std::vector<T> last_collision;       // TC model only (else empty): time of each disk's last collision
  // The disk each one last collided with while its velocity has not changed since (else -1). A pair that
  // are each other's last partner cannot collide again in the same image; see Engine::just_collided.
  std::vector<std::int32_t> last_partner;

  std::size_t size() const { return disk.size(); }
  T x_at(std::size_t i, T t) const { return drift(disk[i].x, disk[i].vx, disk[i].t, t); }
  T y_at(std::size_t i, T t) const { return drift(disk[i].y, disk[i].vy, disk[i].t, t); }
};

}  // namespace ede
