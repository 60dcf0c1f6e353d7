// Thermostat events in the log (format version 3, schema/FORMAT.md): written only by runs with a
// thermostat, decoded exactly by the reader and by the reference reader, verified by a re-run, the same
// bytes for the same scene, the same bytes after an interrupted run is resumed, counted by kind, listed
// with their disk and new velocity, and refused by a conversion to a version that cannot hold them.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "ede/ede.hpp"
#include "reference_compare.hpp"
#include "scene_test_support.hpp"  // interrupted_and_resumed
#include "tool_runner.hpp"  // temp_path, read_file

using namespace ede;
using namespace ede::test;

namespace {

// Two species, one thermostatted by [thermostat], the other by its own table; inelastic pairs, walls;
// rebuilds (resumable keyframes) every 3000 events.
std::string scene_text(const std::string& scalar = "double", bool thermostat = true) {
  const std::string own = thermostat ? "[species.thermostat]\ntemperature = 2.0\nrate = 0.6\n" : "";
  const std::string all = thermostat ? "[thermostat]\ntemperature = 1.0\nrate = 0.3\nspecies = [\"small\"]\n" : "";
  return R"(seed = 5
[box]
size = [6.0, 6.0]
[physics]
restitution = 0.85
[engine]
scalar = ")" + scalar + R"("
rebuild_interval = 3000
[log]
chunk_events = 700
keyframe_interval = 2000
)" + all + R"([[species]]
name = "small"
count = 150
radius = 0.08
[species.velocity]
kind = "maxwell"
temperature = 0.5
[[species]]
name = "big"
count = 30
radius = 0.15
mass = 3.0
)" + own + R"([stop]
time = 40.0
)";
}

Scene scene(const std::string& scalar = "double") { return parse_scene_text(scene_text(scalar), "thermo.toml").value(); }

std::string run_to_log(const std::string& name, const std::string& scalar = "double") {
  const std::string path = temp_path(name);
  auto sim = Simulation::create(scene(scalar), {.log_path = path}).value();
  REQUIRE(sim.run() == RunStatus::ReachedTime);
  REQUIRE(sim.close());
  return path;
}

}  // namespace

TEST_CASE("thermostat log: version 3, exact against the reference reader, verified by a re-run", "[log][thermostat]") {
  for (const std::string scalar : {"double", "float", "long double"}) {
    INFO(scalar);
    const std::string path = run_to_log("thermo-" + std::to_string(scalar.size()) + ".ede", scalar);
    Log log = Log::open(path).value();
    CHECK(log.info().format_version == 3);
    const EventCounts counts = log.count_events().value();
    CHECK(counts.of(EventKind::Thermostat) > 1000);  // 150 x 0.3 + 30 x 0.6 = 63 per unit time, for 40
    CHECK(counts.of(EventKind::Thermostat) < 3500);
    check_exact_and_verified(path, scalar);
  }
}

TEST_CASE("thermostat log: each event names its disk and its new velocity, the state follows it", "[log][thermostat]") {
  const std::string path = run_to_log("thermo-events.ede");
  Log log = Log::open(path).value();
  std::size_t seen = 0;
  REQUIRE(log.for_each_event({}, [&](const Event& e) {
                if (e.kind != EventKind::Thermostat) return true;
                CHECK(e.j == -1);
                CHECK(e.i >= 0);
                const State after = log.state_at_event(e.index + 1).value();
                CHECK(after.vx[std::size_t(e.i)] == double(e.vix));
                CHECK(after.vy[std::size_t(e.i)] == double(e.viy));
                return ++seen < 20;
              }).ok());
  CHECK(seen == 20);
}

TEST_CASE("thermostat log: the same scene gives the same bytes, and an interrupted run resumes to them", "[log][thermostat][resume]") {
  const std::string whole = run_to_log("thermo-whole.ede"), again = run_to_log("thermo-again.ede");
  CHECK(read_file(whole) == read_file(again));
  CHECK(interrupted_and_resumed(scene(), "thermo-cut.ede", 25000) == read_file(whole));
}

TEST_CASE("thermostat log: a run without a thermostat still writes version 2, and version 3 cannot become 2", "[log][thermostat]") {
  const std::string plain = temp_path("thermo-plain.ede");
  const Scene without = parse_scene_text(scene_text("double", false), "plain.toml", {{"stop.time=2"}}).value();
  {
    auto sim = Simulation::create(without, {.log_path = plain}).value();
    REQUIRE(sim.run() == RunStatus::ReachedTime);
    REQUIRE(sim.close());
  }
  CHECK(Log::open(plain).value().info().format_version == 2);
  const std::string path = run_to_log("thermo-convert.ede");
  const auto refused = Log::open(path).value().convert(temp_path("thermo-v2.ede"), 2);
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().message.find("version 3") != std::string::npos);
  const std::string again = temp_path("thermo-v3.ede");
  REQUIRE(Log::open(path).value().convert(again, 3).ok());
  CHECK(Log::open(again).value().content_digest().value() == Log::open(path).value().content_digest().value());
}
