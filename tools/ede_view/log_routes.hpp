// The routes for logs: list the .ede files under --logs folders, a log's summary, and the frame at any
// time (Log::state_at: one keyframe plus the events since it, so any time of a long log is a seek, not a
// replay from the start).
#pragma once

#include <httplib.h>
#include <vector>

#include "http_util.hpp"

namespace ede::view {

void add_log_routes(httplib::Server& server, const std::vector<Root>& log_roots, FrameBudget& budget);

}  // namespace ede::view
