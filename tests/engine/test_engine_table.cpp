// The engine table (engine/engine_factory.hpp): which engine a run gets, which engines can run it, and the
// facts the table rests on: a Dissipative engine at xi = 1 computes bit for bit what an Elastic one does,
// and the TC model (its collision times, which keyframes store) follows the scene, not the engine type.
#include <catch2/catch.hpp>
#include <cstring>

#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

EngineOptions options(BoundaryKind boundary) {
  EngineOptions o = walls_until(1e9);
  o.boundary = boundary;
  o.stop.events = 30000;
  return o;
}

std::unique_ptr<EngineApi<double>> engine_as(EngineKind kind, const InitialState& s, const EngineOptions& o) {
  auto made = make_engine_as<double>(kind, s, o);
  if (!made) throw std::runtime_error(made.error().message);
  return std::move(made).value();
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_events(const std::vector<EventOutcome<double>>& a, const std::vector<EventOutcome<double>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const EventOutcome<double>&x = a[k], &y = b[k];
    if (x.kind != y.kind || x.i != y.i || x.j != y.j || x.tc_elastic != y.tc_elastic || !same_bits(x.time, y.time) ||
        !same_bits(x.vix, y.vix) || !same_bits(x.viy, y.viy) || !same_bits(x.vjx, y.vjx) || !same_bits(x.vjy, y.vjy))
      return false;
  }
  return true;
}

}  // namespace

TEST_CASE("engine table: each run gets the engine with the fewest effects that computes it", "[engine][table]") {
  EngineOptions o = options(BoundaryKind::Walls);
  CHECK(engine_kind_for(o) == EngineKind::WallsElastic);
  o.physics.tc = 1e-4;  // the TC model needs dissipation: an elastic scene's tc changes nothing
  CHECK(engine_kind_for(o) == EngineKind::WallsElastic);
  o.physics.wall_restitution = 0.9;
  CHECK(engine_kind_for(o) == EngineKind::WallsDissipative);
  o = options(BoundaryKind::Walls);
  o.physics.pairs.push_back({"a", "b", 0.5});
  CHECK(engine_kind_for(o) == EngineKind::WallsDissipative);
  o = options(BoundaryKind::Walls);
  o.physics.gravity = {0, -1};
  CHECK(engine_kind_for(o) == EngineKind::WallsGravity);
  o = options(BoundaryKind::Periodic);
  CHECK(engine_kind_for(o) == EngineKind::PeriodicElastic);
  o.physics.restitution = 0.5;
  CHECK(engine_kind_for(o) == EngineKind::PeriodicDissipative);

  // Any engine that computes a run may be named; the others refuse.
  const EngineOptions walls = options(BoundaryKind::Walls);
  EngineOptions dissipative = walls;
  dissipative.physics.restitution = 0.9;
  const InitialState s = lattice_gas(12, 0.015, 1.0, 3);
  for (const EngineKind k : {EngineKind::WallsElastic, EngineKind::WallsDissipative, EngineKind::WallsGravity})
    CHECK(make_engine_as<double>(k, s, walls).ok());
  CHECK_FALSE(make_engine_as<double>(EngineKind::PeriodicElastic, s, walls).ok());
  CHECK_FALSE(make_engine_as<double>(EngineKind::WallsElastic, s, dissipative).ok());
  const auto refused = make_engine_as<double>(EngineKind::PeriodicDissipative, s, dissipative);
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().message.find("walls, dissipative") != std::string::npos);
}

TEST_CASE("engine table: a dissipative engine at xi = 1 computes bit for bit what the elastic one does",
          "[engine][table]") {
  const InitialState s = lattice_gas(14, 0.012, 1.0, 5);
  const std::pair<BoundaryKind, EngineKind> cases[] = {{BoundaryKind::Walls, EngineKind::WallsDissipative},
                                                       {BoundaryKind::Periodic, EngineKind::PeriodicDissipative}};
  for (const auto& c : cases) {
    const EngineOptions o = options(c.first);
    auto elastic = engine(s, o);
    auto dissipative = engine_as(c.second, s, o);
    Recorder<double> re, rd;
    elastic->add_sink(&re);
    dissipative->add_sink(&rd);
    REQUIRE(elastic->run() == RunStatus::ReachedEvents);
    REQUIRE(dissipative->run() == RunStatus::ReachedEvents);
    CHECK(re.of_kind(EventKind::Pair).size() > 1000);
    CHECK(re.of_kind(EventKind::Wall).size() + re.of_kind(EventKind::Wrap).size() > 100);
    CHECK(same_events(re.events, rd.events));
    CHECK(elastic->effects() == dissipative->effects());
  }
}

TEST_CASE("engine table: the TC model follows the scene, not the engine type", "[engine][table]") {
  const InitialState s = lattice_gas(12, 0.015, 1.0, 8);
  EngineOptions o = options(BoundaryKind::Walls);
  o.physics.restitution = 0.9;
  auto no_tc = engine(s, o);  // dissipative, tc = 0: no collision times, no TC-elastic collision
  REQUIRE(no_tc->run() == RunStatus::ReachedEvents);
  CHECK(no_tc->particles().last_collision.empty());
  CHECK(no_tc->counts().tc_elastic == 0);
  CHECK(no_tc->effects().find("TC") == std::string::npos);
  o.physics.tc = 1e-2;
  auto tc = engine(s, o);
  REQUIRE(tc->run() == RunStatus::ReachedEvents);
  CHECK(tc->particles().last_collision.size() == s.size());
  CHECK(tc->counts().tc_elastic > 0);
  CHECK(tc->effects().find("TC (tc=0.01)") != std::string::npos);
  // An elastic scene with tc set under gravity runs the (dissipative) gravity engine: still no TC model.
  EngineOptions g = options(BoundaryKind::Walls);
  g.physics.tc = 1e-2;
  g.physics.gravity = {0, -1};
  auto gravity = engine(s, g);
  REQUIRE(gravity->run() == RunStatus::ReachedEvents);
  CHECK(gravity->particles().last_collision.empty());
  CHECK(gravity->counts().tc_elastic == 0);
  CHECK(gravity->effects().rfind("walls, elastic, gravity (0, -1)", 0) == 0);
}
