// What a picture or a live view of one state needs, in double: positions (wrapped into a periodic box),
// radii, speeds, the displacement from an initial state, the species; and what stands out: the GasLab
// speed classes against the initial mean speed, the marked disks (a projectile), the top of a displacement
// colour scale. The colours are the front end's. Rejected: a frame per scalar type (the drawing code
// would exist three times) and the front ends computing these from a State each in their own way.
// (One part of ede/analysis.hpp, which includes them all.)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/events.hpp"
#include "ede/gas_observables.hpp"
#include "ede/scene.hpp"
#include "ede/state.hpp"

namespace ede {

struct DiskFrame {
  Time time = 0;
  double lx = 1, ly = 1;
  bool periodic = false;
  std::vector<std::string> species_names;  // the log's, all of them
  std::vector<double> x, y, r, speed;
  std::vector<double> displacement;        // from the initial state (periodic: the nearest image's)
  std::vector<std::int32_t> species;
  double initial_mean_speed = 0;           // the mean speed of these disks in the initial state
  // Wall segments (ax, ay, bx, by) to draw; disk_frame leaves it empty (a State carries none), a reader
  // of a log fills it from the log's scene (ede-render does).
  std::vector<std::array<double, 4>> segments;

  std::size_t size() const { return x.size(); }
};

// The disks of `state` (one species, or all) with their displacements from `initial`, the same run at an
// earlier time (usually its start).
DiskFrame disk_frame(const State& state, const State& initial, std::int32_t species = kAllSpecies);

enum class SpeedClass { Slow, Medium, Fast };
// Slow below 0.5 v_ref, fast above 1.5 v_ref, medium in between (as speed_classes counts).
SpeedClass speed_class(double speed, double reference_speed);

// The disks of the named species; with no names, those of every species that has exactly one disk in the
// frame (a projectile), unless every species has one disk. Fails naming the species for an unknown name.
Result<std::vector<bool>> marked_disks(const DiskFrame& frame, const std::vector<std::string>& species_names);
// The top of a displacement colour scale: the 95th percentile of the unmarked disks' displacements (a
// projectile and a few ejecta would leave the rest pale), or the mean radius if they have not moved.
double displacement_scale(const DiskFrame& frame, const std::vector<bool>& marked);

// Times from t0 to t1 for frames, each a value of the scalar type within [t0, t1] (t0 and t1 are): `count`
// evenly spaced, both ends included (one: t0); or t0 + k every (each computed from k, not accumulated) up
// to t1. Empty if t1 < t0, count is 0, every <= 0, or there would be more than max_count.
std::vector<Time> evenly_spaced_times(Time t0, Time t1, std::size_t count, ScalarKind scalar);
std::vector<Time> times_every(Time t0, Time t1, Time every, ScalarKind scalar, std::size_t max_count);

}  // namespace ede
