// The routes for live runs: the example scenes and their key parameters, SETUP (POST /api/run/setup with
// the scene and its overrides as JSON), GO, PAUSE, REVERSE, the pace, the status and the latest frame.
#pragma once

#include <httplib.h>
#include <vector>

#include "http_util.hpp"
#include "live_runs.hpp"

namespace ede::view {

void add_live_routes(httplib::Server& server, const std::vector<Root>& scene_roots, LiveRuns& runs,
                     FrameBudget& budget);

}  // namespace ede::view
