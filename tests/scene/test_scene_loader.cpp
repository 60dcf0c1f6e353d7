// Tests of the scene loader: TOML -> Scene, defaults, every class of error, --set overrides, the effective
// text round trip, and every example scene under examples/.
//
// Error tests check substrings (file, line, key path, the gist) rather than whole messages, so wording can
// improve without rewriting tests while a wrong line or path still fails. Rejected: golden message files,
// which break on every rewording and are then updated without being read.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "ede/scene.hpp"
#include "scene_test_support.hpp"

namespace {

using Catch::Matchers::Contains;
using ede::Override;
using ede::Scene;

// A small valid scene; error tests change one line of it. Lines: 1 seed, 3 size, 4 [[species]], 5 name,
// 6 count, 7 radius, 8 [species.velocity], 9 kind, 10 speed, 11 [stop], 12 time.
const std::string kBase = R"(seed = 42
[box]
size = [1.0, 1.0]
[[species]]
name = "gas"
count = 10
radius = 0.01
[species.velocity]
kind = "speed"
speed = 1.0
[stop]
time = 1.0
)";

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

Scene load(const std::string& text, const std::vector<Override>& overrides = {}) {
  return ede::test::scene_of(text, "scene.toml", overrides);
}

std::string error_of(const std::string& text, const std::vector<Override>& overrides = {}) {
  const std::string message = ede::test::scene_error(text, "scene.toml", overrides);  // refused, with a fix
  CHECK_THAT(message, Contains(": error: "));
  return message;
}

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Every field of a Scene but its source, as text: equal dumps mean equal scenes.
std::string dump(const Scene& s) {
  std::ostringstream o;
  o << s.seed << " box " << num(s.lx) << " " << num(s.ly) << " " << ede::to_string(s.boundary) << " xi "
    << num(s.physics.restitution) << " " << num(s.physics.wall_restitution) << " " << num(s.physics.tc) << " "
    << ede::to_string(s.scalar) << "\n";
  for (const auto& sp : s.species) {
    o << sp.name << " " << sp.count << " r " << num(sp.radius.min) << " " << num(sp.radius.max) << " "
      << sp.radius.from_packing << " m " << static_cast<int>(sp.mass.kind) << " " << num(sp.mass.value)
      << " p " << static_cast<int>(sp.placement.kind) << " " << num(sp.placement.region.x0) << " "
      << num(sp.placement.region.y0) << " " << num(sp.placement.region.x1) << " "
      << num(sp.placement.region.y1) << " "
      << (sp.placement.packing_fraction ? num(*sp.placement.packing_fraction) : "-") << " "
      << static_cast<int>(sp.placement.lattice) << " " << static_cast<int>(sp.placement.sampling) << " v "
      << static_cast<int>(sp.velocity.kind) << " "
      << num(sp.velocity.speed) << " " << num(sp.velocity.vector[0]) << " " << num(sp.velocity.vector[1])
      << " " << num(sp.velocity.temperature) << "\n";
    for (auto [x, y] : sp.placement.positions) o << " at " << num(x) << " " << num(y);
    for (auto [x, y] : sp.velocity.list) o << " v " << num(x) << " " << num(y);
    o << "\n";
  }
  auto opt = [](const auto& v) { return v ? num(static_cast<double>(*v)) : std::string("-"); };
  o << "stop " << opt(s.stop.time) << " " << opt(s.stop.events) << " " << opt(s.stop.collisions_per_particle)
    << " " << opt(s.stop.energy_fraction) << " sample " << opt(s.sample_interval) << "\n";
  for (const auto& a : s.actions) o << "action " << num(a.time) << " " << static_cast<int>(a.kind) << "\n";
  return o.str();
}

const std::string kFull = R"(seed = 7
[box]
size = [2.0, 1.5]
boundary = "periodic"
[physics]
restitution = 0.9
wall_restitution = 0.8
tc = 1e-4
[engine]
scalar = "long_double"
[[species]]
name = "gas"
count = 100
radius = { min = 0.01, max = 0.02 }
density = 2.0
[species.placement]
kind = "random"
region = [0.0, 0.0, 1.0, 1.5]
sampling = "free-voxels"
[species.velocity]
kind = "maxwell"
temperature = 0.5
[[species]]
name = "grid"
count = 16
mass = 4
[species.placement]
kind = "lattice"
lattice = "square"
packing_fraction = 0.5
region = [1, 0, 2, 1]
[species.velocity]
kind = "vector"
vector = [0.0, -5]
[[species]]
name = "pair"
radius = 0.05
[species.placement]
kind = "explicit"
positions = [[0.5, 0.5], [1.5, 0.5]]
[species.velocity]
kind = "list"
values = [[1.0, 0.0], [-1, 0]]
[stop]
time = 10
events = 1e6
collisions_per_particle = 50
energy_fraction = 0.1
[sampling]
interval = 0.25
[[actions]]
time = 6.0
kind = "reverse_velocities"
[[actions]]
time = 3
kind = "reverse_velocities"
)";

}  // namespace

TEST_CASE("scene loader: a full scene gives exactly the Scene it describes", "[scene]") {
  const Scene s = load(kFull);
  CHECK(s.source_name == "scene.toml");
  CHECK(s.seed == 7);
  CHECK(s.lx == 2.0);
  CHECK(s.ly == 1.5);
  CHECK(s.boundary == ede::BoundaryKind::Periodic);
  CHECK(s.physics.restitution == 0.9);
  CHECK(s.physics.wall_restitution == 0.8);
  CHECK(s.physics.tc == 1e-4);
  CHECK(s.scalar == ede::ScalarKind::LongDouble);
  REQUIRE(s.species.size() == 3);

  const auto& gas = s.species[0];
  CHECK(gas.name == "gas");
  CHECK(gas.count == 100);
  CHECK(gas.radius.min == 0.01);
  CHECK(gas.radius.max == 0.02);
  CHECK_FALSE(gas.radius.from_packing);
  CHECK(gas.mass.kind == ede::MassSpec::Kind::PerArea);
  CHECK(gas.mass.value == 2.0);
  CHECK(gas.placement.kind == ede::PlacementKind::Random);
  CHECK(gas.placement.region.x1 == 1.0);
  CHECK(gas.placement.region.y1 == 1.5);
  CHECK(gas.placement.sampling == ede::RandomSampling::FreeVoxels);
  CHECK(gas.velocity.kind == ede::VelocityKind::Maxwell);
  CHECK(gas.velocity.temperature == 0.5);

  const auto& grid = s.species[1];
  CHECK(grid.count == 16);
  CHECK(grid.radius.from_packing);
  CHECK(grid.radius.min == 0);
  CHECK(grid.radius.max == 0);
  CHECK(grid.mass.kind == ede::MassSpec::Kind::Fixed);
  CHECK(grid.mass.value == 4.0);
  CHECK(grid.placement.kind == ede::PlacementKind::Lattice);
  CHECK(grid.placement.lattice == ede::LatticeKind::Square);
  CHECK(grid.placement.packing_fraction == 0.5);
  CHECK(grid.placement.region.x0 == 1.0);
  CHECK(grid.placement.region.y1 == 1.0);
  CHECK(grid.velocity.kind == ede::VelocityKind::Vector);
  CHECK(grid.velocity.vector == std::array<double, 2>{0.0, -5.0});

  const auto& pair = s.species[2];
  CHECK(pair.count == 2);  // from the positions
  CHECK(pair.radius.min == 0.05);
  CHECK(pair.radius.max == 0.05);
  CHECK(pair.mass.value == 1.0);
  CHECK(pair.placement.kind == ede::PlacementKind::Explicit);
  CHECK(pair.placement.positions == std::vector<std::array<double, 2>>{{0.5, 0.5}, {1.5, 0.5}});
  CHECK(pair.velocity.kind == ede::VelocityKind::List);
  CHECK(pair.velocity.list == std::vector<std::array<double, 2>>{{1.0, 0.0}, {-1.0, 0.0}});

  CHECK(s.stop.time == 10.0);
  CHECK(s.stop.events == 1000000u);
  CHECK(s.stop.collisions_per_particle == 50.0);
  CHECK(s.stop.energy_fraction == 0.1);
  CHECK(s.sample_interval == 0.25);
  REQUIRE(s.actions.size() == 2);
  CHECK(s.actions[0].time == 3.0);  // sorted by time
  CHECK(s.actions[1].time == 6.0);
}

TEST_CASE("scene loader: defaults", "[scene]") {
  const Scene s = load("[[species]]\nname = \"a\"\ncount = 5\nradius = 0.01\n[stop]\nevents = 100\n");
  CHECK(s.seed == 1);
  CHECK(s.lx == 1.0);
  CHECK(s.ly == 1.0);
  CHECK(s.boundary == ede::BoundaryKind::Walls);
  CHECK(s.physics.restitution == 1.0);
  CHECK(s.physics.wall_restitution == 1.0);
  CHECK(s.physics.tc == 0.0);
  CHECK(s.scalar == ede::ScalarKind::Double);
  REQUIRE(s.species.size() == 1);
  const auto& a = s.species[0];
  CHECK(a.mass.kind == ede::MassSpec::Kind::Fixed);
  CHECK(a.mass.value == 1.0);
  CHECK(a.placement.kind == ede::PlacementKind::Random);
  CHECK(a.placement.region.x0 == 0.0);
  CHECK(a.placement.region.x1 == 1.0);
  CHECK(a.placement.region.y1 == 1.0);
  CHECK_FALSE(a.placement.packing_fraction);
  CHECK(a.placement.lattice == ede::LatticeKind::Hexagonal);
  CHECK(a.placement.sampling == ede::RandomSampling::Region);
  CHECK(a.velocity.kind == ede::VelocityKind::Zero);
  CHECK(s.stop.events == 100u);
  CHECK_FALSE(s.stop.time);
  CHECK_FALSE(s.sample_interval);
  CHECK(s.actions.empty());
}

TEST_CASE("scene loader: the default region follows the box size", "[scene]") {
  const Scene s = load(with(kBase, "size = [1.0, 1.0]", "size = [3, 2]"));
  CHECK(s.species[0].placement.region.x1 == 3.0);
  CHECK(s.species[0].placement.region.y1 == 2.0);
}

TEST_CASE("scene loader: scalar names", "[scene]") {
  auto scalar = [](const std::string& name) {
    return load(kBase + "[engine]\nscalar = \"" + name + "\"\n").scalar;
  };
  CHECK(scalar("float") == ede::ScalarKind::Float);
  CHECK(scalar("double") == ede::ScalarKind::Double);
  CHECK(scalar("long double") == ede::ScalarKind::LongDouble);
  CHECK(scalar("long_double") == ede::ScalarKind::LongDouble);
  CHECK(std::string(ede::to_string(ede::ScalarKind::LongDouble)) == "long double");
  CHECK(std::string(ede::to_string(ede::ScalarKind::Float128)) == "float128");
  CHECK(std::string(ede::to_string(ede::BoundaryKind::Periodic)) == "periodic");
}

TEST_CASE("scene loader: float128 where the __float128 engine is built, a clear refusal elsewhere", "[scene]") {
  const std::string text = kBase + "[engine]\nscalar = \"float128\"\n";
#if EDE_HAVE_FLOAT128
  CHECK(load(text).scalar == ede::ScalarKind::Float128);
#else
  const std::string msg = error_of(text);
  CHECK_THAT(msg, Contains("engine.scalar"));
  CHECK_THAT(msg, Contains("without the __float128 engine"));
#endif
}

TEST_CASE("scene loader: TOML syntax errors give toml++'s line", "[scene][errors]") {
  const std::string msg = error_of(with(kBase, "radius = 0.01", "radius = [0.01"));
  CHECK_THAT(msg, Contains("scene.toml:"));
  CHECK_THAT(msg, Contains("TOML syntax"));
  CHECK_THAT(error_of("seed = 1\nseed = 2\n"), Contains("scene.toml:2:"));
}

TEST_CASE("scene loader: unknown keys, with a suggestion when close", "[scene][errors]") {
  std::string msg = error_of(with(kBase, "radius = 0.01", "raduis = 0.01"));
  CHECK_THAT(msg, Contains("scene.toml:7:1:"));
  CHECK_THAT(msg, Contains("species[0].raduis"));
  CHECK_THAT(msg, Contains("species 'gas'"));
  CHECK_THAT(msg, Contains("did you mean 'radius'?"));

  msg = error_of(with(kBase, "seed = 42", "sede = 42"));
  CHECK_THAT(msg, Contains("scene.toml:1:1: error: sede"));
  CHECK_THAT(msg, Contains("did you mean 'seed'?"));

  msg = error_of(with(kBase, "count = 10", "count = 10\nspeed = 2.0"));  // a key of another table
  CHECK_THAT(msg, Contains("scene.toml:7:"));
  CHECK_THAT(msg, Contains("species[0].speed"));
  CHECK_THAT(msg, Contains("belongs in [species.velocity]"));

  msg = error_of(kBase + "[sampling]\nxyzzy = 1\n");
  CHECK_THAT(msg, Contains("scene.toml:14:1: error: sampling.xyzzy: unknown key"));
  CHECK_THAT(msg, Contains("interval"));
}

TEST_CASE("scene loader: wrong types", "[scene][errors]") {
  std::string msg = error_of(with(kBase, "radius = 0.01", "radius = \"0.01\""));
  CHECK_THAT(msg, Contains("scene.toml:7:"));
  CHECK_THAT(msg, Contains("species[0].radius"));
  CHECK_THAT(msg, Contains("expected a number, got a string"));

  msg = error_of(with(kBase, "count = 10", "count = 2.5"));
  CHECK_THAT(msg, Contains("scene.toml:6:"));
  CHECK_THAT(msg, Contains("expected an integer, got 2.5"));

  msg = error_of(with(kBase, "name = \"gas\"", "name = 3"));
  CHECK_THAT(msg, Contains("scene.toml:5:"));
  CHECK_THAT(msg, Contains("species[0].name: expected a string"));

  msg = error_of(with(kBase, "[box]\nsize = [1.0, 1.0]", "box = 3"));
  CHECK_THAT(msg, Contains("scene.toml:2:"));
  CHECK_THAT(msg, Contains("box: expected a table"));

  msg = error_of(with(kBase, "size = [1.0, 1.0]", "size = [1.0, true]"));
  CHECK_THAT(msg, Contains("box.size[1]: expected a number"));

  msg = error_of(with(kBase, "size = [1.0, 1.0]", "size = [1.0]"));
  CHECK_THAT(msg, Contains("scene.toml:3:"));
  CHECK_THAT(msg, Contains("box.size: expected an array of 2 numbers"));

  msg = error_of(with(kBase, "kind = \"speed\"", "kind = \"sped\""));
  CHECK_THAT(msg, Contains("scene.toml:9:"));
  CHECK_THAT(msg, Contains("species[0].velocity.kind (species 'gas'): unknown value 'sped'"));
  CHECK_THAT(msg, Contains("did you mean \"speed\"?"));

  msg = error_of("species = { name = \"a\" }\n[stop]\ntime = 1\n");
  CHECK_THAT(msg, Contains("species: expected an array of tables"));
}

TEST_CASE("scene loader: NaN and infinities are rejected", "[scene][errors]") {
  std::string msg = error_of(with(kBase, "speed = 1.0", "speed = nan"));
  CHECK_THAT(msg, Contains("scene.toml:10:"));
  CHECK_THAT(msg, Contains("species[0].velocity.speed"));
  CHECK_THAT(msg, Contains("finite"));
  msg = error_of(with(kBase, "time = 1.0", "time = inf"));
  CHECK_THAT(msg, Contains("scene.toml:12:"));
  CHECK_THAT(msg, Contains("stop.time"));
  msg = error_of(with(kBase, "size = [1.0, 1.0]", "size = [1.0, -inf]"));
  CHECK_THAT(msg, Contains("box.size[1]"));
  msg = error_of(with(kBase, "count = 10", "count = nan"));
  CHECK_THAT(msg, Contains("species[0].count (species 'gas'): expected an integer, got nan"));
}

TEST_CASE("scene loader: non-positive sizes, radii, masses and counts", "[scene][errors]") {
  std::string msg = error_of(with(kBase, "radius = 0.01", "radius = -0.01"));
  CHECK_THAT(msg, Contains("scene.toml:7:"));
  CHECK_THAT(msg, Contains("species[0].radius (species 'gas'): must be > 0, got -0.01"));

  msg = error_of(with(kBase, "radius = 0.01", "radius = 0"));
  CHECK_THAT(msg, Contains("must be > 0, got 0"));

  msg = error_of(with(kBase, "count = 10", "count = 10\nmass = 0"));
  CHECK_THAT(msg, Contains("scene.toml:7:"));
  CHECK_THAT(msg, Contains("species[0].mass"));

  msg = error_of(with(kBase, "count = 10", "count = 0"));
  CHECK_THAT(msg, Contains("scene.toml:6:"));
  CHECK_THAT(msg, Contains("species[0].count"));
  CHECK_THAT(msg, Contains("must be >= 1, got 0"));

  msg = error_of(with(kBase, "size = [1.0, 1.0]", "size = [1.0, 0.0]"));
  CHECK_THAT(msg, Contains("scene.toml:3:"));
  CHECK_THAT(msg, Contains("box.size[1]"));

  msg = error_of(with(kBase, "radius = 0.01", "radius = { min = 0.02, max = 0.01 }"));
  CHECK_THAT(msg, Contains("species[0].radius.max"));
  CHECK_THAT(msg, Contains("less than min"));
}

TEST_CASE("scene loader: restitution outside [0, 1]", "[scene][errors]") {
  std::string msg = error_of(kBase + "[physics]\nrestitution = 1.5\n");
  CHECK_THAT(msg, Contains("scene.toml:14:"));
  CHECK_THAT(msg, Contains("physics.restitution: must be in [0, 1], got 1.5"));
  msg = error_of(kBase + "[physics]\nwall_restitution = -0.1\n");
  CHECK_THAT(msg, Contains("physics.wall_restitution"));
  msg = error_of(kBase + "[physics]\ntc = -1\n");
  CHECK_THAT(msg, Contains("physics.tc: must be >= 0"));
}

TEST_CASE("scene loader: regions", "[scene][errors]") {
  const std::string placed =
      with(kBase, "[species.velocity]", "[species.placement]\nregion = REGION\n[species.velocity]");
  std::string msg = error_of(with(placed, "REGION", "[0.0, 0.0, 2.0, 1.0]"));
  CHECK_THAT(msg, Contains("scene.toml:9:"));
  CHECK_THAT(msg, Contains("species[0].placement.region"));
  CHECK_THAT(msg, Contains("outside the box"));
  msg = error_of(with(placed, "REGION", "[0.5, 0.0, 0.5, 1.0]"));
  CHECK_THAT(msg, Contains("species[0].placement.region"));
  CHECK_THAT(msg, Contains("is empty"));
  CHECK(load(with(placed, "REGION", "[0, 0.5, 1, 1]")).species[0].placement.region.y0 == 0.5);
}

TEST_CASE("scene loader: missing required keys", "[scene][errors]") {
  std::string msg = error_of(with(kBase, "radius = 0.01\n", ""));
  CHECK_THAT(msg, Contains("scene.toml:4:"));  // the [[species]] header
  CHECK_THAT(msg, Contains("species[0].radius (species 'gas'): missing"));

  msg = error_of(with(kBase, "count = 10\n", ""));
  CHECK_THAT(msg, Contains("species[0].count"));
  CHECK_THAT(msg, Contains("missing"));

  msg = error_of(with(kBase, "name = \"gas\"\n", ""));
  CHECK_THAT(msg, Contains("scene.toml:4:"));
  CHECK_THAT(msg, Contains("species[0].name: missing"));

  msg = error_of(with(kBase, "speed = 1.0\n", ""));
  CHECK_THAT(msg, Contains("scene.toml:8:"));
  CHECK_THAT(msg, Contains("species[0].velocity.speed"));

  msg = error_of(with(kBase, "radius = 0.01", "radius = 0.01\n[species.placement]\nkind = \"explicit\""));
  CHECK_THAT(msg, Contains("scene.toml:8:"));
  CHECK_THAT(msg, Contains("species[0].placement.positions (species 'gas'): missing"));

  msg = error_of(kBase + "[[actions]]\nkind = \"reverse_velocities\"\n");
  CHECK_THAT(msg, Contains("scene.toml:13:"));
  CHECK_THAT(msg, Contains("actions[0].time: missing"));
}

TEST_CASE("scene loader: no species, no stop condition", "[scene][errors]") {
  std::string msg = error_of("seed = 1\n[stop]\ntime = 1.0\n");
  CHECK_THAT(msg, Contains("scene.toml: error: species: the scene has no species"));
  msg = error_of(with(kBase, "[stop]\ntime = 1.0\n", ""));
  CHECK_THAT(msg, Contains("error: stop: no stop condition"));
  msg = error_of(with(kBase, "time = 1.0\n", ""));
  CHECK_THAT(msg, Contains("scene.toml:11:"));
  CHECK_THAT(msg, Contains("stop: no stop condition"));
}

TEST_CASE("scene loader: integers are range-checked", "[scene][errors]") {
  std::string msg = error_of(with(kBase, "seed = 42", "seed = -1"));
  CHECK_THAT(msg, Contains("scene.toml:1:"));
  CHECK_THAT(msg, Contains("seed: must be >= 0"));
  msg = error_of(with(kBase, "time = 1.0", "events = -5"));
  CHECK_THAT(msg, Contains("scene.toml:12:"));
  CHECK_THAT(msg, Contains("stop.events: must be >= 1"));
  msg = error_of(with(kBase, "time = 1.0", "events = 1e30"));
  CHECK_THAT(msg, Contains("stop.events: expected an integer, got 1e+30"));
  msg = error_of(with(kBase, "count = 10", "count = 9223372036854775807"));
  CHECK_THAT(msg, Contains("species[0].count"));
  CHECK(load(with(kBase, "seed = 42", "seed = 9223372036854775807")).seed == 9223372036854775807u);
  CHECK(load(with(kBase, "count = 10", "count = 1e3")).species[0].count == 1000);
}

TEST_CASE("scene loader: more than 10^8 disks in total is refused", "[scene][errors]") {
  const std::string two = with(kBase, "count = 10", "count = 60000000") + R"([[species]]
name = "more"
count = 50000000
radius = 0.0001
)";
  const std::string msg = error_of(two);
  CHECK_THAT(msg, Contains("scene.toml:15:"));
  CHECK_THAT(msg, Contains("species[1].count (species 'more')"));
  CHECK_THAT(msg, Contains("110000000 disks in all, more than the limit of 100000000"));
  CHECK_THAT(msg, Contains("memory"));
}

TEST_CASE("scene loader: list lengths must match the count", "[scene][errors]") {
  const std::string explicit_pair = with(kBase, "count = 10", "count = 3") + "";
  std::string msg = error_of(
      with(explicit_pair, "radius = 0.01",
           "radius = 0.01\n[species.placement]\nkind = \"explicit\"\npositions = [[0.2, 0.2], [0.5, 0.5]]"));
  CHECK_THAT(msg, Contains("scene.toml:6:"));
  CHECK_THAT(msg, Contains("species[0].count"));
  CHECK_THAT(msg, Contains("lists 2"));

  msg =
      error_of(with(with(kBase, "kind = \"speed\"", "kind = \"list\""), "speed = 1.0", "values = [[1, 0]]"));
  CHECK_THAT(msg, Contains("scene.toml:10:"));
  CHECK_THAT(msg, Contains("species[0].velocity.values"));
  CHECK_THAT(msg, Contains("10 disks"));

  msg = error_of(
      with(with(kBase, "kind = \"speed\"", "kind = \"list\""), "speed = 1.0", "values = [[1, 0], [1]]"));
  CHECK_THAT(msg, Contains("species[0].velocity.values[1]"));
}

TEST_CASE("scene loader: duplicate species names", "[scene][errors]") {
  const std::string msg = error_of(kBase + "[[species]]\nname = \"gas\"\ncount = 1\nradius = 0.01\n");
  CHECK_THAT(msg, Contains("scene.toml:14:"));
  CHECK_THAT(msg, Contains("species[1].name"));
  CHECK_THAT(msg, Contains("duplicate species name 'gas'"));
  CHECK_THAT(error_of(with(kBase, "\"gas\"", "\"g as\"")), Contains("invalid character ' '"));
  CHECK_THAT(error_of(with(kBase, "\"gas\"", "\"\"")), Contains("species[0].name: the name is empty"));
}

TEST_CASE("scene loader: keys of another kind are errors", "[scene][errors]") {
  std::string msg = error_of(with(kBase, "speed = 1.0", "speed = 1.0\nvector = [1, 0]"));
  CHECK_THAT(msg, Contains("scene.toml:11:"));
  CHECK_THAT(msg, Contains("species[0].velocity.vector (species 'gas'): not used with kind = \"speed\""));
  msg = error_of(
      with(kBase, "[species.velocity]", "[species.placement]\nlattice = \"square\"\n[species.velocity]"));
  CHECK_THAT(msg, Contains("scene.toml:9:"));
  CHECK_THAT(msg, Contains("species[0].placement.lattice (species 'gas'): not used with kind = \"random\""));
  msg = error_of(
      with(kBase, "[species.velocity]", "[species.placement]\npacking_fraction = 0.3\n[species.velocity]"));
  CHECK_THAT(msg, Contains("species[0].radius"));
  CHECK_THAT(msg, Contains("packing fraction sets the radius"));
  msg = error_of(
      with(kBase, "[species.velocity]", "[species.placement]\npacking_fraction = 0.95\n[species.velocity]"));
  CHECK_THAT(msg, Contains("species[0].placement.packing_fraction (species 'gas'): must be in (0, 0.9069]"));
  msg = error_of(with(kBase, "[species.velocity]",
                      "[species.placement]\nkind = \"lattice\"\nsampling = \"free-voxels\"\n[species.velocity]"));
  CHECK_THAT(msg, Contains("species[0].placement.sampling (species 'gas'): not used with kind = \"lattice\""));
  msg = error_of(with(kBase, "[species.velocity]", "[species.placement]\nsampling = \"voxels\"\n[species.velocity]"));
  CHECK_THAT(msg, Contains("species[0].placement.sampling"));
  CHECK_THAT(msg, Contains("free-voxels"));
  msg = error_of(with(kBase, "count = 10", "count = 10\nmass = 1\ndensity = 2"));
  CHECK_THAT(msg, Contains("species[0].density (species 'gas'): both mass and density"));
}

TEST_CASE("scene loader: explicit positions must lie inside the box", "[scene][errors]") {
  const std::string text = with(
      kBase, "radius = 0.01",
      "radius = 0.1\n[species.placement]\nkind = \"explicit\"\npositions = [[0.5, 0.5],\n  [0.95, 0.5]]");
  std::string msg = error_of(with(text, "count = 10\n", ""));
  CHECK_THAT(msg, Contains("scene.toml:10:"));
  CHECK_THAT(msg, Contains("species[0].placement.positions[1]"));
  CHECK_THAT(msg, Contains("outside the box"));
  const Scene periodic = load(with(with(text, "count = 10\n", ""), "size = [1.0, 1.0]",
                                   "size = [1.0, 1.0]\nboundary = \"periodic\""));
  CHECK(periodic.species[0].count == 2);
}

TEST_CASE("scene loader: overrides of scalars, arrays, strings and bare words", "[scene][override]") {
  const Scene s = load(kBase, {{"physics.restitution=0.5"},
                               {"box.size = [2.0, 3]"},
                               {"engine.scalar=float"},
                               {"box.boundary=periodic"},
                               {"seed=5"},
                               {"species[0].velocity.speed=2"}});
  CHECK(s.physics.restitution == 0.5);
  CHECK(s.lx == 2.0);
  CHECK(s.ly == 3.0);
  CHECK(s.scalar == ede::ScalarKind::Float);
  CHECK(s.boundary == ede::BoundaryKind::Periodic);
  CHECK(s.seed == 5);
  CHECK(s.species[0].velocity.speed == 2.0);
  CHECK(load(kBase, {{"engine.scalar=long double"}}).scalar == ede::ScalarKind::LongDouble);
  CHECK(load(kBase, {{"seed=1"}, {"seed=2"}}).seed == 2);  // in order: the last wins
}

TEST_CASE("scene loader: overrides select species by index and by name", "[scene][override]") {
  const std::string two = kBase + "[[species]]\nname = \"projectile\"\ncount = 1\nradius = 0.05\n";
  CHECK(load(two, {{"species[1].mass=25"}}).species[1].mass.value == 25.0);
  CHECK(load(two, {{"species.1.mass=25"}}).species[1].mass.value == 25.0);
  CHECK(load(two, {{"species.projectile.mass=25"}}).species[1].mass.value == 25.0);
  const Scene v = load(two, {{"species.projectile.velocity={kind=\"vector\", vector=[0,-5]}"}});
  CHECK(v.species[1].velocity.kind == ede::VelocityKind::Vector);
  CHECK(v.species[1].velocity.vector[1] == -5.0);
  const Scene p = load(two, {{"species.projectile.placement.kind=explicit"},
                             {"species.projectile.placement.positions=[[0.5,0.9]]"}});
  CHECK(p.species[1].placement.positions[0][1] == 0.9);
  CHECK(load(kBase + "[[actions]]\ntime = 1\nkind = \"reverse_velocities\"\n", {{"actions[0].time=0.5"}})
            .actions[0]
            .time == 0.5);
}

TEST_CASE("scene loader: overrides create missing tables", "[scene][override]") {
  const Scene s = load(
      kBase, {{"sampling.interval=0.1"}, {"species[0].placement.region=[0,0,0.5,0.5]"}, {"physics.tc=1e-3"}});
  CHECK(s.sample_interval == 0.1);
  CHECK(s.species[0].placement.region.x1 == 0.5);
  CHECK(s.physics.tc == 1e-3);
}

TEST_CASE("scene loader: override errors name the override", "[scene][override][errors]") {
  const std::string two = kBase + "[[species]]\nname = \"projectile\"\ncount = 1\nradius = 0.05\n";
  std::string msg = error_of(two, {{"seed=3"}, {"species[7].mass=3"}});
  CHECK_THAT(msg, Contains("scene.toml: error: --set #2 'species[7].mass=3': there is no species[7] "
                           "(the scene has 2 species: gas, projectile)"));
  msg = error_of(two, {{"species.bullet.mass=3"}});
  CHECK_THAT(msg, Contains("there is no species named 'bullet' (the scene has 2 species: gas, projectile)"));
  CHECK_THAT(error_of(kBase, {{"physics.restitution"}}),
             Contains("--set #1 'physics.restitution': missing '='"));
  CHECK_THAT(error_of(kBase, {{"=3"}}), Contains("empty key"));
  CHECK_THAT(error_of(kBase, {{"seed="}}), Contains("missing value"));
  CHECK_THAT(error_of(kBase, {{"a..b=1"}}), Contains("empty key"));
  CHECK_THAT(error_of(kBase, {{"species[x].mass=1"}}), Contains("bad element index"));
  CHECK_THAT(error_of(kBase, {{"seed.x=1"}}), Contains("'seed' is 42, not a table"));
  CHECK_THAT(error_of(kBase, {{"box[0]=1"}}), Contains("'box' is a table, not an array"));
  CHECK_THAT(error_of(kBase, {{"actions[0].time=1"}}),
             Contains("there is no actions[0] (the scene has no actions)"));
  CHECK_THAT(error_of(kBase, {{"box.size=[1,"}}), Contains("not valid TOML"));
}

TEST_CASE("scene loader: values set by an override are checked and blamed on it",
          "[scene][override][errors]") {
  std::string msg = error_of(kBase, {{"species.gas.radius=-1"}});
  CHECK_THAT(msg, Contains("scene.toml: error: species[0].radius (species 'gas'): must be > 0, got -1"));
  CHECK_THAT(msg, Contains("(set by --set #1 'species.gas.radius=-1')"));
  msg = error_of(kBase, {{"physics.restitushun=0.5"}});
  CHECK_THAT(msg, Contains("physics.restitushun: unknown key"));
  CHECK_THAT(msg, Contains("did you mean 'restitution'?"));
  CHECK_THAT(msg, Contains("--set #1"));
  msg = error_of(kBase, {{"stop.time=soon"}});
  CHECK_THAT(msg, Contains("stop.time: expected a number, got a string (set by --set #1 'stop.time=soon')"));
}

TEST_CASE("scene loader: the effective text reads back to the same scene", "[scene][override]") {
  const Scene s = load(kFull, {{"species.gas.count=7"},
                               {"sampling.interval=0.3"},
                               {"physics.tc=0.1"},
                               {"species[1].placement.region=[1.1, 0.1, 1.9, 0.9]"}});
  CHECK(s.species[0].count == 7);
  CHECK_THAT(s.source_text, Contains("# --set #1 'species.gas.count=7'"));
  const Scene again = load(s.source_text);
  CHECK(dump(again) == dump(s));
  CHECK(dump(load(load(kFull).source_text)) == dump(load(kFull)));
  const Scene irrational =
      load(kBase, {{"physics.restitution=0.1234567890123456789"}, {"stop.time=3.3333333333333335"}});
  CHECK(dump(load(irrational.source_text)) == dump(irrational));
}

TEST_CASE("scene loader: files", "[scene]") {
  auto missing = ede::load_scene_file("/nonexistent/scene.toml");
  REQUIRE_FALSE(missing.ok());
  CHECK_THAT(missing.error().message, Contains("/nonexistent/scene.toml: error: cannot find the scene file"));
  auto dir = ede::load_scene_file(EDE_SOURCE_DIR);
  REQUIRE_FALSE(dir.ok());
  CHECK_THAT(dir.error().message, Contains("directory"));
}

TEST_CASE("scene loader: every example scene loads", "[scene][examples]") {
  const std::filesystem::path root = std::filesystem::path(EDE_SOURCE_DIR) / "examples";
  int loaded = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".toml") continue;
    const std::string name = entry.path().filename().string();
    if (name.size() > 11 && name.compare(name.size() - 11, 11, ".sweep.toml") == 0) continue;  // ede-sweep's files
    INFO(entry.path().string());
    auto scene = ede::load_scene_file(entry.path().string());
    if (!scene) FAIL(scene.error().message);
    CHECK(scene.value().source_name == entry.path().string());
    CHECK(dump(load(scene.value().source_text)) == dump(scene.value()));
    ++loaded;
  }
  CHECK(loaded >= 9);
}

TEST_CASE("scene loader: every prefix and byte flip of a scene gives a scene or one error",
          "[scene][errors]") {
  // A cheap stand-in for the fuzzer: no crash, no exception, and every error says where it is.
  for (std::size_t n = 0; n <= kFull.size(); ++n) {
    auto result = ede::parse_scene_text(kFull.substr(0, n), "cut.toml");
    if (!result) CHECK_THAT(result.error().message, Contains("cut.toml"));
  }
  for (std::size_t i = 0; i < kFull.size(); i += 3) {
    for (char c : {'0', '-', '[', '"', '.', 'x', '\0', '\xff'}) {
      std::string text = kFull;
      text[i] = c;
      auto result = ede::parse_scene_text(text, "flip.toml");
      if (!result) CHECK_THAT(result.error().message, Contains("flip.toml"));
    }
  }
}
