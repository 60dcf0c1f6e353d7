// Schedules in collisions per disk (Scene::actions[].collisions_per_disk, Scene::sample_collisions): the
// action and the samples happen right after the pair collision that brings the pair count P to
// ceil(c N / 2), at its time; the action is logged like a time action and replayed exactly (verify), and
// the reversal then retraces the run (the state at twice the reversal's time is the start, reversed).
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/ede.hpp"
#include "engine_test_support.hpp"
#include "public_log_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

const std::string kGas = gas_toml(200, 0.01, "collisions_per_particle = 7", "", "periodic");

}  // namespace

TEST_CASE("a reversal after 3 collisions per disk happens right after pair collision ceil(3 N / 2), logged and replayed exactly",
          "[run][collision_schedule]") {
  const Log log = public_log(kGas + "\n[[actions]]\ncollisions_per_disk = 3\nkind = \"reverse_velocities\"\n",
                             "schedule-reverse.ede");
  const auto events = log.events({}).value();
  std::uint64_t pairs = 0;
  std::size_t action = events.size();
  for (std::size_t k = 0; k < events.size(); ++k) {
    if (events[k].kind == EventKind::Pair) ++pairs;
    if (events[k].kind == EventKind::Action) {
      CHECK(action == events.size());  // one action
      action = k;
      CHECK(pairs == 300);             // ceil(3 * 200 / 2)
      REQUIRE(k > 0);
      CHECK(events[k - 1].kind == EventKind::Pair);  // right after the 300th pair collision
      CHECK(events[k - 1].time == events[k].time);   // at its time
    }
  }
  REQUIRE(action < events.size());
  CHECK(pairs == 700);  // stop at 7 collisions per disk: after the retrace, which has 2 x 300
  // Replay is exact: verify reruns the scene and compares every event.
  const VerifyReport v = log.verify().value();
  INFO(v.text);
  CHECK(v.identical);
  // Time reversal: at twice the reversal's time the disks are back where they started (to round-off).
  const double t_rev = double(events[action].time);
  REQUIRE(double(log.info().end_time) >= 2 * t_rev);
  {
    const State s0 = log.state_at(0).value(), back = log.state_at(2 * t_rev).value();
    double worst = 0;
    for (std::size_t i = 0; i < s0.size(); ++i) {
      double dx = std::fabs(back.x[i] - s0.x[i]), dy = std::fabs(back.y[i] - s0.y[i]);
      dx = std::min(dx, 1 - dx), dy = std::min(dy, 1 - dy);
      worst = std::max({worst, dx, dy});
    }
    CHECK(worst < 1e-6);
  }
}

TEST_CASE("samples every 0.5 collisions per disk follow pair collisions ceil(k N / 4)", "[run][collision_schedule]") {
  InitialState s = box();
  for (int k = 0; k < 100; ++k)
    s.add(0.05 + 0.1 * (k % 10), 0.05 + 0.1 * (k / 10), std::cos(k * 1.3), std::sin(k * 1.3), 0.02, 1.0, 0);
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.collisions_per_particle = 4;
  o.sample_collisions = 0.5;
  Recorder<double> rec;
  auto e = engine(s, o);
  e->add_sink(&rec);
  CHECK(e->run() == RunStatus::ReachedCollisions);
  // The k-th sample follows pair collision ceil(k * 0.5 * 100 / 2) = 25 k, at its time.
  std::vector<double> expected;
  std::uint64_t pairs = 0;
  for (const auto& ev : rec.events)
    if (ev.kind == EventKind::Pair && ++pairs % 25 == 0) expected.push_back(ev.time);
  REQUIRE(expected.size() == 8);
  // The last (k = 8, P = 200) is the stop itself: the run ends at that collision, the sample was taken first.
  REQUIRE(rec.sample_times.size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) CHECK(rec.sample_times[k] == expected[k]);
}

TEST_CASE("a scene mixing actions by time and by collisions per disk is refused, naming the fix", "[scene][collision_schedule]") {
  auto scene = parse_scene_text(kGas + "\n[[actions]]\ntime = 1.0\nkind = \"reverse_velocities\"\n"
                                       "[[actions]]\ncollisions_per_disk = 2\nkind = \"reverse_velocities\"\n",
                                "mixed.toml");
  REQUIRE_FALSE(scene);
  CHECK_THAT(scene.error().message, Catch::Contains("actions[1]") && Catch::Contains("every action a collisions_per_disk"));
  auto both = parse_scene_text(kGas + "\n[sampling]\ninterval = 0.1\ncollisions_per_disk = 2\n", "both.toml");
  REQUIRE_FALSE(both);
  CHECK_THAT(both.error().message, Catch::Contains("keep one of interval and collisions_per_disk"));
}
