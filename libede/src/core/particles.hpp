// Particles<T>: the engine's state, readable by sinks (log writer, observers) without copying.
//
// Everything a prediction reads of a neighbour sits in one 64-byte record per disk (double): position,
// velocity, time, radius, and the bookkeeping touched on the way (next disk in its cell, velocity-change
// counter, last partner, cell). At large N every neighbour is a cache miss, so one line per neighbour
// instead of four (one per column) is worth ~25% of the run time; see docs/performance.md. Cold data
// (mass, species, TC times) sits in its own arrays. This departs from DESIGN.md's "structure of arrays"
// for the hot part, on measurement.
// A disk's position at time t is drift(x, vx, t_last, t): state is lazy, untouched disks cost nothing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/drift.hpp"

namespace ede {

template <class T>
struct alignas(64) Disk {
  T x, y;    // position at time t
  T vx, vy;  // velocity since time t
  T t;       // time of the last change of this record
  T r;       // radius
  // Engine bookkeeping, read-only for everyone else:
  std::int32_t next_in_cell;  // next disk in the same cell's list, or -1
  std::uint32_t counter;      // velocity changes so far; a prediction naming a changed partner is stale
  // The disk this one last collided with while its velocity has not changed since (else -1). A pair that
  // are each other's last partner cannot collide again in the same image; see Engine::just_collided.
  std::int32_t last_partner;
  std::int32_t cell;  // the grid cell the disk is tracked in
};

// A value repeated for every entry kept once (masses, species, radii of a one-kind gas). The vector is
// rebuilt, not shrunk in place, so its memory goes. NaN is never uniform: kept per entry.
template <class V>
void once_if_uniform(std::vector<V>& v) {
  if (v.size() > 1 && std::all_of(v.begin() + 1, v.end(), [&](const V& x) { return x == v.front(); }))
    std::vector<V>{v.front()}.swap(v);
}

template <class T>
struct Particles {
  std::vector<Disk<T>> disk;
  // Masses and species: one value for all disks when they all have the same (set_masses, set_species), else
  // one per disk, so that a one-mass, one-species gas pays nothing per disk for them (12 B/disk in double:
  // issue 15's 120 B/disk). Read them through mass(i) and species_of(i).
  std::vector<T> masses;
  std::vector<std::int32_t> species_ids;
  std::vector<T> last_collision;  // TC model only (else empty): time of each disk's last collision
  // Rough engines only (else empty): angular velocity (counter-clockwise positive) and moment of inertia.
  // Cold like mass: read only at collisions, so they stay out of the 64-byte hot record.
  std::vector<T> omega, inertia;
  T gx{}, gy{};                   // the constant gravity the disks fall under between events (usually 0)

  std::size_t size() const { return disk.size(); }
  T mass(std::size_t i) const { return masses.size() == 1 ? masses[0] : masses[i]; }
  std::int32_t species_of(std::size_t i) const { return species_ids.size() == 1 ? species_ids[0] : species_ids[i]; }
  // Each keeps a single value when every disk has the same (and the whole vector otherwise).
  void set_masses(std::vector<T> m) {
    once_if_uniform(m);
    masses = std::move(m);
  }
  void set_species(std::vector<std::int32_t> s) {
    once_if_uniform(s);
    species_ids = std::move(s);
  }
  // One value per disk, whether stored once or per disk (for copies out: states, v1 logs).
  std::vector<T> mass_column() const { return column(masses); }
  std::vector<std::int32_t> species_column() const { return column(species_ids); }
  // Position and velocity of disk i at time t (>= its record's time), by the shared functions of drift.hpp.
  // Without gravity the velocity is the record's; with gravity, read it here, not from disk[i].vx.
  T x_at(std::size_t i, T t) const { return position_along(disk[i].x, disk[i].vx, gx, disk[i].t, t); }
  T y_at(std::size_t i, T t) const { return position_along(disk[i].y, disk[i].vy, gy, disk[i].t, t); }
  T vx_at(std::size_t i, T t) const { return velocity_along(disk[i].vx, gx, disk[i].t, t); }
  T vy_at(std::size_t i, T t) const { return velocity_along(disk[i].vy, gy, disk[i].t, t); }

 private:
  template <class V>
  std::vector<V> column(const std::vector<V>& v) const {
    return v.size() == 1 && size() != 1 ? std::vector<V>(size(), v[0]) : v;
  }
};

}  // namespace ede
