// What the engine vouches for to the log (engine_core.hpp, "what the engine vouches for"; EventOutcome's
// v2_time_exact and v2_velocities_exact): the writer codes those residuals as 0 without computing them, so a
// wrong vouch would make a log decode wrongly. Checked here:
//   - the writer's check (log.check_exactness, ede-sim --check-exactness) catches a vouch that is wrong;
//   - every example scene, shortened, runs with the check and writes the same bytes as without it;
//   - where nothing is vouched for, the writer predicts from the records the event carries.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "log/event_coder.hpp"
#include "log/event_predictions.hpp"
#include "tool_runner.hpp"

using namespace ede;
using namespace ede::test;

namespace {

// Two disks of radius 0.1 in a walled unit box, i at rest at (0.3, 0.5) since t = 0, j at (0.6, 0.5) since
// t = 0.1 moving left at speed 1: they touch when j is at 0.5, at t = 0.2.
struct TwoDisks {
  EventPhysics<double> physics = EventPhysics<double>::box(1.0, 1.0, false, 0.0, 0.0);
  Particles<double> p;
  EventOutcome<double> pair;
  TwoDisks() {
    physics.one_plus_xi = {2.0};
    p.disk.assign(2, Disk<double>{});
    p.disk[0].x = 0.3, p.disk[0].y = 0.5, p.disk[0].r = 0.1;
    p.disk[1].x = 0.6, p.disk[1].y = 0.5, p.disk[1].vx = -1, p.disk[1].t = 0.1, p.disk[1].r = 0.1;
    p.set_masses({1.0, 1.0});
    p.set_species({0, 0});
    pair.kind = EventKind::Pair, pair.i = 0, pair.j = 1;
    pair.before_i = record_before(p.disk[0]), pair.before_j = record_before(p.disk[1]);
    pair.time = predict_pair_time(physics, pair.before_i, pair.before_j);
    // The elastic head-on rule exchanges the velocities.
    pair.vix = -1, pair.viy = 0, pair.vjx = 0, pair.vjy = 0;
  }
};

}  // namespace

TEST_CASE("the writer predicts what the engine does not vouch for, from the records the event carries", "[log][exactness]") {
  TwoDisks s;
  REQUIRE(s.pair.time == Approx(0.2));
  EventCoder<double> coder(s.physics, 2, false);
  const CodedEvent<double> c = coder.code(s.pair, s.p);
  CHECK(c.predicted_time == s.pair.time);
  CHECK_FALSE(c.velocities_predicted);  // not vouched for: coded against the prediction
  CHECK(c.pv[0] == -1.0);
  CHECK(c.pv[2] == 0.0);
  CHECK(coder.mismatch().empty());
}

TEST_CASE("a wrong vouch is caught by the writer's check, and trusted without it", "[log][exactness]") {
  TwoDisks s;
  s.pair.v2_time_exact = true;
  s.pair.v2_velocities_exact = true;
  s.pair.time = std::nextafter(s.pair.time, 1.0);  // one ulp later than the format predicts
  EventCoder<double> trusting(s.physics, 2, false);
  const CodedEvent<double> c = trusting.code(s.pair, s.p);
  CHECK(c.predicted_time == s.pair.time);  // the residual would be coded as 0: the log would be wrong
  CHECK(c.velocities_predicted);
  EventCoder<double> checking(s.physics, 2, true);
  checking.code(s.pair, s.p);
  CHECK_THAT(checking.mismatch(), Catch::Contains("vouched for its time"));

  TwoDisks v;
  v.pair.v2_time_exact = v.pair.v2_velocities_exact = true;
  v.pair.vix = -0.5;  // not what the rule gives
  EventCoder<double> velocities(v.physics, 2, true);
  velocities.code(v.pair, v.p);
  CHECK_THAT(velocities.mismatch(), Catch::Contains("vouched for its velocities"));
}

TEST_CASE("every example scene runs with the writer checking each vouch, and writes the same log", "[log][exactness][tool][slow]") {
  std::vector<std::string> scenes;
  for (const char* dir : {"examples", "examples/scenes", "examples/rough", "examples/dense"})
    for (const auto& f : std::filesystem::directory_iterator(source_path(dir)))
      if (f.path().extension() == ".toml") scenes.push_back(f.path().string());
  REQUIRE(scenes.size() >= 25);
  int checked = 0;
  for (const std::string& scene : scenes) {
    const std::string plain = temp_path("exact-plain.ede"), checked_log = temp_path("exact-checked.ede");
    const std::string args = scene + " -q --set stop.events=20000";
    const ToolRun a = run_tool("ede-sim", args + " -o " + plain, "exact-plain", 300);
    const ToolRun b = run_tool("ede-sim", args + " --check-exactness -o " + checked_log, "exact-checked", 300);
    INFO(scene << "\n" << b.err);
    CHECK(a.status == b.status);
    if (a.status != 0) continue;  // a scene that needs a log of its own first ([start]): same refusal
    CHECK(b.err.find("vouched") == std::string::npos);
    CHECK(read_file(plain) == read_file(checked_log));
    ++checked;
  }
  CHECK(checked >= 20);
}
