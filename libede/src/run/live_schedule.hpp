// A live run's scene (ede/live_run.hpp): the overrides that make a scene a live run, and reversals of
// time as reverse_velocities actions joined to the scene's own schedule, by time or by collisions per
// disk. Pure functions of the scene and the presses, so they are tested without a worker thread.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/live_run.hpp"
#include "ede/scene.hpp"

namespace ede {

// stop.time at `until`, the other stop conditions lifted far away, small log chunks unless the scene sets them.
std::vector<Override> live_overrides(const Scene& base, const LiveRunSetup& setup);

// The scene's actions are scheduled by collisions per disk (the loader refuses a mix with time actions).
bool actions_by_collisions(const Scene& scene);

// The collisions per disk c whose action fires right after pair collision number `pairs` of a run of n
// disks (the engine fires it at the first P >= ceil(c n / 2), computed in double).
double collisions_per_disk_for(std::uint64_t pairs, std::size_t n);

// actions = the scene's own plus the reversals asked for, in one schedule: by time (a reversal at each
// time in `times`) when the scene's actions are by time or it has none, else by collisions per disk (a
// reversal right after each pair collision number in `pairs`, of a run of n disks).
Override actions_override(const Scene& scene, const std::vector<double>& times, const std::vector<std::uint64_t>& pairs,
                          std::size_t n);

// Why a reversal cannot be scheduled now, or "": an action needs a time > 0, or, in a scene whose actions
// are by collisions per disk, a pair collision to follow.
std::string cannot_reverse(const Scene& scene, double time, std::uint64_t pairs);

}  // namespace ede
