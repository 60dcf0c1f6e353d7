// Scenes in tests, through the public API: text parsed into a Scene (a refusal fails the test with its
// message), the message of a scene that must be refused (with a fix), a scene run with its log written to
// a scratch file, and the one-species gas most scene and run tests start from, as TOML text.
// Rejected: a scene builder over ede::Scene's fields (tests are about the TOML a user writes, errors
// included, so they keep text) and scratch scene files (parse_scene_text takes the text and a name).
#pragma once

#include <catch2/catch.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ede/ede.hpp"
#include "tool_runner.hpp"  // temp_path

namespace ede::test {

// The scene the text describes; `name` is what its messages call it.
inline Scene scene_of(const std::string& text, const std::string& name = "scene.toml",
                      const std::vector<Override>& overrides = {}) {
  auto scene = parse_scene_text(text, name, overrides);
  if (!scene) FAIL(scene.error().message);
  return std::move(scene).value();
}

// The message of a scene that must be refused; every refusal names a fix.
inline std::string scene_error(const std::string& text, const std::string& name = "scene.toml",
                               const std::vector<Override>& overrides = {}) {
  auto scene = parse_scene_text(text, name, overrides);
  REQUIRE_FALSE(scene.ok());
  INFO(scene.error().message);
  CHECK_THAT(scene.error().message, Catch::Matchers::Contains("Fix: "));
  return scene.error().message;
}

// Runs the scene to its end with its log at temp_path(file) and returns that path; with `expected`, the
// run must end that way.
inline std::string run_to_log(const Scene& scene, const std::string& file, std::optional<RunStatus> expected = {}) {
  const std::string path = temp_path(file);
  auto sim = Simulation::create(scene, {.log_path = path});
  INFO((sim ? "" : sim.error().message));
  REQUIRE(sim);
  const RunStatus status = sim.value().run();
  REQUIRE(is_finished(status));
  if (expected) CHECK(status == *expected);
  REQUIRE(sim.value().close());
  return path;
}

// The scene run into temp_path(file) for `events` events, interrupted there (at a resumable point it
// must have passed), then resumed to its end: the bytes of the finished log.
inline std::string interrupted_and_resumed(const Scene& scene, const std::string& file, std::uint64_t events) {
  const std::string path = temp_path(file);
  {
    auto sim = Simulation::create(scene, {.log_path = path}).value();
    REQUIRE(sim.run(events) == RunStatus::Running);
    sim.interrupt();
    REQUIRE(sim.close());
    const LogKept k = sim.log_kept().value();
    REQUIRE(k.resumable);
    CHECK(k.resume_event > 0);
  }
  auto resumed = Simulation::resume(path).value();
  REQUIRE(is_finished(resumed.run()));
  REQUIRE(resumed.close());
  return read_file(path);
}

// A gas of one species, "gas", as TOML: seed, box size, count, radius, an optional [species.placement]
// table, the velocity rule and the stop condition (each field is the TOML text of its value or lines).
struct GasToml {
  std::string seed = "5", size = "[1.0, 1.0]", count = "400", radius = "0.01";
  std::string placement = {};  // the lines of [species.placement]; none: no table (random in the box)
  std::string velocity = "kind = \"speed\"\nspeed = 1.0";
  std::string stop = "time = 1.0";
  std::string tables = {};  // more top-level tables before [[species]] ([engine], [log], ...)

  std::string text() const {
    std::string t = (seed.empty() ? "" : "seed = " + seed + "\n") + "[box]\nsize = " + size + "\n" + tables +
                    "[[species]]\nname = \"gas\"\ncount = " + count + "\nradius = " + radius + "\n";
    if (!placement.empty()) t += "[species.placement]\n" + placement + "\n";
    return t + "[species.velocity]\n" + velocity + "\n[stop]\n" + stop + "\n";
  }
};

// 400 disks in a walled box with small rebuild, keyframe and chunk intervals, so that short runs hold
// several of each and a stop falls between them: the run and Simulation tests' gas.
inline GasToml logged_gas(const std::string& seed, const std::string& stop_time) {
  GasToml g;
  g.seed = seed, g.stop = "time = " + stop_time;
  g.tables = "[engine]\nrebuild_interval = 4000\n[log]\nkeyframe_interval = 3000\nchunk_events = 1024\n";
  return g;
}

// The divider at x = 1 of a [2, 1] box with a hole from y = lower_top to upper_bottom, as two
// [[walls.segments]] (the effusion scenes); `upper_extra`: more lines for the upper one (a restitution).
inline std::string divider_toml(const std::string& lower_top, const std::string& upper_bottom,
                                const std::string& upper_extra = "") {
  return "[[walls.segments]]\nfrom = [1.0, 0.0]\nto = [1.0, " + lower_top + "]\n[[walls.segments]]\nfrom = [1.0, " +
         upper_bottom + "]\nto = [1.0, 1.0]\n" + upper_extra;
}

// A Maxwellian gas (kT = 1) of `count` disks placed at random in the left half [0, 1] x [0, 1] of a [2, 1]
// box: the effusion scenes' gas.
inline GasToml left_half_gas(const std::string& count, const std::string& radius) {
  GasToml g;
  g.size = "[2.0, 1.0]", g.count = count, g.radius = radius;
  g.placement = "kind = \"random\"\nregion = [0.0, 0.0, 1.0, 1.0]";
  g.velocity = "kind = \"maxwell\"\ntemperature = 1.0";
  return g;
}

}  // namespace ede::test
