// Log::verify (run/verify.cpp): the re-run planned the one way every run is (run/run_plan.hpp). The other
// verify tests (identical logs, every kind of difference, damage, cut-short logs) are in
// tests/replay/test_log.cpp with the rest of the public Log.
#include <catch2/catch.hpp>

#include "ede/ede.hpp"
#include "scene_test_support.hpp"  // run_to_log

using ede::test::run_to_log;

TEST_CASE("verify re-runs a log started from a spinning state with its spins", "[run][verify]") {
  // A rough source: after its events the disks spin. The continuation's scene names no roughness, so
  // only its starting state's spins make its run rough; a re-run that dropped them (as verify did before
  // it planned runs with plan_run_from) ran smooth and found event 1 different.
  const std::string rough = "seed = 18\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n[physics]\n"
                            "roughness = 0.4\n[[species]]\nname = \"grains\"\ncount = 300\nradius = 0.01\n"
                            "[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n[stop]\nevents = 3000\n";
  const std::string source = run_to_log(ede::parse_scene_text(rough, "rough.toml").value(), "verify-rough.ede");
  const std::string smooth = "seed = 3\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n[start]\nfrom = \"" +
                             source + "\"\n[stop]\nevents = 3000\n";
  const std::string path =
      run_to_log(ede::parse_scene_text(smooth, "smooth.toml").value(), "verify-smooth-from-rough.ede");
  const ede::Log log = ede::Log::open(path).value();
  REQUIRE(log.info().rotates);
  const ede::State start = log.state_at_event(0).value();
  bool spinning = false;
  for (std::size_t i = 0; i < start.omega.size(); ++i) spinning = spinning || start.omega[i] != 0;
  REQUIRE(spinning);
  const ede::VerifyReport r = log.verify().value();
  INFO(r.text);
  CHECK(r.identical);
  CHECK_FALSE(r.partial);
  CHECK(r.events_compared == log.info().events);
}
