// [start]: reading the table that makes a scene start from a state (ede/scene.hpp, StartSpec), and the
// scene text of a continuation (ede-sim --continue: the source log's scene with [start] in place of its
// disks).
// Apart from scene_loader.cpp so that a scene without [start] reads exactly as before and the table's
// rules sit in one place. Rejected: a `[[species]] kind = "from_log"` entry, which would mix per-species
// keys (count, radius) that a loaded state already fixes with keys that must not be given.
#pragma once

#include <optional>
#include <string>

#include "ede/error.hpp"
#include "ede/scene.hpp"
#include "scene/scene_keys.hpp"

namespace ede::scene_detail {

// The [start] table, or nullopt without one. Exactly one of from and csv; at only with from.
std::optional<StartSpec> read_start(const Reader& top);

}  // namespace ede::scene_detail

namespace ede {

// The scene text `scene_text` (a log's effective scene) made into a continuation: its [[species]] and
// [[actions]] removed (actions happened at times of the old run) and [start] set to from = log_path and at
// (when given); the rest (box, physics, stop, ...) kept for --set overrides to change.
Result<std::string> continuation_scene_text(const std::string& scene_text, const std::string& scene_name,
                                            const std::string& log_path, std::optional<double> at);

}  // namespace ede
