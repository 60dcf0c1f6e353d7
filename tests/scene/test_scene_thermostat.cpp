// The thermostat's keys ([thermostat], [species.thermostat]): parsed into the Scene and the engine's
// options, checked with errors naming file, line, key and fix.
#include <catch2/catch.hpp>
#include <string>

#include "ede/scene.hpp"
#include "engine/engine.hpp"
#include "scene_test_support.hpp"

namespace {

using Catch::Matchers::Contains;

const std::string kScene = R"(seed = 3
[box]
size = [1.0, 1.0]
[[species]]
name = "gas"
count = 30
radius = 0.01
[[species]]
name = "dust"
count = 10
radius = 0.02
[stop]
time = 1.0
)";

std::string with_top(const std::string& lines) { return kScene + lines + "\n"; }  // tables after [stop]
std::string with_dust(const std::string& lines) { return kScene.substr(0, kScene.find("[stop]")) + lines + "\n[stop]\ntime = 1.0\n"; }

// A refusal names the file, its line and a fix (scene_error checks the fix).
std::string error_of(const std::string& text) {
  const std::string message = ede::test::scene_error(text);
  CHECK_THAT(message, Contains("scene.toml:"));
  return message;
}

ede::Scene load(const std::string& text) { return ede::test::scene_of(text); }

}  // namespace

TEST_CASE("scene thermostat: none by default, the scene's and a species' own reach the engine", "[scene][thermostat]") {
  CHECK_FALSE(load(kScene).thermostatted());
  const ede::Scene s = load(with_dust("[species.thermostat]\ntemperature = 2.5\nrate = 0.5") + "\n[thermostat]\ntemperature = 1.5\nrate = 0.25\nspecies = [\"gas\"]\n");
  REQUIRE(s.thermostatted());
  REQUIRE(s.physics.thermostat);
  CHECK(s.physics.thermostat->temperature == 1.5);
  CHECK(s.physics.thermostat->rate == 0.25);
  CHECK(s.physics.thermostat->species == std::vector<std::string>{"gas"});
  REQUIRE(s.species[1].thermostat);
  CHECK(s.species[1].thermostat->temperature == 2.5);
  const ede::EngineOptions o = ede::engine_options_from(s, 40);
  CHECK(ede::uses_thermostat(o));
  CHECK(o.seed == 3);
  const ede::ThermostatSpec gas = ede::thermostat_for("gas", o.physics, o.species_thermostats);
  const ede::ThermostatSpec dust = ede::thermostat_for("dust", o.physics, o.species_thermostats);
  CHECK(gas.temperature == 1.5);
  CHECK(gas.rate == 0.25);
  CHECK(dust.temperature == 2.5);
  CHECK(dust.rate == 0.5);
  // A species' rate of 0 leaves it out.
  const ede::Scene off = load(with_dust("[species.thermostat]\ntemperature = 2.5\nrate = 0.0"));
  CHECK_FALSE(off.thermostatted());
}

TEST_CASE("scene thermostat: bad keys are errors with file, line, key and fix", "[scene][thermostat]") {
  CHECK_THAT(error_of(with_top("[thermostat]\nrate = 1.0")), Contains("thermostat.temperature"));
  CHECK_THAT(error_of(with_top("[thermostat]\ntemperature = 1.0")), Contains("thermostat.rate"));
  CHECK_THAT(error_of(with_top("[thermostat]\ntemperature = 0.0\nrate = 1.0")), Contains("> 0"));
  CHECK_THAT(error_of(with_top("[thermostat]\ntemperature = 1.0\nrate = 0.0")), Contains("thermostat.rate"));
  CHECK_THAT(error_of(with_top("[thermostat]\ntemperature = 1.0\nrate = 1.0\nspecies = [\"gsa\"]")),
             Contains("there is no species 'gsa'"));
  CHECK_THAT(error_of(with_top("[thermostat]\ntemperature = 1.0\nrat = 1.0")), Contains("rate"));
  CHECK_THAT(error_of(with_dust("[species.thermostat]\ntemperature = 1.0\nrate = -1.0")), Contains("species[1].thermostat.rate"));
  CHECK_THAT(error_of(with_dust("[species.thermostat]\ntemperature = 1.0\nrate = 1.0\nspecies = [\"gas\"]")),
             Contains("species"));
  CHECK_THAT(error_of(with_top("[physics]\ngravity = [0.0, -1.0]\n[thermostat]\ntemperature = 1.0\nrate = 1.0")),
             Contains("not supported yet"));
  CHECK_THAT(error_of(with_top("[physics]\nroughness = 0.5\n[thermostat]\ntemperature = 1.0\nrate = 1.0")),
             Contains("not supported yet"));
  // Steps and a thermostat: no engine has both (engine_factory.hpp), refused whichever table names it.
  const std::string steps = "[[physics.steps]]\nradius = [0.06]\nenergy = [-0.5]\n";
  CHECK(load(with_top(steps)).physics.has_steps());
  CHECK_THAT(error_of(with_top(steps + "[thermostat]\ntemperature = 1.0\nrate = 1.0")),
             Contains("the thermostat with square wells or shoulders") && Contains("not supported yet"));
  CHECK_THAT(error_of(with_dust("[species.thermostat]\ntemperature = 1.0\nrate = 1.0") + steps),
             Contains("a species' thermostat with square wells or shoulders"));
}
