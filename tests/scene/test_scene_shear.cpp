// The Lees-Edwards keys (box.boundary = "lees-edwards", box.shear_rate): parsed into the Scene and the
// engine's options, checked with errors naming file, line, key and fix, and the effects its engine does
// not have refused with their reasons.
#include <catch2/catch.hpp>
#include <string>

#include "ede/scene.hpp"
#include "engine/engine.hpp"
#include "scene_test_support.hpp"

namespace {

using Catch::Matchers::Contains;

std::string scene(const std::string& box, const std::string& more = "") {
  return "seed = 3\n[box]\nsize = [2.0, 2.0]\n" + box + "\n" + more +
         "\n[[species]]\nname = \"gas\"\ncount = 30\nradius = 0.01\n[stop]\ntime = 1.0\n";
}

std::string error_of(const std::string& text) {
  const std::string message = ede::test::scene_error(text);
  CHECK_THAT(message, Contains("scene.toml:"));
  return message;
}

}  // namespace

TEST_CASE("scene shear: a Lees-Edwards box is periodic with its rate, and reaches the sheared engine", "[scene][shear]") {
  const ede::Scene plain = ede::test::scene_of(scene("boundary = \"periodic\""));
  CHECK_FALSE(plain.sheared());
  const ede::Scene s = ede::test::scene_of(scene("boundary = \"lees-edwards\"\nshear_rate = 0.25"));
  REQUIRE(s.sheared());
  CHECK(s.boundary == ede::BoundaryKind::Periodic);
  CHECK(*s.shear_rate == 0.25);
  const ede::EngineOptions o = ede::engine_options_from(s, 30);
  CHECK(ede::uses_shear(o));
  CHECK(ede::engine_kind_for(o) == ede::EngineKind::Sheared);
  CHECK_FALSE(ede::engine_can_run(ede::EngineKind::PeriodicDissipative, o));
  CHECK_FALSE(ede::engine_can_run(ede::EngineKind::Sheared, ede::engine_options_from(plain, 30)));
  CHECK(ede::test::scene_of(scene("boundary = \"lees-edwards\"\nshear_rate = 0.0")).sheared());
  // A thermostat in a sheared box draws about the flow, in the same engine.
  const ede::Scene heated =
      ede::test::scene_of(scene("boundary = \"lees-edwards\"\nshear_rate = 0.25", "[thermostat]\ntemperature = 1.0\nrate = 0.1"));
  CHECK(heated.thermostatted());
  CHECK(ede::engine_kind_for(ede::engine_options_from(heated, 30)) == ede::EngineKind::Sheared);
}

TEST_CASE("scene shear: bad keys and unsupported effects are errors with file, line, key and fix", "[scene][shear]") {
  CHECK_THAT(error_of(scene("boundary = \"lees-edwards\"")), Contains("box.shear_rate") && Contains("missing"));
  CHECK_THAT(error_of(scene("boundary = \"lees-edwards\"\nshear_rate = -0.5")), Contains("box.shear_rate"));
  CHECK_THAT(error_of(scene("boundary = \"lees-edwards\"\nshear_rate = inf")), Contains("box.shear_rate"));
  CHECK_THAT(error_of(scene("boundary = \"periodic\"\nshear_rate = 0.5")),
             Contains("only a Lees-Edwards box is sheared"));
  CHECK_THAT(error_of(scene("boundary = \"lees-edward\"\nshear_rate = 0.5")), Contains("lees-edwards"));
  const std::string le = "boundary = \"lees-edwards\"\nshear_rate = 0.5";
  CHECK_THAT(error_of(scene(le, "[physics]\nroughness = 0.5")), Contains("rough or spinning disks"));
  CHECK_THAT(error_of(scene(le, "[physics]\ngravity = [0.0, -1.0]")), Contains("gravity needs walls"));
  CHECK_THAT(error_of(scene(le, "[[physics.steps]]\nradius = [0.06]\nenergy = [-0.5]")),
             Contains("square wells or shoulders"));
  CHECK_THAT(error_of(scene(le, "[[actions]]\ntime = 0.5\nkind = \"reverse_velocities\"")), Contains("actions"));
}
