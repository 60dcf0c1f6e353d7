// engine/stall_text.hpp: a stalled run's message names the cause that applies. An elastic run cannot
// collapse: its stall is the clock's resolution (a float run under strong gravity), and the TC model is
// not its remedy; an inelastic run's stall is collapse, and the TC model is.
#include <catch2/catch.hpp>

#include "text_support.hpp"

#include "engine/stall_text.hpp"

TEST_CASE("an elastic stall names the clock's resolution, not inelastic collapse", "[engine][stall]") {
  ede::StallFacts f;
  f.time = 0.11, f.same_time_events = 1000001, f.elastic = true, f.gravity = true, f.scalar = "float";
  f.epsilon = 1.1920928955078125e-07;
  const std::string m = ede::stall_text(f);
  INFO(m);
  CHECK(contains(m, "the simulation stalled at t = 0.11: 1000001 consecutive events without time advancing"));
  CHECK(contains(m, "not inelastic collapse (every collision of this run is elastic)"));
  CHECK(contains(m, "with engine.scalar = \"float\" the clock at t = 0.11 moves in steps of about 1.3"));
  CHECK(contains(m, "hits it every 2 v / g"));
  CHECK(contains(m, "Fix: use a wider scalar type"));
  CHECK_FALSE(contains(m, "TC"));
  f.gravity = false;
  CHECK_FALSE(contains(ede::stall_text(f), "gravity"));
}

TEST_CASE("an inelastic stall names collapse and the TC model", "[engine][stall]") {
  ede::StallFacts f;
  f.time = 2, f.same_time_events = 10, f.elastic = false;
  CHECK(contains(ede::stall_text(f), "(inelastic collapse). Enable the TC model (physics.tc > 0"));
  f.tc_model = true, f.tc = 1e-6, f.gravity = true;
  const std::string m = ede::stall_text(f);
  CHECK(contains(m, "resting contact is not a state an event-driven run can reach"));
  CHECK(contains(m, "Increase physics.tc (now 1e-06) so that settled disks keep hopping"));
}
