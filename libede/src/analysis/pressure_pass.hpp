// The replay pass behind measure_pressure: impulses and the kinetic-energy integral in fine time bins.
//
// One walk over the events of the window with a mirror of the velocities before each event; nothing is
// averaged here (pressure.cpp turns the sums into pressures, blocks and errors). Bins have equal length,
// so a block of bins is a plain sum and the block values' mean is the window's value.
// Rejected: computing per-block pressures during the walk: the blocking analysis needs the fine bins
// anyway, and sums keep the exact totals available for tests.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "log/log_reader.hpp"
#include "ede/error.hpp"

namespace ede {

struct PressureBins {
  long double t0 = 0, t1 = 0;                            // the window (t0, t1], in the log's scalar type
  std::vector<std::array<long double, 4>> wall_impulse;  // per bin, per wall: sum |dp_n|
  std::vector<long double> virial;                       // per bin: sum r_ij . dp_i
  std::vector<long double> kinetic;                      // per bin: integral of K dt
  std::vector<std::uint64_t> pairs, walls;               // per bin: collisions
  long double kinetic_start = 0, kinetic_end = 0;        // K at t0 and t1
  std::size_t size() const { return virial.size(); }
};

// What the pass needs to know of the disks before choosing a window: the log's end (rounded down to a
// double, so it lies within the log) and the radii.
struct LogDisks {
  std::size_t count = 0;
  double radius_sum = 0;  // sum r_i
  double disk_area = 0;   // sum pi r_i^2
  double end_time = 0;
};
Result<LogDisks> log_disks(const std::shared_ptr<const LogReader>& log);

// The window is (t0, t1] (events at t0 belong to the state at t0, as Replay::seek_time defines it); the
// caller has checked 0 <= t0 < t1 <= end of the log. K is the kinetic energy in the centre-of-mass frame
// for a periodic box, in the box's frame with walls.
Result<PressureBins> accumulate_pressure(const std::shared_ptr<const LogReader>& log, double t0, double t1,
                                         std::size_t bins);

}  // namespace ede
