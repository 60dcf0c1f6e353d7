// A time-stepped hard-disk simulation: the baseline the event-driven engine is measured against in the
// accuracy study (ede-bench accuracy), never a way to get results.
//
// Every step moves every disk by v dt, then finds the pairs that overlap (cell list, O(N) per step) and the
// disks that cross a wall, and resolves them: an overlapping pair that is approaching gets the engine's own
// collision rule along the line of centres as it is found (overlapping), and is pushed apart to contact;
// a disk past a wall and moving outwards gets the wall rule and is put back inside. This is how a
// time-stepped code "sees" hard collisions: late (up to one step), along the wrong normal, and not at all
// when two disks pass through each other within one step. The study shows what that costs against the
// event-driven engine at equal CPU time: collision rate, energy (for xi < 1, the cooling curve), overlaps.
//
// Deterministic: the same state and options give the same result bit for bit (pairs are resolved in a
// fixed order, no randomness, no threads).
#pragma once

#include <cstdint>
#include <vector>

#include "ede/internal/engine.hpp"
#include "ede/error.hpp"
#include "ede/scene.hpp"

namespace ede {

struct TimeSteppedOptions {
  double dt = 1e-3;
  BoundaryKind boundary = BoundaryKind::Walls;
  double restitution = 1.0;       // pairs
  double wall_restitution = 1.0;  // walls (ignored in a periodic box)
};

struct TimeSteppedCounts {
  std::uint64_t steps = 0;
  std::uint64_t pair_collisions = 0;  // overlapping, approaching pairs resolved
  std::uint64_t wall_collisions = 0;  // disks reflected at a wall
};

class TimeStepped {
 public:
  // Refuses (with a message) a non-positive or non-finite dt, an empty state, or disks larger than a
  // third of the box in a periodic box.
  static Result<TimeStepped> create(const InitialState& initial, const TimeSteppedOptions& options);

  // Steps of dt while they fit before t, then one shorter step to land on t exactly (nothing when
  // t <= time() or t is not finite).
  void run_until(double t);

  double time() const { return time_; }
  const TimeSteppedCounts& counts() const { return counts_; }
  double kinetic_energy() const;  // summed in long double
  // The largest overlap found before resolution since the start, as a fraction of the contact distance.
  double largest_overlap() const { return largest_overlap_; }

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& vx() const { return vx_; }
  const std::vector<double>& vy() const { return vy_; }

 private:
  TimeStepped() = default;
  void step(double dt);
  void move(double dt);
  void resolve_walls();
  void wrap_all();
  void build_cells();
  void resolve_pairs();
  void resolve_overlap(std::size_t i, std::size_t j, double dx, double dy);

  TimeSteppedOptions options_;
  double lx_ = 1, ly_ = 1, time_ = 0, largest_overlap_ = 0;
  // time_ = anchor_time_ + whole_steps_ * dt: whole steps are counted, not summed, so run_until(1) with
  // dt = 1e-3 takes 1000 steps and no sliver step made of the sum's round-off.
  double anchor_time_ = 0;
  std::uint64_t whole_steps_ = 0;
  std::vector<double> x_, y_, vx_, vy_, r_, m_;
  TimeSteppedCounts counts_;
  // Cell list, rebuilt every step: cell sizes at least one largest diameter.
  std::int32_t nx_ = 1, ny_ = 1;
  double cell_ix_ = 1, cell_iy_ = 1;  // cells per unit length
  std::vector<std::int32_t> cell_head_, next_in_cell_, cell_x_, cell_y_;
};

}  // namespace ede
