// Starting a run from a state (a scene's [start], ede/scene.hpp StartSpec): the disks of an event log at a
// time, read through the public Log (Log::state_at, bit-identical to the engine's state there), or of a
// CSV state (setup/setup_from_csv.hpp); then the scene's box, zero total momentum and reversal as asked,
// and the provenance recorded in the scene text the new log stores: start.at (the log's end when not
// given) and start.digest (the source log's content digest, or XXH3-128 of the CSV's bytes). A digest the
// scene already gives must match (a verify or resume months later from a changed source is refused).
// Here in run/ because reading a log needs replay/, a floor above setup/. Rejected: storing the starting
// state's provenance in new log header fields (a format change for what the scene text can carry; the
// header's per-disk data and first keyframe already make the new log replayable without its source).
#pragma once

#include "core/initial_state.hpp"
#include "ede/error.hpp"
#include "ede/scene.hpp"
#include "ede/state.hpp"

namespace ede {

struct StartedRun {
  Scene scene;           // the scene with start.at and start.digest recorded in its source_text
  InitialState initial;  // checked against the box (overlaps, disks inside)
};

Result<StartedRun> start_from_state(const Scene& scene);

// A state's disks (with their spins, if any) and box as an initial state.
InitialState initial_state_of(const State& state);

// The path a [start] names, relative to the scene file's folder (as given for scene text "<...>").
std::string resolve_start_path(const std::string& path, const std::string& scene_source_name);

}  // namespace ede
