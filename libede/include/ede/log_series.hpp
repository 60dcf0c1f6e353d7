// Log series: observables of a run on a time grid, and snapshots at given times, from its event log.
//
// log_series walks the events once, in order, keeping a mirror of the state just before the event at hand:
// the kinetic energy of every disk, computed from its velocity (events carry only the velocities after
// them). An event replaces its disks' energies in running sums (long double), so the total and per-species energies on a grid of any fineness cost
// O(events + grid points), not one replay per point. The value at a grid time t is that of the state
// after every event with time <= t, as Replay::seek_time(t) defines it, so it equals the sum over the
// replayed state at t up to the rounding of the running sums. Pair and wall collisions are counted on
// the same walk. An action (reversing every velocity) resynchronises the mirror from the replayed state.
// for_each_snapshot gives the velocities at a few times through Replay::seek_time, forward only: each
// seek continues from the last, or jumps to a later keyframe when that is cheaper.
// Rejected: one seek_time per grid point for the energy series: O(points x (keyframe + events since it)),
// hundreds of times slower on the fine grids the energy curves need.
// Times are doubles; in a float or long double log a grid time means that value converted to the log's
// type (exact for long double, rounded for float).
// (One part of ede/analysis.hpp, which includes them all.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/gas_observables.hpp"
#include "ede/log.hpp"

namespace ede {

// What a log says without replaying it: its size, its end and its collision counts (from the kinds column).
struct LogOverview {
  std::size_t disks = 0;
  double end_time = 0;  // the time the run reached, rounded down to a double (so it is within the log)
  std::uint64_t pair_events = 0, wall_events = 0;
  // The mean time between two pair collisions of one disk over the whole run: N t_end / (2 pairs);
  // infinity without pair collisions.
  double mean_free_time() const {
    return pair_events ? double(disks) * end_time / (2.0 * double(pair_events)) : std::numeric_limits<double>::infinity();
  }
};
Result<LogOverview> log_overview(const Log& log);

// t0, t0 + dt, t0 + 2 dt, ... (each computed as t0 + k dt, so no error accumulates), none above t1; empty
// if t1 < t0, dt <= 0, or the grid would have more than max_points points.
std::vector<double> time_grid(double t0, double t1, double dt, std::size_t max_points = 10'000'000);
// The same grid with t1 itself appended when the grid stops short of it (both ends included); empty when
// time_grid is.
std::vector<double> time_grid_to(double t0, double t1, double dt, std::size_t max_points = 10'000'000);

struct LogSeries {
  std::vector<double> time;
  std::vector<std::string> species_names;
  std::vector<std::uint64_t> species_count;            // disks per species
  std::vector<double> kinetic_energy;                  // total, at each time
  std::vector<std::vector<double>> species_energy;     // [species][k]: total kinetic energy of the species
  std::vector<std::uint64_t> pair_collisions;          // pair events with time <= t (cumulative)
  std::vector<std::uint64_t> wall_collisions;          // wall events with time <= t (cumulative)
  std::vector<double> potential_energy;                // a stepped potential's (format version 3), else empty

  std::uint64_t disks() const;
  double collisions_per_particle(std::size_t k) const;  // 2 pair_collisions / N
  double mean_kinetic_energy(std::size_t k) const;      // per disk
  double species_mean_energy(std::size_t s, std::size_t k) const;
};

// The series at the given times (non-decreasing, within [0, end of the log]).
Result<LogSeries> log_series(const Log& log, const std::vector<double>& times);

// The state's velocities at each of the given times (non-decreasing, within the log), one snapshot at a
// time; the snapshot passed to f is reused between calls.
Status for_each_snapshot(const Log& log, const std::vector<double>& times,
                         const std::function<void(const GasSnapshot&)>& f);

}  // namespace ede
