// Format version 3 (schema/FORMAT.md, "Format version 3: step events"): a square-well run writes version 3
// and its log replays to the engine's state bit for bit, with its step events listed; verify passes; a run
// interrupted and resumed writes the same bytes as an uninterrupted one (the pair depths are derived again
// at the rebuild point: engine/step_table.hpp); a hard-disk run still writes version 2; and a version 3
// log is not converted to a version without step events.
#include <catch2/catch.hpp>

#include "ede/ede.hpp"
#include "tool_runner.hpp"  // temp_path, read_file

using ede::test::read_file;
using ede::test::temp_path;

namespace {

// 150 disks in a periodic box with a shoulder inside a well; rebuilds (resume points) every 997 events.
const std::string kWellGas = R"(seed = 9
[box]
size = [1.0, 1.0]
boundary = "periodic"
[[physics.steps]]
radius = [0.025, 0.035]
energy = [0.5, -1.0]
[engine]
rebuild_interval = 997
[log]
chunk_events = 400
keyframe_interval = 1200
[[species]]
name = "gas"
count = 150
radius = 0.01
[species.velocity]
kind = "maxwell"
temperature = 0.7
[stop]
events = 30000
)";

ede::Scene well_gas(const std::vector<ede::Override>& overrides = {}) {
  return ede::parse_scene_text(kWellGas, "well-gas", overrides).value();
}

}  // namespace

TEST_CASE("steps: a square-well log is format version 3 and replays the engine's state exactly", "[log][steps]") {
  const std::string path = temp_path("steps-v3.ede");
  auto sim = ede::Simulation::create(well_gas(), {.log_path = path}).value();
  REQUIRE(sim.run() == ede::RunStatus::ReachedEvents);
  const ede::State end = sim.state();
  const ede::RunSummary summary = sim.summary();
  REQUIRE(sim.close());
  CHECK(summary.counts.of(ede::EventKind::Step) > 1000);
  CHECK(summary.stepped);
  CHECK(summary.potential_final < 0);

  auto log = ede::Log::open(path).value();
  CHECK(log.info().format_version == 3);
  const ede::State replayed = log.state_at_end().value();
  REQUIRE(replayed.size() == end.size());
  for (std::size_t i = 0; i < end.size(); ++i) {
    CHECK(replayed.x.values<double>()[i] == end.x.values<double>()[i]);
    CHECK(replayed.vy.values<double>()[i] == end.vy.values<double>()[i]);
  }
  std::uint64_t steps = 0;
  REQUIRE(log.for_each_event({}, [&](const ede::Event& e) {
    if (e.kind != ede::EventKind::Step) return true;
    ++steps;
    CHECK(e.i < e.j);
    // The impulse acts along the line of centres: momentum is kept (equal masses).
    CHECK(double(e.vix + e.vjx) == Approx(double(e.vix_before + e.vjx_before)).margin(1e-12));
    return true;
  }));
  CHECK(steps == summary.counts.of(ede::EventKind::Step));
  const ede::VerifyReport v = log.verify().value();
  CHECK(v.identical);
  CHECK(v.resumable_checked > 0);
}

TEST_CASE("steps: an interrupted square-well run resumes to the bytes of an uninterrupted one", "[log][steps][resume]") {
  const std::string whole = temp_path("steps-whole.ede"), cut = temp_path("steps-cut.ede");
  {
    auto sim = ede::Simulation::create(well_gas(), {.log_path = whole}).value();
    REQUIRE(sim.run() == ede::RunStatus::ReachedEvents);
  }
  {
    auto sim = ede::Simulation::create(well_gas(), {.log_path = cut}).value();
    REQUIRE(sim.run(12000) == ede::RunStatus::Running);
    sim.interrupt();
    REQUIRE(sim.close());
    REQUIRE(sim.log_kept().value().resumable);
  }
  auto resumed = ede::Simulation::resume(cut).value();
  REQUIRE(resumed.run() == ede::RunStatus::ReachedEvents);
  REQUIRE(resumed.close());
  CHECK(read_file(cut) == read_file(whole));
}

TEST_CASE("steps: hard disks still write version 2, and a version 3 log keeps its version", "[log][steps]") {
  const std::string hard = temp_path("steps-none.ede"), stepped = temp_path("steps-convert.ede");
  {
    std::string text = kWellGas;
    text.erase(text.find("[[physics.steps]]"), text.find("[engine]") - text.find("[[physics.steps]]"));
    const ede::Scene scene = ede::parse_scene_text(text, "hard-gas").value();
    auto sim = ede::Simulation::create(scene, {.log_path = hard}).value();
    sim.run();
    REQUIRE(sim.close());
  }
  CHECK(ede::Log::open(hard).value().info().format_version == 2);
  {
    auto sim = ede::Simulation::create(well_gas({{"stop.events=3000"}}), {.log_path = stepped}).value();
    sim.run();
    REQUIRE(sim.close());
  }
  auto log = ede::Log::open(stepped).value();
  for (std::uint32_t version : {1u, 2u}) {
    const ede::Status s = log.convert(temp_path("steps-converted.ede"), version);
    REQUIRE_FALSE(s);
    CHECK(s.error().message.find("keep version 3") != std::string::npos);
  }
}
