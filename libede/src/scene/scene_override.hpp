// --set key=value overrides, applied to a scene's TOML tree before it is checked.
//
// An override edits the tree, not the Scene: the checks then treat its value exactly like one from the
// file, and the tree serialised afterwards is what was run. Rejected: overriding Scene fields after
// loading, which needs a second checker per field and cannot record the result as a scene file.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <vector>

#include "ede/scene.hpp"
#include "scene/scene_keys.hpp"

namespace ede::scene_detail {

// Applies the overrides in order. Key paths: dotted keys, array elements as species[1] or species.1, or
// species.NAME for the species (any array element) whose name is NAME; missing tables on the way are
// created. Returns each override with the canonical path it set, for naming it in later errors. Throws
// SceneError for an override that cannot be applied (no '=', empty key, no such element, not a table).
std::vector<AppliedOverride> apply_overrides(toml::table& root, const std::vector<Override>& overrides,
                                             const std::string& source_name);

}  // namespace ede::scene_detail
