// Starting a run from a state ([start], run/run_start.cpp): from a log at a time, from a CSV state, zero
// momentum, reversal, the provenance the new log records, and the errors.
// Comparisons: a continued run is not bit-identical to the longer run it continues (the longer run keeps
// each disk's (x, v, t_last) and drifts from t_last; the continuation starts from positions rounded at the
// start time), so the tests compare what determinism allows: the same sequence of events (kind, disks),
// event times and positions within 1e-7 after ~5 collisions per disk (round-off ~1e-16 amplified by chaos;
// measured: 7e-9 and 8e-9).
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "ede/ede.hpp"
#include "setup/setup_from_csv.hpp"
#include "scene_test_support.hpp"  // GasToml, run_to_log
#include "tool_runner.hpp"  // temp_path, read_file

using ede::test::run_to_log;
using ede::test::temp_path;

namespace {

const std::string kGas = ede::test::GasToml{}.text();  // 400 disks, r = 0.01, speed 1, t = 1

double max_position_difference(const ede::State& a, const ede::State& b) {
  REQUIRE(a.size() == b.size());
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max({d, std::abs(a.x[i] - b.x[i]), std::abs(a.y[i] - b.y[i])});
  return d;
}

}  // namespace

TEST_CASE("a run continued from its own final state follows the longer run", "[run][start]") {
  const std::string a = run_to_log(ede::parse_scene_text(kGas, "gas").value(), "start-a.ede");
  const std::string longer =
      run_to_log(ede::parse_scene_text(kGas, "gas", {{"stop.time=1.25"}}).value(), "start-longer.ede");
  const ede::Scene cont = ede::continuation_scene(a, std::nullopt, {{"stop.time=0.25"}}).value();
  REQUIRE(cont.start);
  CHECK(cont.species.empty());
  const std::string c = run_to_log(cont, "start-c.ede");

  const ede::Log la = ede::Log::open(a).value(), ll = ede::Log::open(longer).value(), lc = ede::Log::open(c).value();
  // Provenance: the source log's content digest and the time, in the new log's scene text.
  const std::string digest = la.content_digest().value();
  CHECK(lc.info().scene_text.find("digest = \"" + digest + "\"") != std::string::npos);
  CHECK(lc.info().scene_text.find("at = 1") != std::string::npos);
  CHECK(lc.scene().value().start->digest == digest);
  // The state at the start is the source's state at its end, exactly.
  const ede::State s0 = lc.state_at(0).value(), end_a = la.state_at_end().value();
  CHECK(max_position_difference(s0, end_a) == 0);
  for (std::size_t i = 0; i < s0.size(); ++i) REQUIRE((s0.vx[i] == end_a.vx[i] && s0.vy[i] == end_a.vy[i]));
  // The same events after t = 1, in the same order, at the same times up to round-off.
  const auto tail = ll.events({.from_time = ede::Time(1.0)}).value();
  const auto ev = lc.events({}).value();
  REQUIRE(ev.size() > 300);
  REQUIRE(tail.size() >= ev.size());
  std::size_t same = 0;
  double max_dt = 0;
  for (std::size_t k = 0; k < ev.size(); ++k) {
    if (ev[k].kind != tail[k].kind || ev[k].i != tail[k].i || ev[k].j != tail[k].j) break;
    max_dt = std::max(max_dt, std::abs(double(ev[k].time + 1.0L - tail[k].time)));
    ++same;
  }
  INFO("largest event time difference " << max_dt);
  CHECK(same == ev.size());
  CHECK(max_dt < 1e-7);
  const double dx = max_position_difference(lc.state_at_end().value(), ll.state_at_end().value());
  INFO("max position difference after 0.25 time units: " << dx);
  CHECK(dx < 1e-7);
  // The continued log verifies (rerun from the state it starts with; the source is not needed).
  CHECK(lc.verify().value().identical);
}

TEST_CASE("a run reversed from its final state returns close to its start", "[run][start]") {
  const std::string a = run_to_log(ede::parse_scene_text(kGas, "gas", {{"stop.time=0.2"}}).value(), "rev-a.ede");
  // ~5 collisions per disk each way: few enough for double round-off, amplified by chaos, to stay small
  // (examples/time-reversal.toml: double fails after ~15).
  const ede::Scene back =
      ede::continuation_scene(a, std::nullopt, {{"stop.time=0.2"}, {"start.reverse_velocities=true"}}).value();
  const std::string c = run_to_log(back, "rev-c.ede");
  const ede::State start = ede::Log::open(a).value().state_at(0).value();
  const ede::State returned = ede::Log::open(c).value().state_at_end().value();
  const double dx = max_position_difference(start, returned);
  double dv = 0;
  for (std::size_t i = 0; i < start.size(); ++i)
    dv = std::max({dv, std::abs(start.vx[i] + returned.vx[i]), std::abs(start.vy[i] + returned.vy[i])});
  INFO("return error: positions " << dx << ", velocities " << dv);
  CHECK(dx < 1e-8);  // measured 4e-11 and 3e-9 (velocities amplify round-off more)
  CHECK(dv < 1e-7);
}

TEST_CASE("a run starts from a CSV state exactly, with zero total momentum when asked", "[run][start]") {
  const std::string a = run_to_log(ede::parse_scene_text(kGas, "gas", {{"stop.time=0.2"}}).value(), "csv-a.ede");
  const ede::State mid = ede::Log::open(a).value().state_at(0.1L).value();
  const std::string csv = temp_path("csv-state.csv");
  REQUIRE(ede::write_state_csv(csv, mid));
  const std::string text = std::string(R"([box]
size = [1.0, 1.0]
[start]
csv = ")") + csv + R"("
[stop]
time = 0.1
)";
  auto sim = ede::Simulation::create(ede::parse_scene_text(text, "<csv>").value()).value();
  const ede::State s = sim.state();
  CHECK(max_position_difference(s, mid) == 0);
  for (std::size_t i = 0; i < s.size(); ++i) REQUIRE((s.vx[i] == mid.vx[i] && s.vy[i] == mid.vy[i]));
  CHECK(sim.scene().source_text.find("digest = \"xxh3-128:") != std::string::npos);

  auto zero = ede::Simulation::create(ede::parse_scene_text(text, "<csv>", {{"start.zero_momentum=true"}}).value()).value();
  const ede::State z = zero.state();
  double px = 0, py = 0, p_scale = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    px += z.mass[i] * z.vx[i], py += z.mass[i] * z.vy[i];
    p_scale += z.mass[i] * std::hypot(mid.vx[i], mid.vy[i]);
  }
  CHECK(std::hypot(px, py) < 1e-14 * p_scale);
  zero.run();
  const ede::RunSummary sum = zero.summary();
  CHECK(sum.energy_final > 0);
}

TEST_CASE("bad starts are refused with the file, the line and the fix", "[run][start]") {
  SECTION("a CSV with a bad number names the line and the column") {
    auto r = ede::parse_state_csv("id,species,x,y,vx,vy,radius,mass\n0,gas,0.5,0.5,1,0,0.01,1\n1,gas,0.2,abc,0,0,0.01,1\n",
                                  "state.csv");
    REQUIRE(!r);
    CHECK(r.error().message.find("state.csv:3:") == 0);
    CHECK(r.error().message.find("column 'y'") != std::string::npos);
    CHECK(r.error().message.find("Fix:") != std::string::npos);
  }
  SECTION("a CSV without the header") {
    auto r = ede::parse_state_csv("0,gas,0.5,0.5,1,0,0.01,1\n", "s.csv");
    REQUIRE(!r);
    CHECK(r.error().message.find("s.csv:1:") == 0);
  }
  SECTION("ids out of order, a short row, a radius of zero") {
    CHECK(ede::parse_state_csv("id,species,x,y,vx,vy,radius,mass\n1,gas,0.5,0.5,1,0,0.01,1\n", "s").error().message.find("s:2:") == 0);
    CHECK(ede::parse_state_csv("id,species,x,y,vx,vy,radius,mass\n0,gas,0.5,0.5,1\n", "s").error().message.find("fields") != std::string::npos);
    CHECK(ede::parse_state_csv("id,species,x,y,vx,vy,radius,mass\n0,gas,0.5,0.5,1,0,0,1\n", "s").error().message.find("radius") != std::string::npos);
  }
  SECTION("a scene with [start] and [[species]], or neither source") {
    auto both = ede::parse_scene_text(std::string(kGas) + "[start]\ncsv = \"x.csv\"\n", "s.toml");
    REQUIRE(!both);
    CHECK(both.error().message.find("no [[species]]") != std::string::npos);
    auto none = ede::parse_scene_text("[start]\nzero_momentum = true\n[stop]\ntime = 1\n", "s.toml");
    REQUIRE(!none);
    CHECK(none.error().message.find("neither from nor csv") != std::string::npos);
  }
  SECTION("a source log that is not the one recorded") {
    const std::string a = run_to_log(ede::parse_scene_text(kGas, "gas", {{"stop.time=0.05"}}).value(), "digest-a.ede");
    auto scene = ede::continuation_scene(a, std::nullopt, {{"start.digest=\"xxh3-128:00\""}}).value();
    auto sim = ede::Simulation::create(scene);
    REQUIRE(!sim);
    CHECK(sim.error().message.find("not the source this run started from") != std::string::npos);
  }
  SECTION("a time outside the log") {
    const std::string a = run_to_log(ede::parse_scene_text(kGas, "gas", {{"stop.time=0.05"}}).value(), "at-a.ede");
    auto sim = ede::Simulation::create(ede::continuation_scene(a, 7.0).value());
    REQUIRE(!sim);
    CHECK(sim.error().message.find("outside the log") != std::string::npos);
  }
}
