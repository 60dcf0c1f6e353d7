// The Andersen thermostat (engine/room_thermostat.hpp, engine/thermostat.hpp): the velocities it draws are
// Maxwell-Boltzmann at its kT, the gas it holds relaxes to that distribution, the kinetic energy of an
// elastic gas under it fluctuates canonically, a driven inelastic gas settles at the granular temperature
// the energy balance predicts, and the same options give the same events.
//
// Tolerances: the KS tests ask p > 0.001 of the right law and p < 1e-4 of a law 20 % off (the run's
// sample sizes tell those apart by many standard errors); the energy moments are within about four
// standard errors of their estimators (derived beside each test; docs/physics.md, "Andersen thermostat").
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "ede/distributions.hpp"
#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

// N = side^2 disks of radius r in a periodic box of side l, at rest, half of them of mass 4.
InitialState resting_mixture(int side, double r, double l) {
  InitialState s = lattice_gas(side, r, l, 3, 0.0);
  for (std::size_t i = 0; i < s.size(); i += 2) s.mass[i] = 4;
  return s;
}

EngineOptions thermostatted(double kT, double rate, double until) {
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.time = until;
  o.physics.thermostat = ThermostatSpec{kT, rate, {}};
  o.seed = 11;
  return o;
}

// u = F_m(v) for each speed, F_m the 2D Maxwell-Boltzmann speed CDF of the disk's own mass: uniform on
// [0, 1] when the speeds follow the law whatever the masses.
KsResult ks_of_speeds(const std::vector<double>& speeds, const std::vector<double>& masses, double kT) {
  std::vector<double> u(speeds.size());
  for (std::size_t k = 0; k < speeds.size(); ++k) u[k] = mb_speed_cdf(speeds[k], masses[k], kT);
  return ks_test(u, [](double x) { return x; });
}

// The kinetic energy at each sample time.
class EnergySampler final : public Sink<double> {
 public:
  std::vector<double> energies;
  void on_event(const EventOutcome<double>&, const Particles<double>&) override {}
  void on_sample(double, const Particles<double>& p) override { energies.push_back(kinetic_energy(p)); }
};

}  // namespace

TEST_CASE("thermostat: the velocities it draws are Maxwell-Boltzmann at its kT for each mass", "[thermostat]") {
  const InitialState s = resting_mixture(10, 0.2, 20);
  auto run = run_recorded(s, thermostatted(2.0, 1.0, 200));
  const auto redraws = run.recorder->of_kind(EventKind::Thermostat);
  // 100 disks at rate 1 for 200 time units: 20 000 redraws expected (Poisson, sd 141).
  REQUIRE(redraws.size() > 19000);
  REQUIRE(redraws.size() < 21000);
  std::vector<double> speeds, masses;
  for (const auto& e : redraws) {
    speeds.push_back(std::hypot(e.vix, e.viy));
    masses.push_back(s.mass[std::size_t(e.i)]);
    CHECK(e.j == -1);
  }
  CHECK(ks_of_speeds(speeds, masses, 2.0).p_value > 1e-3);
  CHECK(ks_of_speeds(speeds, masses, 2.4).p_value < 1e-4);  // the test tells a 20 % error
  // Every disk is picked about equally often: 200 redraws each, within 5 sd (sd 14).
  std::vector<int> picks(s.size(), 0);
  for (const auto& e : redraws) ++picks[std::size_t(e.i)];
  for (int p : picks) CHECK(std::abs(p - 200) < 75);
}

TEST_CASE("thermostat: a gas at rest relaxes to Maxwell-Boltzmann at the thermostat's kT", "[thermostat]") {
  const InitialState s = resting_mixture(10, 0.2, 20);
  EngineOptions o = thermostatted(2.0, 0.5, 100);
  o.sample_interval = 4;  // two relaxation times 1/nu apart
  Recorder<double> rec;
  rec.keep_states = true;
  auto e = engine(s, o);
  e->add_sink(&rec);
  REQUIRE(e->run() == RunStatus::ReachedTime);
  std::vector<double> speeds, masses;
  for (std::size_t k = 0; k < rec.sample_states.size(); ++k) {
    if (rec.sample_times[k] <= 20) continue;  // ten relaxation times
    for (std::size_t i = 0; i < s.size(); ++i) {
      speeds.push_back(std::hypot(rec.sample_states[k][i].vx, rec.sample_states[k][i].vy));
      masses.push_back(s.mass[i]);
    }
  }
  REQUIRE(speeds.size() == 2000);
  CHECK(ks_of_speeds(speeds, masses, 2.0).p_value > 1e-3);
  CHECK(ks_of_speeds(speeds, masses, 2.4).p_value < 1e-4);
}

// Canonical fluctuations. Between redraws collisions keep the kinetic energy E, and each redraw replaces
// one disk's energy by an exponential one of mean kT (2D: m v^2 / 2 with v ~ N(0, kT/m) per component), so
// the stationary law of the velocities is canonical and E ~ Gamma(N, kT): <E> = N kT and
// <dE^2> = N (kT)^2 (two quadratic degrees of freedom per disk, each with variance (kT)^2 / 2).
// E relaxes at rate nu exactly (d<E>/dt = nu (N kT - E)), so samples 2/nu apart correlate by e^-2 = 0.135.
// With M samples the relative standard errors are 1.14 / sqrt(N M) for the mean and about 1.02 sqrt(2/M)
// for the variance: 0.36 % and 3.2 % for N = 64, M = 2000; the tolerances are 1.5 % and 13 %.
TEST_CASE("thermostat: an elastic gas's kinetic energy fluctuates canonically, <dE^2> = N (kT)^2", "[thermostat][slow]") {
  const double kT = 1.5, nu = 0.5;
  InitialState s = lattice_gas(8, 0.3, 16, 5, 1.0);
  const double n = double(s.size());
  EngineOptions o = thermostatted(kT, nu, 40 + 2000 * 4);
  o.sample_interval = 4;
  EnergySampler sampler;
  auto e = engine(s, o);
  e->add_sink(&sampler);
  REQUIRE(e->run() == RunStatus::ReachedTime);
  std::vector<double> E(sampler.energies.begin() + 10, sampler.energies.end());  // after 20 / nu
  REQUIRE(E.size() == 2000);
  double mean = 0;
  for (double x : E) mean += x;
  mean /= double(E.size());
  double var = 0;
  for (double x : E) var += (x - mean) * (x - mean);
  var /= double(E.size() - 1);
  CHECK(mean / (n * kT) == Approx(1.0).epsilon(0.015));
  CHECK(var / (n * kT * kT) == Approx(1.0).epsilon(0.13));
}

// A driven granular gas. Pair collisions of equal masses m lose (1 - xi^2) m (g.n)^2 / 4 each, and under
// molecular chaos with Maxwellian velocities at T the collision-weighted <(g.n)^2> is 2 var(g.n) = 4T/m,
// so the gas loses (1 - xi^2) T per collision, N omega / 2 collisions per unit time (omega: collisions per
// disk per unit time). The thermostat brings nu N (T_b - T). In the steady state, with E = N T:
//   T = T_b / (1 + (1 - xi^2) omega / (2 nu)),
// with omega measured in the run itself (so no equation of state for the collision rate is assumed).
// Tolerance 4 % (the mean over 30 relaxation times 1/nu of 400 disks has a standard error near 1 %, omega
// one near 0.5 %): the steady state's velocities are close to, not exactly, Maxwellian.
TEST_CASE("thermostat: a driven inelastic gas settles at the granular temperature of the energy balance", "[thermostat][slow]") {
  const double kT = 1.0, nu = 0.1, xi = 0.8;
  InitialState s = lattice_gas(20, 0.25, 28, 9, 1.0);  // 400 disks, packing fraction 0.1
  const double n = double(s.size());
  EngineOptions o = thermostatted(kT, nu, 400);
  o.physics.restitution = xi;
  o.sample_interval = 1;
  EnergySampler sampler;
  struct PairCounter final : Sink<double> {
    std::size_t after_100 = 0;
    void on_event(const EventOutcome<double>& e, const Particles<double>&) override {
      if (e.kind == EventKind::Pair && e.time > 100) ++after_100;
    }
  } pairs;
  auto e = engine(s, o);
  e->add_sink(&sampler);
  e->add_sink(&pairs);
  REQUIRE(e->run() == RunStatus::ReachedTime);
  REQUIRE(sampler.energies.size() == 400);
  const auto mean_T = [&](std::size_t from, std::size_t to) {
    double sum = 0;
    for (std::size_t k = from; k < to; ++k) sum += sampler.energies[k];
    return sum / double(to - from) / n;
  };
  const double T = mean_T(100, 400), early = mean_T(100, 250), late = mean_T(250, 400);
  const double omega = 2 * double(pairs.after_100) / n / 300;
  const double expected = kT / (1 + (1 - xi * xi) * omega / (2 * nu));
  INFO("T = " << T << ", omega = " << omega << ", expected " << expected);
  CHECK(T < 0.7 * kT);  // well below the bath: the balance is not trivial
  CHECK(T == Approx(expected).epsilon(0.04));
  CHECK(early == Approx(late).epsilon(0.06));  // steady: each half-window mean has a standard error near 2 %
}

TEST_CASE("thermostat: the same options give the same events, and a species' own thermostat overrides", "[thermostat]") {
  InitialState s = resting_mixture(6, 0.2, 12);
  s.species_names = {"a", "b"};
  for (std::size_t i = 0; i < s.size(); ++i) s.species[i] = std::int32_t(i % 2);
  EngineOptions o = thermostatted(1.0, 1.0, 30);
  o.physics.thermostat->species = {"a"};
  o.species_thermostats = {{"b", 3.0, 0.5}};
  auto one = run_recorded(s, o);
  auto two = run_recorded(s, o);
  REQUIRE(one.events().size() == two.events().size());
  for (std::size_t k = 0; k < one.events().size(); ++k) {
    CHECK(one.events()[k].time == two.events()[k].time);
    CHECK(one.events()[k].vix == two.events()[k].vix);
  }
  // Species a (even ids) at rate 1, b at 0.5: 18 disks each for 30 time units, 540 and 270 redraws
  // expected (sd 23 and 16).
  std::size_t a = 0, b = 0;
  for (const auto& e : one.recorder->of_kind(EventKind::Thermostat)) (e.i % 2 == 0 ? a : b)++;
  CHECK(std::abs(double(a) - 540) < 100);
  CHECK(std::abs(double(b) - 270) < 75);
  EngineOptions other = o;
  other.seed = 12;
  auto three = run_recorded(s, other);
  CHECK(three.recorder->of_kind(EventKind::Thermostat).front().time !=
        one.recorder->of_kind(EventKind::Thermostat).front().time);
}

TEST_CASE("thermostat: it runs its own engines, and refuses gravity, segments and rotation", "[thermostat]") {
  EngineOptions o = thermostatted(1.0, 1.0, 1);
  CHECK(engine_kind_for(o) == EngineKind::PeriodicThermostat);
  o.boundary = BoundaryKind::Walls;
  CHECK(engine_kind_for(o) == EngineKind::WallsThermostat);
  CHECK_FALSE(engine_can_run(EngineKind::WallsDissipative, o));
  o.physics.gravity = {0, -1};
  auto made = make_engine<double>(resting_mixture(4, 0.1, 4), o);
  REQUIRE_FALSE(made.ok());
  CHECK(made.error().message.find("thermostat") != std::string::npos);
}
