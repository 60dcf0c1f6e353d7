// Loading a scene: TOML text -> overrides -> checked Scene.
//
// Every error names the file, the line and column where toml++ knows them, the key as a dotted path
// (species[1].radius), what is wrong and what would fix it. Unknown keys are errors (no silent default
// for a mistyped key). Overrides ("--set key=value") are applied to the TOML tree before checking, so an
// override is checked exactly like the file's own value, and Scene::source_text records what was run.
#pragma once

#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/scene.hpp"

namespace ede {

// key=value, e.g. "physics.restitution=0.9", "species[1].mass=25", "species.projectile.velocity.vector=[0,-5]".
// The value is a TOML value; a bare word that is not a TOML value is taken as a string (scalar=float).
struct Override {
  std::string text;
};

Result<Scene> load_scene_file(const std::string& path, const std::vector<Override>& overrides = {});
Result<Scene> parse_scene_text(const std::string& text, const std::string& source_name,
                               const std::vector<Override>& overrides = {});

}  // namespace ede
