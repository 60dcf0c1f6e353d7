// --dry-run: how many runs a sweep makes and about how long and how much disk they take, from short pilot
// runs of its first and last run (the corners of the parameter space) in this process, each for at most
// a second or so of wall time, logs in a temporary folder that is removed. A pilot's share of its run is
// the furthest of its stop conditions it has come towards (time, events, collisions per particle); a
// stop on energy cannot be extrapolated, so such a run's estimate is an upper bound (its other stops).
// Rejected: running a whole run as the pilot (a sweep's point is to have long runs).
#pragma once

#include <string>

#include "sweep.hpp"

namespace ede::sweep {

// The report, for stdout; a bad point among the pilots is reported in it, not an error.
std::string dry_run_report(const Sweep& s, std::size_t jobs, double pilot_seconds);

}  // namespace ede::sweep
