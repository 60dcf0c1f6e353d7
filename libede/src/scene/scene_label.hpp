// The name a run records for its scene: the file's name without its directory.
//
// A log's header and the effective scene text it stores name the scene; with the path as given, the same
// scene and seed run from another directory (`ede-sim gas.toml` against `ede-sim ../x/gas.toml`) wrote
// different bytes, against the promise that a scene and a seed give one log. Messages about a scene's
// contents still name the path as given (the user needs it to find the file).
// Rejected: the canonical absolute path (still differs between machines and checkouts) and no name at
// all (ede-replay info would lose what the run was).
#pragma once

#include <string>

namespace ede {

inline std::string scene_label(const std::string& source_name) {
  const std::size_t slash = source_name.find_last_of('/');
  if (slash == std::string::npos || slash + 1 == source_name.size()) return source_name;
  return source_name.substr(slash + 1);
}

}  // namespace ede
