// The course's test cases, each exact: walls, pairs, restitution, energy, the scattering angle.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

TEST_CASE("course: a disk hits a wall head-on and comes straight back", "[course][wall]") {
  InitialState s = box();
  s.add(0.5, 0.5, 1.0, 0.0, 0.1, 1.0, 0);
  const RecordedRun run = run_recorded(s, walls_until(0.5));
  const auto& e = run.engine;
  const auto& rec = *run.recorder;
  REQUIRE(run.status == RunStatus::ReachedTime);
  REQUIRE(rec.events.size() == 1);
  const auto& hit = rec.events[0];
  CHECK(hit.kind == EventKind::Wall);
  CHECK(hit.j == kWallRight);
  CHECK(hit.time == Approx(0.4).epsilon(1e-15));
  CHECK(hit.vix == -1.0);
  CHECK(hit.viy == 0.0);
  CHECK(x_now(*e, 0) == Approx(0.8).epsilon(1e-15));
}

TEST_CASE("course: a disk hitting a wall at an angle obeys the law of reflection", "[course][wall]") {
  InitialState s = box();
  s.add(0.5, 0.5, 1.0, 0.5, 0.1, 1.0, 0);
  const RecordedRun run = run_recorded(s, walls_until(0.5));
  const auto& rec = *run.recorder;
  REQUIRE(rec.events.size() == 1);
  CHECK(rec.events[0].j == kWallRight);
  // Angle of incidence equals angle of reflection: the normal component flips, the tangential one stays.
  CHECK(rec.events[0].vix == -1.0);
  CHECK(rec.events[0].viy == 0.5);
}

TEST_CASE("course: v = [v0, v0] touches each wall once and returns to its start", "[course][wall]") {
  const double v0 = 1.0, r = 0.1;
  InitialState s = box();
  s.add(0.5, 0.3, v0, v0, r, 1.0, 0);
  // Bouncing between r and 1 - r takes 2 (1 - 2r) / v0 = 1.6 in each direction.
  const RecordedRun run = run_recorded(s, walls_until(1.6));
  const auto& e = run.engine;
  const auto& rec = *run.recorder;
  REQUIRE(run.status == RunStatus::ReachedTime);
  REQUIRE(rec.events.size() == 4);
  std::vector<int> walls;
  for (const auto& ev : rec.events) walls.push_back(ev.j);
  std::sort(walls.begin(), walls.end());
  CHECK(walls == std::vector<int>{kWallLeft, kWallRight, kWallBottom, kWallTop});
  CHECK(x_now(*e, 0) == Approx(0.5).margin(1e-15));
  CHECK(y_now(*e, 0) == Approx(0.3).margin(1e-15));
  CHECK(e->particles().disk[0].vx == v0);
  CHECK(e->particles().disk[0].vy == v0);
}

TEST_CASE("course: xi = 0 at a wall stops the disk there", "[course][wall][inelastic]") {
  InitialState s = box();
  s.add(0.5, 0.5, 1.0, 0.5, 0.1, 1.0, 0);
  EngineOptions o;
  o.stop.events = 100;
  o.physics.wall_restitution = 0;
  auto e = engine(s, o);
  // After the hit nothing moves, so nothing will ever happen again (with no stop time to wait for).
  REQUIRE(e->run() == RunStatus::NoMoreEvents);
  CHECK(e->counts().of(EventKind::Wall) == 1);
  CHECK(e->particles().disk[0].vx == 0.0);
  CHECK(e->particles().disk[0].vy == 0.0);  // the course's rule damps the tangential part too
  CHECK(x_now(*e, 0) == Approx(0.9).epsilon(1e-15));
  CHECK(e->effects().find("inelastic") != std::string::npos);
}

TEST_CASE("course: two equal disks head-on bounce straight back", "[course][pair]") {
  // Binary-exact numbers (r = 1/8, centres 1/4 and 3/4) make the velocities exact in floating point.
  InitialState s = box();
  s.add(0.25, 0.5, 1.0, 0.0, 0.125, 1.0, 0);
  s.add(0.75, 0.5, -1.0, 0.0, 0.125, 1.0, 0);
  const RecordedRun run = run_recorded(s, walls_until(0.2));
  const auto& rec = *run.recorder;
  REQUIRE(rec.events.size() == 1);
  const auto& c = rec.events[0];
  CHECK(c.kind == EventKind::Pair);
  CHECK(c.time == Approx(0.125).epsilon(1e-15));
  CHECK(c.vix == -1.0);
  CHECK(c.viy == 0.0);
  CHECK(c.vjx == 1.0);
  CHECK(c.vjy == 0.0);
}

TEST_CASE("course: at impact parameter (r1+r2)/sqrt(2) equal disks leave at right angles", "[course][pair]") {
  const double r = 0.05, b = 2 * r / std::sqrt(2.0);
  InitialState s = box();
  s.add(0.2, 0.5, 1.0, 0.0, r, 1.0, 0);
  s.add(0.6, 0.5 + b, 0.0, 0.0, r, 1.0, 0);
  const RecordedRun run = run_recorded(s, walls_until(0.35));
  const auto& rec = *run.recorder;
  const auto pairs = rec.of_kind(EventKind::Pair);
  REQUIRE(pairs.size() == 1);
  const auto& c = pairs[0];
  const double dot = c.vix * c.vjx + c.viy * c.vjy;
  CHECK(dot == Approx(0).margin(1e-15));
  CHECK(std::hypot(c.vix, c.viy) == Approx(1 / std::sqrt(2.0)).epsilon(1e-14));
  CHECK(std::hypot(c.vjx, c.vjy) == Approx(1 / std::sqrt(2.0)).epsilon(1e-14));
  // The struck disk leaves along the line of centres, 45 degrees up; the other 45 degrees down.
  CHECK(std::atan2(c.vjy, c.vjx) == Approx(M_PI / 4).epsilon(1e-14));
  CHECK(std::atan2(c.viy, c.vix) == Approx(-M_PI / 4).epsilon(1e-14));
}

TEST_CASE("course: xi = 0 head-on leaves both equal disks at rest", "[course][pair][inelastic]") {
  InitialState s = box();
  s.add(0.3, 0.5, 1.0, 0.0, 0.1, 1.0, 0);
  s.add(0.7, 0.5, -1.0, 0.0, 0.1, 1.0, 0);
  EngineOptions o;
  o.stop.events = 100;
  o.physics.restitution = 0;
  auto e = engine(s, o);
  REQUIRE(e->run() == RunStatus::NoMoreEvents);
  CHECK(e->counts().of(EventKind::Pair) == 1);
  for (int i = 0; i < 2; ++i) {
    CHECK(e->particles().disk[i].vx == 0.0);
    CHECK(e->particles().disk[i].vy == 0.0);
  }
}

TEST_CASE("course: total energy is constant for xi = 1 with many disks", "[course][energy]") {
  // 900 disks, ~10^5 collisions. Each elastic collision conserves the pair's energy up to a few roundings
  // of its terms (~1e-16 of the pair's energy, ~2/N of the total), so even added up linearly over 10^5
  // collisions the relative change stays below ~1e-15 * ... ; we allow 1e-13, far above round-off and
  // far below any real error (one missed or wrong collision changes the energy by ~1e-3).
  for (BoundaryKind bc : {BoundaryKind::Walls, BoundaryKind::Periodic}) {
    InitialState s = lattice_gas(30, 0.01, 1.0, 7);
    EngineOptions o;
    o.boundary = bc;
    o.stop.events = 150000;
    auto e = engine(s, o);
    const double e0 = e->initial_kinetic_energy();
    REQUIRE(e->run() == RunStatus::ReachedEvents);
    REQUIRE(e->counts().of(EventKind::Pair) > 50000);
    CHECK(std::abs(kinetic_energy(e->particles()) - e0) / e0 < 1e-13);
    CHECK(e->check_invariants(1e-9) == "");
    if (bc == BoundaryKind::Periodic) {  // no walls: momentum is conserved too
      double px0 = 0, py0 = 0, px = 0, py = 0;
      for (std::size_t i = 0; i < s.size(); ++i) px0 += s.mass[i] * s.vx[i], py0 += s.mass[i] * s.vy[i];
      momentum(e->particles(), px, py);
      CHECK(std::abs(px - px0) < 1e-12);
      CHECK(std::abs(py - py0) < 1e-12);
    }
  }
}

TEST_CASE("course: scattering angle of a light disk off a heavy one", "[course][pair]") {
  // r = 0.001, m = 1 against R = 0.1, m = 1e6 at rest: theta(b) = pi - 2 asin(b / R12) for an infinitely
  // heavy target. The finite mass ratio mu = 1e-6 shifts the laboratory angle by at most ~mu (tan theta_lab
  // = sin theta_cm / (cos theta_cm + mu)), so 1e-5 rad is a tolerance the physics allows and a wrong
  // formula (e.g. a missing factor 2, or the textbook root failing) exceeds by orders of magnitude.
  const double r = 0.001, R = 0.1, r12 = r + R;
  for (int k = 0; k < 20; ++k) {
    const double b = r12 * (k + 0.5) / 20;
    InitialState s = box();
    s.add(0.5, 0.5, 0.0, 0.0, R, 1e6, 0);
    s.add(0.2, 0.5 + b, 1.0, 0.0, r, 1.0, 0);
    const auto pairs = run_recorded(s, walls_until(0.3)).pairs();
    REQUIRE(pairs.size() == 1);
    const auto& c = pairs[0];
    const double vx = c.i == 1 ? c.vix : c.vjx, vy = c.i == 1 ? c.viy : c.vjy;
    const double theta = std::atan2(vy, vx);
    INFO("b / R12 = " << b / r12);
    CHECK(theta == Approx(M_PI - 2 * std::asin(b / r12)).margin(1e-5));
  }
}
