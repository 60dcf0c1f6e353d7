// A live run's scene (run/live_schedule.cpp): the overrides that make a scene a live run, and a reversal of
// time as an action joined to the scene's own schedule. The live run itself (ede/live_run.hpp) is driven
// over HTTP by the ede-view tests (tests/tools/view).
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/ede.hpp"
#include "run/live_schedule.hpp"

using namespace ede;

namespace {

Scene scene_of(const std::string& extra) {
  return parse_scene_text("seed = 1\n[box]\nsize = [1.0, 1.0]\n[[species]]\nname = \"gas\"\ncount = 10\n"
                          "radius = 0.01\n[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n" + extra,
                          "live.toml")
      .value();
}

}  // namespace

TEST_CASE("a reversal by collisions per disk fires right after the pair collision it names", "[run][live]") {
  // The engine fires an action at c collisions per disk after pair collision ceil(c n / 2), computed in
  // double: the c chosen must give exactly the pair asked for, for every pair count and odd or even n.
  for (const std::size_t n : {3u, 10u, 1000u, 99991u})
    for (std::uint64_t pairs = 1; pairs < 2000; pairs += 7) {
      const double c = collisions_per_disk_for(pairs, n);
      INFO("n = " << n << ", pairs = " << pairs << ", c = " << c);
      REQUIRE(std::uint64_t(std::ceil(c * double(n) / 2)) == pairs);
    }
}

TEST_CASE("reversals join the scene's schedule, by time or by collisions per disk", "[run][live]") {
  const Scene by_time = scene_of("[stop]\ntime = 1.0\n[[actions]]\ntime = 0.5\nkind = \"reverse_velocities\"\n");
  CHECK_FALSE(actions_by_collisions(by_time));
  CHECK(actions_override(by_time, {0.25, 0.75}, {}, 10).text ==
        "actions=[{time=0.25,kind=\"reverse_velocities\"},{time=0.5,kind=\"reverse_velocities\"},"
        "{time=0.75,kind=\"reverse_velocities\"}]");
  const Scene by_collisions =
      scene_of("[stop]\ntime = 1.0\n[[actions]]\ncollisions_per_disk = 2.0\nkind = \"reverse_velocities\"\n");
  REQUIRE(actions_by_collisions(by_collisions));
  // Times are ignored in a schedule by collisions: the pair count (5 of 10 disks: c = 1) is what counts.
  CHECK(actions_override(by_collisions, {0.25}, {5}, 10).text ==
        "actions=[{collisions_per_disk=1,kind=\"reverse_velocities\"},"
        "{collisions_per_disk=2,kind=\"reverse_velocities\"}]");
}

TEST_CASE("a reversal that cannot be scheduled says why", "[run][live]") {
  const Scene by_time = scene_of("[stop]\ntime = 1.0\n");
  CHECK(cannot_reverse(by_time, 0.0, 0).find("must be after t = 0") != std::string::npos);
  CHECK(cannot_reverse(by_time, 0.1, 0).empty());
  const Scene by_collisions =
      scene_of("[stop]\ntime = 1.0\n[[actions]]\ncollisions_per_disk = 2.0\nkind = \"reverse_velocities\"\n");
  CHECK(cannot_reverse(by_collisions, 0.3, 0).find("there has been none yet") != std::string::npos);
  CHECK(cannot_reverse(by_collisions, 0.3, 1).empty());
}

TEST_CASE("a live scene stops at its time, with its other stops lifted and small log chunks", "[run][live]") {
  const Scene base = scene_of("[stop]\nevents = 100\ncollisions_per_particle = 3.0\n");
  LiveRunSetup setup;
  setup.until = 2.5;
  setup.overrides = {"physics.restitution=0.9"};
  std::vector<std::string> texts;
  for (const Override& o : live_overrides(base, setup)) texts.push_back(o.text);
  CHECK(texts == std::vector<std::string>{"physics.restitution=0.9", "stop.time=2.5", "log.chunk_events=1024",
                                          "stop.collisions_per_particle=1000000000000000",
                                          "stop.events=1000000000000000000"});
}
