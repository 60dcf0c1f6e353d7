// Stepped-potential keys ([[physics.steps]]: species, radius, energy): parsed into the Scene, and refused
// with errors naming file, line, key and fix: steps inside the hard core, unsorted radii, energies missing,
// zero or not finite, unknown species, a pair given twice, and the combinations not supported (rough disks,
// wall segments).
#include <catch2/catch.hpp>
#include <string>

#include "ede/scene.hpp"

namespace {

using Catch::Matchers::Contains;

const std::string kScene = R"(seed = 3
[box]
size = [1.0, 1.0]
[physics]
[[species]]
name = "gas"
count = 300
radius = 0.01
[[species]]
name = "big"
count = 10
radius = 0.02
[stop]
time = 1.0
)";

std::string with_physics(const std::string& lines) {
  std::string s = kScene;
  s.insert(s.find("[[species]]"), lines + "\n");
  return s;
}

std::string error_of(const std::string& text) {
  auto result = ede::parse_scene_text(text, "scene.toml");
  REQUIRE_FALSE(result.ok());
  INFO(result.error().message);
  CHECK_THAT(result.error().message, Contains("scene.toml:"));
  CHECK_THAT(result.error().message, Contains("Fix: "));
  return result.error().message;
}

}  // namespace

TEST_CASE("scene steps: a well for every pair and a shoulder for one pair are read as given", "[scene][steps]") {
  auto scene = ede::parse_scene_text(with_physics("[[physics.steps]]\nradius = [0.05, 0.06]\nenergy = [0.5, -1]\n"
                                                  "[[physics.steps]]\nspecies = [\"gas\", \"big\"]\nradius = [0.04]\nenergy = [2]"),
                                     "scene.toml");
  REQUIRE(scene.ok());
  const auto& steps = scene.value().physics.steps;
  REQUIRE(steps.size() == 2);
  CHECK(steps[0].a.empty());
  CHECK(steps[0].radius == std::vector<double>{0.05, 0.06});
  CHECK(steps[0].energy == std::vector<double>{0.5, -1});
  CHECK(steps[1].a == "gas");
  CHECK(steps[1].b == "big");
  CHECK(scene.value().physics.has_steps());
  CHECK_FALSE(ede::parse_scene_text(kScene, "scene.toml").value().physics.has_steps());
}

TEST_CASE("scene steps: bad steps are refused with the key and a fix", "[scene][steps]") {
  // big-big touch at 0.04: a default step at 0.035 lies inside their core.
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nradius = [0.035]\nenergy = [-1]")),
             Contains("physics.steps[0]: the innermost step (radius 0.035) lies inside the hard core"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nspecies = [\"gas\", \"gas\"]\nradius = [0.015]\nenergy = [-1]")),
             Contains("lies inside the hard core"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nradius = [0.06, 0.05]\nenergy = [-1, 1]")),
             Contains("physics.steps[0].radius[1]: the step radii must increase"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nradius = [0.05, 0.06]\nenergy = [-1]")),
             Contains("needs one energy per radius"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nradius = [0.05]\nenergy = [0]")),
             Contains("physics.steps[0].energy[0]: a step of energy 0 changes nothing"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nradius = [0.05]\nenergy = [inf]")),
             Contains("physics.steps[0].energy[0]"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nradius = [nan]\nenergy = [1]")),
             Contains("physics.steps[0].radius[0]"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nenergy = [1]")), Contains("physics.steps[0].radius"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nspecies = [\"gas\", \"dust\"]\nradius = [0.05]\nenergy = [1]")),
             Contains("there is no species 'dust'"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nspecies = [\"gas\", \"big\"]\nradius = [0.05]\nenergy = [1]\n"
                                   "[[physics.steps]]\nspecies = [\"big\", \"gas\"]\nradius = [0.06]\nenergy = [1]")),
             Contains("were already given by physics.steps[0]"));
  CHECK_THAT(error_of(with_physics("[[physics.steps]]\nradius = [0.05]\nenergy = [1]\nlambda = 1.5")),
             Contains("lambda"));
}

TEST_CASE("scene steps: combinations not supported yet are refused, not run wrongly", "[scene][steps]") {
  CHECK_THAT(error_of(with_physics("roughness = 0.5\n[[physics.steps]]\nradius = [0.05]\nenergy = [-1]")),
             Contains("not supported yet"));
  std::string segments = with_physics("[[physics.steps]]\nradius = [0.05]\nenergy = [-1]");
  segments += "[walls]\n[[walls.segments]]\nfrom = [0.5, 0.0]\nto = [0.5, 0.4]\n";
  CHECK_THAT(error_of(segments), Contains("with wall segments are not supported yet"));
}
