// Fuzz target: the scene parser (and, for small scenes, setup and engine creation).
//
// Any text must give a Scene or one clear error, never a crash, a hang or a sanitizer report. Scenes that
// parse and stay small (at most 300 disks) go on to setup and engine creation, which check placement,
// overlaps and the box; bigger ones stop after parsing (placing 10^8 disks is not a parser bug).
// Seed corpus: fuzz/corpus/scene (the example scenes and edge cases).
// The harness returns false on a violated check; the fuzz target traps on it, the test suite fails.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/engine.hpp"
#include "ede/scene.hpp"
#include "setup/setup.hpp"

namespace ede::fuzz {

inline bool fuzz_scene(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto scene = ede::parse_scene_text(text, "fuzz.toml");
  if (!scene) {
    if (scene.error().message.empty()) return false;  // every refusal says why
    return true;
  }
  std::int64_t disks = 0;
  for (const ede::SpeciesSpec& s : scene.value().species) disks += s.count;
  if (disks > 300) return true;
  // Growth runs ~6 / rate collisions per disk: only fast growth stays within a fuzzing step.
  if (scene.value().grow && scene.value().grow->rate < 1e-2) return true;
  auto initial = ede::build_initial_state(scene.value());
  if (!initial) {
    if (initial.error().message.empty()) return false;
    return true;
  }
  auto engine = ede::make_engine<double>(initial.value(), ede::engine_options_from(scene.value(), initial.value().size()));
  if (engine) engine.value()->run(200);  // a few events: initial predictions on whatever setup accepted
  return true;
}

}  // namespace ede::fuzz
