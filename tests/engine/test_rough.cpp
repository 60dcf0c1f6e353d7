// Rough disks (engine/collide.hpp collide_pair_tangential and collide_wall_tangential, the Rough engines):
// exact collisions with known spins after them, beta = -1 bit for bit the smooth engines, energy kept for
// beta = +-1 with xi = 1, and equipartition between translation and rotation in a rough elastic gas.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "core/energy.hpp"
#include "engine/collide.hpp"
#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// r = 1/16, m = 1, I = m r^2 / 2 = 1/512: every product below is exact in binary.
constexpr double kR = 1.0 / 16;

InitialState two_disks(double w0) {
  InitialState s = box();
  s.add(0.3, 0.5, 1, 0, kR, 1, 0);
  s.add(0.7, 0.5, -1, 0, kR, 1, 0);
  s.omega = {w0, 0};
  s.inertia = {0.5 * kR * kR, 0.5 * kR * kR};
  return s;
}

EngineOptions rough(EngineOptions o, double beta, double beta_w) {
  o.physics.roughness = beta;
  o.physics.wall_roughness = beta_w;
  o.rotation = true;
  return o;
}

// Spins are read from the engine's state after the run.
double omega(const EngineApi<double>& e, std::size_t i) { return e.particles().omega[i]; }

}  // namespace

TEST_CASE("rough: the pair rule gives the textbook spins for a head-on collision of a spinning disk", "[rough]") {
  // Disk i spins at w with r w = 3 and meets j head-on. g_t = -(r w) = -3, K = 1 + 1 + 2 + 2 = 6,
  // P_t = (1 + beta) g_t / K = -1 for beta = 1: v_i' = (-1, -1), v_j' = (1, 1), w_i' = w / 3, w_j' = -2 w / 3.
  double vix = 1, viy = 0, vjx = -1, vjy = 0, wi = 48, wj = 0;
  const double I = 0.5 * kR * kR;
  collide_pair(2 * kR, 0.0, 1.0, 1.0, 2.0, vix, viy, vjx, vjy);
  collide_pair_tangential(2 * kR, 0.0, -2.0, 0.0, 1.0, 1.0, kR, kR, I, I, 2.0, vix, viy, vjx, vjy, wi, wj);
  CHECK(vix == -1);
  CHECK(viy == -1);
  CHECK(vjx == 1);
  CHECK(vjy == 1);
  CHECK(wi == 16);
  CHECK(wj == -32);
  // Energy: (1/2)(1 + 1) + (1/2) I 48^2 before, the same after.
  const double before = 1.0 + 0.5 * I * 48 * 48;
  const double after = 0.5 * (vix * vix + viy * viy + vjx * vjx + vjy * vjy) + 0.5 * I * (wi * wi + wj * wj);
  CHECK(after == before);
}

TEST_CASE("rough: the engine resolves a head-on collision of a spinning disk exactly", "[rough]") {
  EngineOptions o = rough(walls_until(0.2), 1, -1);
  auto run = run_recorded(two_disks(48), o);
  const auto pairs = run.pairs();
  REQUIRE(pairs.size() == 1);
  const auto& e = pairs[0];
  CHECK(e.vix == -1);
  CHECK(e.viy == -1);
  CHECK(e.vjx == 1);
  CHECK(e.vjy == 1);
  CHECK(e.wi == 16);
  CHECK(e.wj == -32);
  CHECK(omega(*run.engine, 0) == 16);
  CHECK(omega(*run.engine, 1) == -32);
  CHECK(run.engine->effects().find("rough") != std::string::npos);
}

TEST_CASE("rough: a partly rough pair (beta = 0) stops the contact points sliding", "[rough]") {
  // beta = 0: g_t' = 0. P_t = g_t / K = -1/2; w_i' = 48 - 16 = 32, w_j' = -16; the contact points then
  // move together: (v_j - v_i).t - r (w_i + w_j) = (1/2 + 1/2) - (2 - 1) = 0.
  auto run = run_recorded(two_disks(48), rough(walls_until(0.2), 0, -1));
  const auto pairs = run.pairs();
  REQUIRE(pairs.size() == 1);
  CHECK(pairs[0].wi == 32);
  CHECK(pairs[0].wj == -16);
  CHECK(pairs[0].viy == -0.5);
  CHECK(pairs[0].vjy == 0.5);
  CHECK((pairs[0].vjy - pairs[0].viy) - kR * (pairs[0].wi + pairs[0].wj) == 0);
}

TEST_CASE("rough: a disk spinning into a rough wall leaves it rolling the other way", "[rough]") {
  // Left wall, v = (-1, 0), r w = 3 (counter-clockwise: the contact point slides down). K = 1 + 2 = 3,
  // g_t = -3, P_t = -2 for beta_w = 1: v' = (1, 2), w' = 48 - 64 = -16; energy 1/2 + I 48^2 / 2 = 2.75 kept.
  InitialState s = box();
  s.add(0.2, 0.5, -1, 0, kR, 1, 0);
  s.omega = {48};
  s.inertia = {0.5 * kR * kR};
  auto run = run_recorded(s, rough(walls_until(0.2), -1, 1));
  const auto walls = run.recorder->of_kind(EventKind::Wall);
  REQUIRE(walls.size() == 1);
  CHECK(walls[0].j == kWallLeft);
  CHECK(walls[0].vix == 1);
  CHECK(walls[0].viy == 2);
  CHECK(walls[0].wi == -16);
  CHECK(kinetic_energy(run.engine->particles()) == 2.75);
  // A smooth wall (beta_w = -1) leaves the spin alone and reflects as the course rule does.
  auto smooth = run_recorded(s, rough(walls_until(0.2), -1, -1));
  const auto w2 = smooth.recorder->of_kind(EventKind::Wall);
  REQUIRE(w2.size() == 1);
  CHECK(w2[0].vix == 1);
  CHECK(w2[0].viy == 0);
  CHECK(w2[0].wi == 48);
}

namespace {

void check_same_events(const RecordedRun& a, const RecordedRun& b) {
  REQUIRE(a.events().size() == b.events().size());
  REQUIRE(a.events().size() > 1000);
  for (std::size_t k = 0; k < a.events().size(); ++k) {
    const auto &x = a.events()[k], &y = b.events()[k];
    INFO("event " << k);
    REQUIRE(x.kind == y.kind);
    REQUIRE(x.i == y.i);
    REQUIRE(x.j == y.j);
    REQUIRE(same_bits(x.time, y.time));
    REQUIRE((same_bits(x.vix, y.vix) && same_bits(x.viy, y.viy) && same_bits(x.vjx, y.vjx) && same_bits(x.vjy, y.vjy)));
  }
}

RecordedRun run_as(EngineKind kind, const InitialState& s, const EngineOptions& o) {
  RecordedRun r;
  auto made = make_engine_as<double>(kind, s, o);
  if (!made) throw std::runtime_error(made.error().message);
  r.engine = std::move(made).value();
  r.engine->add_sink(r.recorder.get());
  r.status = r.engine->run();
  return r;
}

}  // namespace

TEST_CASE("rough: beta = -1 in the rough engines is the smooth engines bit for bit", "[rough]") {
  const InitialState gas = lattice_gas(12, 0.01, 1, 7);
  // Every contact smooth (beta = beta_w = -1, the defaults); the rough engine is named, the smooth one chosen.
  EngineOptions o = walls_until(3);
  check_same_events(run_as(EngineKind::WallsRough, gas, o), run_as(EngineKind::WallsElastic, gas, o));
  o.physics.restitution = 0.9;
  o.physics.wall_restitution = 0.8;
  check_same_events(run_as(EngineKind::WallsRough, gas, o), run_as(EngineKind::WallsDissipative, gas, o));
  EngineOptions p = o;
  p.boundary = BoundaryKind::Periodic;
  p.physics.restitution = 1;
  p.physics.wall_restitution = 1;  // counts even in a periodic box (PhysicsSpec::elastic)
  check_same_events(run_as(EngineKind::PeriodicRough, gas, p), run_as(EngineKind::PeriodicElastic, gas, p));
  // Spinning disks with smooth contacts keep their spins and move exactly as smooth disks do.
  InitialState spinning = gas;
  spinning.omega.assign(gas.size(), 5.0);
  o.rotation = true;
  auto spun = run_as(EngineKind::WallsRough, spinning, o);
  o.rotation = false;
  check_same_events(spun, run_as(EngineKind::WallsDissipative, gas, o));
  for (std::size_t i = 0; i < gas.size(); ++i) REQUIRE(spun.engine->particles().omega[i] == 5.0);
  // A smooth scene never picks a rough engine; a rough one always does.
  EngineOptions smooth = walls_until(1);
  CHECK(engine_kind_for(smooth) == EngineKind::WallsElastic);
  smooth.physics.roughness = 0.5;
  CHECK(engine_kind_for(smooth) == EngineKind::WallsRough);
  CHECK_FALSE(engine_can_run(EngineKind::WallsDissipative, smooth));
}

namespace {

// Translational and rotational energy of a state.
struct Energies {
  double trans = 0, rot = 0;
};
template <class T>
Energies energies(const Particles<T>& p) {
  Energies e;
  e.rot = rotational_energy(p);
  e.trans = kinetic_energy(p) - e.rot;
  return e;
}

class EnergySampler final : public Sink<double> {
 public:
  std::vector<Energies> samples;
  void on_event(const EventOutcome<double>&, const Particles<double>&) override {}
  void on_sample(double, const Particles<double>& p) override { samples.push_back(energies(p)); }
};

}  // namespace

TEST_CASE("rough: energy is conserved for beta = +1 and -1 with xi = 1 over a long gas run", "[rough]") {
  // 400 spinning disks, ~100 collisions each. Tolerance: 1e-12 relative (round-off of ~4e4 collisions,
  // each exact to a few ulps, adds up to ~1e-14).
  for (const double beta : {1.0, -1.0})
    for (const BoundaryKind boundary : {BoundaryKind::Periodic, BoundaryKind::Walls}) {
      InitialState gas = lattice_gas(20, 0.008, 1, 11);
      gas.inertia.assign(gas.size(), 0);
      gas.omega.assign(gas.size(), 0);
      for (std::size_t i = 0; i < gas.size(); ++i) {
        gas.inertia[i] = 0.5 * gas.mass[i] * gas.radius[i] * gas.radius[i];
        gas.omega[i] = (double(i % 7) - 3) * 40;  // r w ~ 1: as much spin as speed
      }
      EngineOptions o = rough(walls_until(1e9), beta, beta);
      o.boundary = boundary;
      o.stop.time.reset();
      o.stop.collisions_per_particle = 100;
      auto e = engine(gas, o);
      const double e0 = kinetic_energy(e->particles()), rot0 = rotational_energy(e->particles());
      REQUIRE(e->run() == RunStatus::ReachedCollisions);
      INFO("beta " << beta << (boundary == BoundaryKind::Walls ? " walls" : " periodic"));
      CHECK(std::abs(kinetic_energy(e->particles()) / e0 - 1) < 1e-12);
      CHECK(e->check_invariants(1e-9).empty());
      // beta = 1 trades energy between translation and rotation; beta = -1 never touches the spins.
      if (beta == 1) CHECK(std::abs(rotational_energy(e->particles()) / rot0 - 1) > 1e-3);
      if (beta == -1) CHECK(rotational_energy(e->particles()) == rot0);
    }
}

TEST_CASE("rough: equipartition in a rough elastic gas, <I w^2/2> = kT/2 against <m v^2/2> = kT", "[rough][statistics]") {
  // 400 disks (phi ~ 0.08) start with translation only; beta = 1 hands energy to rotation until each disk
  // holds kT/2 in rotation and kT in translation: <E_rot> / <E_trans> = 1/2. Measured over 200 samples
  // after 40 collisions per disk (relaxation takes ~10): each sample's ratio has a spread of ~sqrt(2/N) ~ 7 %
  // and neighbouring samples are correlated over a few mean free times, so the mean over ~200 samples is
  // good to ~1-2 %. Tolerance: 5 %.
  InitialState gas = lattice_gas(20, 0.008, 1, 3);
  gas.omega.assign(gas.size(), 0);
  gas.inertia.assign(gas.size(), 0);
  for (std::size_t i = 0; i < gas.size(); ++i) gas.inertia[i] = 0.5 * gas.mass[i] * gas.radius[i] * gas.radius[i];
  EngineOptions o = rough(walls_until(1e9), 1, 1);
  o.boundary = BoundaryKind::Periodic;
  o.stop.time.reset();
  o.stop.collisions_per_particle = 240;
  // Mean free time ~ 1 / (2 sigma n sqrt(pi kT / m)) ~ 1 / (0.032 * 400 * 1.25) ~ 0.06: a sample every
  // 0.05, the first 4 time units (~60 collisions per disk) skipped.
  o.sample_interval = 0.05;
  EnergySampler sampler;
  auto e = engine(gas, o);
  e->add_sink(&sampler);
  REQUIRE(e->run() == RunStatus::ReachedCollisions);
  const std::size_t skip = std::size_t(4.0 / 0.05);
  REQUIRE(sampler.samples.size() > skip + 100);
  double trans = 0, rot = 0;
  for (std::size_t k = skip; k < sampler.samples.size(); ++k) trans += sampler.samples[k].trans, rot += sampler.samples[k].rot;
  INFO("samples " << sampler.samples.size() - skip << ", <E_rot>/<E_trans> = " << rot / trans);
  CHECK(rot / trans == Approx(0.5).epsilon(0.05));
}
