// Simulation::finish (a run ended by its program at the current time, with a complete log that verifies
// and replays to the exact state there) and Simulation::impulses (the running wall and virial sums a live
// pressure monitor takes differences of, against ede/pressure.hpp's sums over the same window of the log).
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/ede.hpp"
#include "scene_test_support.hpp"
#include "tool_runner.hpp"  // temp_path

using ede::test::temp_path;

namespace {

// The shared test gas (scene_test_support.hpp), with a few overrides.
ede::Scene gas(const std::vector<ede::Override>& overrides = {}) {
  return ede::parse_scene_text(ede::test::logged_gas("11", "50.0").text(), "finish-test", overrides).value();
}

void check_same_state(const ede::State& a, const ede::State& b) {
  REQUIRE(a.size() == b.size());
  CHECK(a.time == b.time);
  bool same = true;
  for (std::size_t i = 0; i < a.size(); ++i)
    same = same && a.x.values<double>()[i] == b.x.values<double>()[i] &&
           a.y.values<double>()[i] == b.y.values<double>()[i] && a.vx.values<double>()[i] == b.vx.values<double>()[i] &&
           a.vy.values<double>()[i] == b.vy.values<double>()[i];
  CHECK(same);
}

}  // namespace

TEST_CASE("Simulation::finish ends a run early with a complete log that verifies", "[run][simulation][finish]") {
  // Stopped by an event budget (mid-chunk, at an event's time) and by advance_to (between events).
  for (const bool by_time : {false, true}) {
    INFO("stopped by " << (by_time ? "advance_to" : "run(n)"));
    const std::string path = temp_path(by_time ? "finish-time.ede" : "finish-events.ede");
    auto sim = ede::Simulation::create(gas(), {.log_path = path}).value();
    if (by_time)
      REQUIRE(sim.advance_to(0.8372).value() == ede::RunStatus::Running);
    else
      REQUIRE(sim.run(10000 + 517) == ede::RunStatus::Running);
    const ede::Time t = sim.time();
    REQUIRE(sim.finish());
    const ede::State here = sim.state();  // the state finish() left, at t
    CHECK(here.time == t);
    CHECK(sim.run() == ede::RunStatus::EndedByProgram);  // finished: runs nothing more
    CHECK(sim.state().events == here.events);
    const ede::EventCounts counts = sim.counts();

    auto log = ede::Log::open(path).value();
    CHECK(log.info().complete);
    CHECK(log.info().final_status == "ended by its program (Simulation::finish)");
    CHECK(log.info().end_time == t);
    // Every event is in the log (cell crossings are never logged), not only the complete chunks of 1024.
    CHECK(log.info().events == counts.events() - counts.of(ede::EventKind::Cell));
    CHECK(log.info().events % 1024 != 0);
    check_same_state(log.state_at_end().value(), here);
    check_same_state(log.state_at(t).value(), here);
    const ede::VerifyReport v = log.verify().value();
    INFO(v.text);
    CHECK(v.identical);
    CHECK_FALSE(v.partial);
    CHECK(v.events_compared == log.info().events);
    CHECK(sim.finish());  // idempotent
  }
}

TEST_CASE("Simulation::finish on a run that already ended changes nothing", "[run][simulation][finish]") {
  const std::string path = temp_path("finish-ended.ede");
  auto sim = ede::Simulation::create(gas({{"stop.time=0.5"}}), {.log_path = path}).value();
  REQUIRE(sim.run() == ede::RunStatus::ReachedTime);
  REQUIRE(sim.finish());
  auto log = ede::Log::open(path).value();
  CHECK(log.info().final_status == "reached stop.time");
  CHECK(log.verify().value().identical);
}

TEST_CASE("Simulation::impulses equal the pressure pass's sums over the same window", "[run][simulation][pressure]") {
  for (const char* boundary : {"walls", "periodic"}) {
    INFO(boundary);
    const std::string path = temp_path(std::string("impulses-") + boundary + ".ede");
    ede::SimulationOptions o;
    o.log_path = path;
    o.impulses = true;
    auto sim = ede::Simulation::create(gas({{std::string("box.boundary=\"") + boundary + "\""}, {"stop.time=3.0"}}), o)
                   .value();
    REQUIRE(sim.advance_to(1.0).value() == ede::RunStatus::Running);
    const ede::ImpulseSums a = sim.impulses();
    REQUIRE(sim.run() == ede::RunStatus::ReachedTime);
    const ede::ImpulseSums b = sim.impulses();
    REQUIRE(sim.close());
    CHECK(a.time == 1.0);
    CHECK(b.time == 3.0);
    ede::PressureOptions po;
    po.from = 1.0, po.to = 3.0, po.blocks = 4, po.bins_per_block = 4;
    const ede::PressureReport r = ede::measure_pressure(ede::Log::open(path).value(), po).value();
    // The same impulses summed in the same order: equal up to the rounding of the two long double sums
    // and their differences (relative 1e-12; a lost or doubled event would be ~1e-3).
    CHECK(b.pair_collisions - a.pair_collisions == r.totals.pair_collisions);
    CHECK(b.wall_collisions - a.wall_collisions == r.totals.wall_collisions);
    CHECK(b.virial - a.virial == Approx(r.totals.virial_sum).epsilon(1e-12));
    CHECK(r.totals.virial_sum > 0);
    for (std::size_t w = 0; w < 4; ++w) CHECK(b.wall[w] - a.wall[w] == Approx(r.totals.wall_impulse[w]).epsilon(1e-12));
    if (std::string(boundary) == "walls") CHECK(r.totals.wall_impulse[0] > 0);
  }
  // Off by default: nothing is summed.
  auto plain = ede::Simulation::create(gas({{"stop.time=0.2"}})).value();
  plain.run();
  CHECK(plain.impulses().pair_collisions == 0);
  CHECK(plain.impulses().virial == 0);
}
