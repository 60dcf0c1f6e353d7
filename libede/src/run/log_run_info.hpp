// What a log's header records of a run, from its scene and the engine options it runs with: where the
// scene (scene/), the engine's options (engine/) and the log writer (log/) meet, so it lives in run/ and the
// log needs nothing of the engine's.
#pragma once

#include <string>
#include <vector>

#include "ede/scene.hpp"
#include "engine/engine.hpp"
#include "log/log_writer.hpp"

namespace ede {

LogRunInfo log_run_info(const Scene& scene, const EngineOptions& options, const std::vector<std::string>& species);

}  // namespace ede
