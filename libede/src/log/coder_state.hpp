// CoderState<T>: the state the log writer's coder predicts from (format version 2), in 40 bytes a disk.
//
// The coder needs, per disk, what replay's state has before each event: the position, velocity and time
// of its record (x, y, vx, vy, t), which every event changes, and the radius, mass and species, which no
// event changes and which a scene usually gives every disk alike: those are kept once when all disks have
// the same value, else per disk; spins and moments of inertia only in rough runs. The predictors and
// apply_event are the ones replay runs (log/event_predictions.hpp, log/chunk_codec.hpp), templated on the
// state: they read a disk through record_of, which here materialises a Disk<T> (the engine's functions take
// one), and change one through writable_record, a copy written back when it goes out of scope.
// Rejected: a copy of the engine's Particles<T> (a 64-byte record, mass and species per disk: 76 B/disk
// at the peak of a run at N = 10^6, docs/performance.md "Memory at 10⁶ with the log") and a second,
// hand-written apply for the writer (two copies of the rules replay's bytes depend on).
#pragma once

#include <cstdint>
#include <vector>

#include "core/drift.hpp"
#include "core/particles.hpp"

namespace ede {

template <class T>
struct CoderState {
  struct Motion {
    T x, y, vx, vy, t;
  };
  std::vector<Motion> motion;
  // One value when every disk has the same, else one per disk.
  std::vector<T> radius, mass;
  std::vector<std::int32_t> species;
  std::vector<T> omega, inertia;  // rough runs only (else empty), per disk
  T gx{}, gy{};

  std::size_t size() const { return motion.size(); }
  bool empty() const { return motion.empty(); }

  // The state of `p` (its records, masses, species, spins and moments of inertia; not its TC times).
  void assign(const Particles<T>& p) {
    motion.clear();
    motion.shrink_to_fit();
    motion.reserve(p.size());
    for (const Disk<T>& d : p.disk) motion.push_back({d.x, d.y, d.vx, d.vy, d.t});
    radius.clear();
    for (const Disk<T>& d : p.disk) radius.push_back(d.r);
    once_if_uniform(radius);
    mass = p.masses;  // one value when uniform, as set_masses and set_species keep them
    species = p.species_ids;
    omega = p.omega;
    inertia = p.inertia;
    gx = p.gx, gy = p.gy;
  }

  Disk<T> record(std::size_t i) const {
    Disk<T> d{};
    const Motion& m = motion[i];
    d.x = m.x, d.y = m.y, d.vx = m.vx, d.vy = m.vy, d.t = m.t;
    d.r = radius.size() == 1 ? radius[0] : radius[i];
    return d;
  }
  void store(std::size_t i, const Disk<T>& d) { motion[i] = {d.x, d.y, d.vx, d.vy, d.t}; }
  T mass_of(std::size_t i) const { return mass.size() == 1 ? mass[0] : mass[i]; }
  std::int32_t species_of(std::size_t i) const { return species.size() == 1 ? species[0] : species[i]; }
  // As Particles<T>::vx_at, vy_at.
  T vx_at(std::size_t i, T t) const { return velocity_along(motion[i].vx, gx, motion[i].t, t); }
  T vy_at(std::size_t i, T t) const { return velocity_along(motion[i].vy, gy, motion[i].t, t); }
};

// The accessors the predictors and apply_event use (event_predictions.hpp, chunk_codec.hpp).
template <class T>
inline Disk<T> record_of(const CoderState<T>& s, std::size_t i) {
  return s.record(i);
}
template <class T>
inline T mass_of(const CoderState<T>& s, std::size_t i) {
  return s.mass_of(i);
}
template <class T>
inline std::int32_t species_of(const CoderState<T>& s, std::size_t i) {
  return s.species_of(i);
}

// A disk's record to change, written back into the state when it goes out of scope.
template <class T>
class CoderRecord {
 public:
  CoderRecord(CoderState<T>& s, std::size_t i) : state_(s), i_(i), disk_(s.record(i)) {}
  ~CoderRecord() { state_.store(i_, disk_); }
  CoderRecord(const CoderRecord&) = delete;
  CoderRecord& operator=(const CoderRecord&) = delete;
  operator Disk<T>&() { return disk_; }

 private:
  CoderState<T>& state_;
  std::size_t i_;
  Disk<T> disk_;
};

template <class T>
inline CoderRecord<T> writable_record(CoderState<T>& s, std::size_t i) {
  return CoderRecord<T>(s, i);  // guaranteed copy elision: never copied
}

}  // namespace ede
