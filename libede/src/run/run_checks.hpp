// Checks before a run starts, for runs that are valid but could never finish or never give a number:
// refusals (Simulation::create fails with the reason and the fix) and warnings (scene_warnings, printed by
// the tools, which then go on).
//
// Refused: an initial state whose energy or momentum overflows a double (masses near 1e308: every later
// number would be infinite), or in a float run a float (3.4e38; also the sum of the two heaviest masses,
// which the collision rule divides by), and a sampling interval so small against stop.time that the samples alone
// could not be taken in a lifetime (more than 1e12); scales the run's scalar type cannot hold exactly
// (run/scale_checks.hpp, called from here after the overflow checks, whose messages come first). Warned: a sampling interval giving more than 1e9
// samples. The scene loader refuses what it can tell from the file alone (an energy stop with elastic
// collisions); a run whose length depends on the physics is estimated by the tool from a short pilot
// (docs/reliability.md). Rejected: refusing on a pilot's estimate (a slow start is not a slow run; a
// warning with the estimate and Ctrl-C, which keeps everything done, serve better).
#pragma once

#include <string>
#include <vector>

#include "core/initial_state.hpp"
#include "ede/error.hpp"
#include "ede/scene.hpp"

namespace ede {

Status check_run_can_finish(const Scene& scene, const InitialState& initial);

}  // namespace ede
