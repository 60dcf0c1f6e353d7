// Gravity and restitution per pair of species and per wall: closed-form flights, conservation, replay.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "ede/scene.hpp"
#include "engine/engine_core.hpp"
#include "log_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

EngineOptions under_gravity(double g, double t_end) {
  EngineOptions o = walls_until(t_end);
  o.physics.gravity = {0.0, -g};
  return o;
}

// Kinetic plus potential energy (zero at y = 0) at the engine's time.
double mechanical_energy(const EngineApi<double>& e) {
  const Particles<double>& p = e.particles();
  const double t = e.time();
  long double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double vx = p.vx_at(i, t), vy = p.vy_at(i, t);
    sum += 0.5L * p.mass(i) * (vx * vx + vy * vy) - (long double)p.mass(i) * p.gy * p.y_at(i, t);
  }
  return double(sum);
}

}  // namespace

TEST_CASE("gravity: a dropped disk hits the floor at sqrt(2h/g) with speed sqrt(2gh)", "[gravity]") {
  const double g = 2.0, r = 0.05, h = 0.5;  // the disk's bottom is h above the floor
  InitialState s = box();
  s.add(0.5, r + h, 0.0, 0.0, r, 1.0, 0);
  const double t_hit = std::sqrt(2 * h / g);
  const RecordedRun run = run_recorded(s, under_gravity(g, 2 * t_hit));
  const auto walls = run.recorder->of_kind(EventKind::Wall);
  REQUIRE(walls.size() == 1);
  const auto& hit = walls[0];
  CHECK(hit.kind == EventKind::Wall);
  CHECK(hit.j == kWallBottom);
  CHECK(hit.time == Approx(t_hit).epsilon(1e-14));
  CHECK(hit.viy0 == Approx(-std::sqrt(2 * g * h)).epsilon(1e-14));
  CHECK(hit.viy == Approx(std::sqrt(2 * g * h)).epsilon(1e-14));
  // Back at its start height, at rest, after twice the fall time.
  CHECK(y_now(*run.engine, 0) == Approx(r + h).epsilon(1e-14));
  CHECK(run.engine->particles().vy_at(0, run.engine->time()) == Approx(0).margin(1e-14));
}

TEST_CASE("gravity: an elastic ball keeps bouncing to the same height", "[gravity]") {
  InitialState s = box();
  s.add(0.5, 0.6, 0.3, 0.0, 0.05, 1.0, 0);  // also moving sideways: it bounces off the side walls too
  auto e = engine(s, under_gravity(1.0, 40.0));
  const double e0 = mechanical_energy(*e);
  REQUIRE(e->run() == RunStatus::ReachedTime);
  CHECK(e->counts().of(EventKind::Wall) > 30);
  CHECK(std::abs(mechanical_energy(*e) - e0) / e0 < 1e-13);
  CHECK(e->check_invariants(1e-12) == "");
}

TEST_CASE("gravity: a projectile lands where the parabola says", "[gravity]") {
  const double g = 1.0, r = 0.01, x0 = 0.1, y0 = 0.2, vx = 0.4, vy = 0.6;
  InitialState s = box();
  s.add(x0, y0, vx, vy, r, 1.0, 0);
  const RecordedRun run = run_recorded(s, under_gravity(g, 3.0));
  const auto walls = run.recorder->of_kind(EventKind::Wall);
  REQUIRE_FALSE(walls.empty());
  const auto& land = walls[0];
  REQUIRE(land.j == kWallBottom);
  // y0 + vy t - g t^2 / 2 = r
  const double t = (vy + std::sqrt(vy * vy + 2 * g * (y0 - r))) / g;
  CHECK(land.time == Approx(t).epsilon(1e-14));
  CHECK(land.i == 0);
  const RecordedRun at_landing = run_recorded(s, under_gravity(g, t));
  CHECK(x_now(*at_landing.engine, 0) == Approx(x0 + vx * t).epsilon(1e-14));
}

TEST_CASE("gravity: two disks falling together collide as in their falling frame", "[gravity]") {
  InitialState s = box();
  s.add(0.25, 0.8, 1.0, 0.0, 0.125, 1.0, 0);
  s.add(0.75, 0.8, -1.0, 0.0, 0.125, 1.0, 0);
  const RecordedRun run = run_recorded(s, under_gravity(1.0, 0.2));
  const auto pairs = run.pairs();
  REQUIRE(pairs.size() == 1);
  CHECK(pairs[0].time == Approx(0.125).epsilon(1e-14));  // the same as without gravity
  CHECK(pairs[0].vix == Approx(-1.0).epsilon(1e-14));
  CHECK(pairs[0].viy == Approx(-0.125).epsilon(1e-13));  // the fall so far, g t
}

TEST_CASE("gravity: an elastic gas conserves kinetic plus potential energy, its log replays exactly", "[gravity][log]") {
  const InitialState s = lattice_gas(20, 0.008, 1.0, 41);
  EngineOptions o = under_gravity(3.0, 1e9);
  o.stop.events = 150000;
  o.stop.time.reset();
  o.sample_interval = 0.05;
  o.rebuild_interval = 20000;
  LogSettings small;
  small.chunk_events = 1000;
  small.keyframe_interval = 7000;
  const LoggedRun<double> run = run_logged<double>(s, o, "gravity-gas.ede", small);
  REQUIRE(run.status == RunStatus::ReachedEvents);
  CHECK(run.engine->effects().find("gravity") != std::string::npos);
  CHECK(run.engine->check_invariants(1e-9) == "");
  // The gas has fallen: kinetic energy grew from 200 at the start, potential energy fell.
  auto e = engine(s, o);
  const double e0 = mechanical_energy(*e);
  e->run();
  CHECK(std::abs(mechanical_energy(*e) - e0) / std::abs(e0) < 1e-11);
  // Replay at every sample and at the end: bit for bit, positions and velocities at the sample time.
  auto replay = replay_of<double>(run.path);
  for (std::size_t k = 0; k < run.recorder->sample_times.size(); k += 7) {
    const double t = run.recorder->sample_times[k];
    REQUIRE(replay->seek_time(t));
    for (std::size_t i = 0; i < s.size(); ++i) {
      REQUIRE(replay->particles().x_at(i, t) == run.recorder->sample_states[k][i].x);
      REQUIRE(replay->particles().y_at(i, t) == run.recorder->sample_states[k][i].y);
    }
  }
  REQUIRE(replay->seek_time(replay->final_time()));
  for (std::size_t i = 0; i < s.size(); ++i) {
    REQUIRE(std::memcmp(&replay->particles().disk[i], &run.engine->particles().disk[i], 5 * sizeof(double)) == 0);
  }
}

TEST_CASE("gravity: time reversal brings a falling gas back", "[gravity][action]") {
  const InitialState s = lattice_gas(8, 0.02, 1.0, 42);
  EngineOptions o = under_gravity(2.0, 0.3);
  o.actions.push_back({0.15, ActionKind::ReverseVelocities});
  auto e = engine(s, o);
  REQUIRE(e->run() == RunStatus::ReachedTime);
  CHECK(e->counts().collisions() > 10);
  for (std::size_t i = 0; i < s.size(); ++i) {
    CHECK(x_now(*e, i) == Approx(s.x[i]).margin(1e-9));
    CHECK(y_now(*e, i) == Approx(s.y[i]).margin(1e-9));
  }
}

TEST_CASE("gravity: an inelastic bed with TC settles without stalling", "[gravity][inelastic]") {
  const InitialState s = lattice_gas(15, 0.015, 1.0, 43);
  EngineOptions o = under_gravity(1.0, 3.0);
  o.physics.restitution = 0.5;
  o.physics.wall_restitution = 0.5;
  o.physics.tc = 1e-3;
  auto e = engine(s, o);
  REQUIRE(e->run() == RunStatus::ReachedTime);
  CHECK(e->check_invariants(1e-6) == "");
  CHECK(kinetic_energy(e->particles(), e->time()) < 0.01 * e->initial_kinetic_energy());  // settled
  double highest = 0;
  for (std::size_t i = 0; i < s.size(); ++i) highest = std::max(highest, y_now(*e, i));
  CHECK(highest < 0.6);  // 225 disks of radius 0.015 on a unit floor: a few layers, well below 0.6
}

TEST_CASE("gravity: disks at rest exactly on cell sides fall through them", "[gravity]") {
  // Regression: a disk at rest on a cell's lower side crossed into the cell below at once, and from there
  // "crossed" back up (the touch of s = 0, u = 0 pushed inwards counted as a crossing), forever at t = 0.
  // Found with the projectile of examples/crater-gravity.toml at y = 1.8 = 36 cells of 0.05.
  InitialState s = box();
  for (int k = 0; k < 100; ++k) s.add(0.005 + 0.01 * k, 0.95, 0.0, 0.0, 0.004, 1.0, 0);  // sets the grid
  std::vector<std::size_t> on_sides;
  for (int k = 1; k <= 4; ++k) {  // small disks on the sides of cells 1..4, heights set below
    on_sides.push_back(s.size());
    s.add(0.1 * k, 0.0, 0.0, 0.0, 0.002, 1.0, 0);
  }
  on_sides.push_back(s.size());  // a big disk (outside the cell lists) on a side too, as the projectile
  s.add(0.7, 0.0, 0.0, 0.0, 0.05, 1.0, 0);
  const GridShape shape = engine_grid_for(s, false, Algorithm::Cells);  // depends on the count, not on y
  REQUIRE(shape.split.big_radius < 0.05);  // the big disk is kept out of the cell lists
  REQUIRE(shape.ny >= 8);
  const double wy = 1.0 / double(shape.ny);
  for (std::size_t k = 0; k < on_sides.size(); ++k) s.y[on_sides[k]] = double(k + 1) * wy;
  s.y[on_sides.back()] = double(shape.ny / 2) * wy;
  const double fall = 0.5 * wy;  // the distance each disk drops in the run
  // Dropped from rest under g = 1, each falls 0.5 wy by t = sqrt(wy).
  auto e = engine(s, under_gravity(1.0, std::sqrt(wy)));
  REQUIRE(e->run() == RunStatus::ReachedTime);
  CHECK(e->counts().of(EventKind::Cell) < 100);
  for (std::size_t i : on_sides) CHECK(y_now(*e, i) == Approx(s.y[i] - fall).epsilon(1e-12));
  CHECK(e->check_invariants(1e-12) == "");
}

TEST_CASE("gravity: a ball bouncing to rest without TC stalls with a message that says why", "[gravity][inelastic]") {
  // xi_w = 0.5: the bounces shorten geometrically and add up to a finite time (a Zeno sequence); the run
  // must end with Stalled and a message about resting contact and the TC model, not hang or sink.
  InitialState s = box();
  s.add(0.5, 0.3, 0.0, 0.0, 0.05, 1.0, 0);
  EngineOptions o = under_gravity(1.0, 100.0);
  o.physics.wall_restitution = 0.5;
  o.stall_limit = 1000;
  auto e = engine(s, o);
  REQUIRE(e->run() == RunStatus::Stalled);
  CHECK(e->stall_message().find("resting contact") != std::string::npos);
  CHECK(e->stall_message().find("physics.tc") != std::string::npos);
  const double h = 0.25, t_rest = std::sqrt(2 * h) * (1 + 2 * 0.5 / (1 - 0.5));  // drop, then 2 t_k per bounce
  CHECK(e->time() == Approx(t_rest).epsilon(1e-6));
  CHECK(y_now(*e, 0) >= 0.05 * (1 - 1e-12));
}

TEST_CASE("gravity: scenes refuse it with a periodic box or a kinetic-energy stop", "[gravity][scene]") {
  const auto bad_periodic = parse_scene_text(
      "[box]\nboundary = \"periodic\"\n[physics]\ngravity = [0, -1]\n[[species]]\nname = \"a\"\ncount = 3\n"
      "radius = 0.01\n[stop]\ntime = 1\n",
      "g.toml");
  REQUIRE_FALSE(bad_periodic.ok());
  CHECK(bad_periodic.error().message.find("gravity needs walls") != std::string::npos);
  const auto bad_stop = parse_scene_text(
      "[physics]\ngravity = [0, -1]\n[[species]]\nname = \"a\"\ncount = 3\nradius = 0.01\n[stop]\n"
      "energy_fraction = 0.1\n",
      "g.toml");
  REQUIRE_FALSE(bad_stop.ok());
  CHECK(bad_stop.error().message.find("g.toml:8") != std::string::npos);
}

TEST_CASE("restitution per pair of species and per wall", "[inelastic][scene]") {
  // Species a and b: a-b collisions perfectly inelastic, a-a elastic; the bottom wall stops, the others bounce.
  InitialState s = box();
  s.species_names = {"a", "b"};
  s.add(0.25, 0.5, 1.0, 0.0, 0.125, 1.0, 0);
  s.add(0.75, 0.5, -1.0, 0.0, 0.125, 1.0, 1);
  EngineOptions o;
  o.stop.events = 100;
  o.physics.pairs.push_back({"a", "b", 0.0});
  auto e = engine(s, o);
  CHECK(e->effects().find("1 species pairs apart") != std::string::npos);
  REQUIRE(e->run() == RunStatus::NoMoreEvents);
  CHECK(e->particles().disk[0].vx == 0.0);  // a-b: both stopped
  CHECK(e->particles().disk[1].vx == 0.0);

  s.species = {0, 0};  // now both a: elastic, they bounce off each other and the side walls
  EngineOptions walls;
  walls.stop.events = 3;
  walls.physics.pairs.push_back({"a", "b", 0.0});
  walls.physics.walls[kBottomWall] = 0.0;
  auto aa = engine(s, walls);
  aa->run();
  CHECK(aa->particles().disk[0].vx == Approx(-1.0).epsilon(1e-14));

  InitialState drop = box();
  drop.add(0.5, 0.5, 0.3, -1.0, 0.1, 1.0, 0);
  EngineOptions floor_only = walls_until(0.45);  // the floor at t = 0.4, the right wall not before 1.33
  floor_only.physics.walls[kBottomWall] = 0.0;
  auto d = engine(drop, floor_only);
  d->run();
  CHECK(d->particles().disk[0].vy == 0.0);  // the course's rule at the inelastic floor: (xi vx, -xi vy)
  CHECK(d->particles().disk[0].vx == 0.0);

  const auto scene = parse_scene_text(
      "[physics]\nwall_restitution = { bottom = 0.5 }\n[[physics.pairs]]\nspecies = [\"a\", \"b\"]\n"
      "restitution = 0.3\n[[species]]\nname = \"a\"\ncount = 3\nradius = 0.01\n[[species]]\nname = \"b\"\n"
      "count = 3\nradius = 0.01\n[stop]\ntime = 1\n",
      "pairs.toml");
  REQUIRE(scene.ok());
  CHECK(scene.value().physics.wall(kBottomWall) == 0.5);
  CHECK(scene.value().physics.wall(kLeftWall) == 1.0);
  CHECK(scene.value().physics.pairs.size() == 1);
  CHECK_FALSE(scene.value().physics.elastic());
  const auto unknown = parse_scene_text(
      "[[physics.pairs]]\nspecies = [\"a\", \"c\"]\nrestitution = 0.3\n[[species]]\nname = \"a\"\ncount = 3\n"
      "radius = 0.01\n[stop]\ntime = 1\n",
      "pairs.toml");
  REQUIRE_FALSE(unknown.ok());
  CHECK(unknown.error().message.find("no species 'c'") != std::string::npos);
}
