// Rough-disk keys (physics.roughness, wall_roughness, physics.pairs[].roughness; species inertia_factor,
// omega, spin_temperature): parsed into the Scene, checked with errors naming file, line, key and fix,
// and set up deterministically (spins drawn after the velocities, so the velocities do not change).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "ede/scene.hpp"
#include "setup/setup.hpp"

namespace {

using Catch::Matchers::Contains;

const std::string kScene = R"(seed = 3
[box]
size = [1.0, 1.0]
[physics]
restitution = 0.9
[[species]]
name = "gas"
count = 300
radius = 0.01
[species.velocity]
kind = "maxwell"
temperature = 1.0
[stop]
time = 1.0
)";

std::string with_physics(const std::string& lines) {
  std::string s = kScene;
  s.insert(s.find("[[species]]"), lines + "\n");
  return s;
}
std::string with_species(const std::string& lines) {
  std::string s = kScene;
  s.insert(s.find("[species.velocity]"), lines + "\n");
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

ede::Scene load(const std::string& text) {
  auto result = ede::parse_scene_text(text, "scene.toml");
  INFO((result.ok() ? std::string() : result.error().message));
  REQUIRE(result.ok());
  return result.value();
}

}  // namespace

TEST_CASE("scene rough: a smooth scene is what it was: beta = -1, no rotation", "[scene][rough]") {
  const ede::Scene s = load(kScene);
  CHECK(s.physics.roughness == -1);
  CHECK(s.physics.wall_roughness == -1);
  CHECK_FALSE(s.physics.rough());
  CHECK_FALSE(s.rotates());
  CHECK(s.species[0].inertia_factor == 0.5);
  auto init = ede::build_initial_state(s);
  REQUIRE(init.ok());
  CHECK(init.value().omega.empty());
  CHECK(init.value().inertia.empty());
}

TEST_CASE("scene rough: roughness keys for pairs, walls and a pair of species", "[scene][rough]") {
  std::string text = with_physics("roughness = 0.5\nwall_roughness = 1.0");
  text += "[[species]]\nname = \"big\"\ncount = 2\nradius = 0.05\n[[physics.pairs]]\nspecies = [\"gas\", \"big\"]\nroughness = -0.2\n";
  const ede::Scene s = load(text);
  CHECK(s.physics.roughness == 0.5);
  CHECK(s.physics.wall_roughness == 1.0);
  REQUIRE(s.physics.pairs.size() == 1);
  CHECK(s.physics.pair_roughness(s.physics.pairs[0]) == -0.2);
  CHECK(s.physics.pairs[0].value == 0.9);  // only roughness given: the scene's restitution
  CHECK(s.rotates());
  // The effective text reads back to the same scene.
  const ede::Scene again = load(s.source_text);
  CHECK(again.physics.roughness == 0.5);
  CHECK(again.physics.pair_roughness(again.physics.pairs[0]) == -0.2);
}

TEST_CASE("scene rough: spins drawn from the species' stream leave the velocities as they were", "[scene][rough]") {
  const ede::Scene smooth = load(kScene);
  const ede::Scene spun = load(with_species("inertia_factor = 0.25\nspin_temperature = 2.0"));
  CHECK(spun.rotates());
  auto a = ede::build_initial_state(smooth), b = ede::build_initial_state(spun);
  REQUIRE((a.ok() && b.ok()));
  const ede::InitialState &s = a.value(), &r = b.value();
  REQUIRE(r.omega.size() == r.size());
  double sum = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    REQUIRE(r.vx[i] == s.vx[i]);
    REQUIRE(r.x[i] == s.x[i]);
    REQUIRE(r.inertia[i] == 0.25 * r.mass[i] * r.radius[i] * r.radius[i]);
    sum += 0.5 * r.inertia[i] * r.omega[i] * r.omega[i];
  }
  // <I w^2 / 2> = kT / 2 = 1 per disk; 300 draws: ~8 % spread. Tolerance 25 %.
  CHECK(sum / double(r.size()) == Approx(1.0).epsilon(0.25));
  const ede::Scene fixed = load(with_species("omega = 3.5"));
  auto c = ede::build_initial_state(fixed);
  REQUIRE(c.ok());
  CHECK(c.value().omega[7] == 3.5);
  CHECK(c.value().inertia[7] == 0.5 * c.value().mass[7] * c.value().radius[7] * c.value().radius[7]);
}

TEST_CASE("scene rough: bad values are refused with the key and a fix", "[scene][rough]") {
  CHECK_THAT(error_of(with_physics("roughness = 1.5")), Contains("physics.roughness"));
  CHECK_THAT(error_of(with_physics("wall_roughness = -2.0")), Contains("physics.wall_roughness"));
  CHECK_THAT(error_of(with_species("inertia_factor = 0.0")), Contains("inertia_factor"));
  CHECK_THAT(error_of(with_species("omega = 1.0\nspin_temperature = 1.0")), Contains("both omega and spin_temperature"));
  CHECK_THAT(error_of(with_physics("roughness = 0.5\ngravity = [0.0, -1.0]")), Contains("not supported yet"));
  CHECK_THAT(error_of(with_physics("rougness = 0.5")), Contains("roughness"));
}
