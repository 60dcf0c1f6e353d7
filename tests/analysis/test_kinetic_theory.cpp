// Kinetic-theory references (ede/kinetic_theory.hpp): exact checks of the formulas on hand-made states,
// then statistical checks against runs, each with its tolerance:
// - the collision rate of an elastic gas (N = 1000, phi = 0.2, periodic, ~5000 pair collisions after
//   equilibration) against Enskog with Henderson's g(sigma): within 4% (the count's Poisson error is
//   ~1.4%; Henderson's g within ~0.5% at phi = 0.2; finite-N effects O(1/N));
// - Haff's law for xi = 0.9 (the cooling example's gas, N = 2000, phi = 0.2): the cooling time implied by
//   the measured E(t)/E(0) at t ~ tau, tau_meas = t / ((E(t)/E(0))^(-1/2) - 1), within the stated 10% of
//   Enskog's tau at the start (measured: +6.8%, +6.4%, +7.6% for seeds 3, 4, 5; the spread is ~1%).
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/ede.hpp"
#include "tool_runner.hpp"  // temp_path

using ede::test::temp_path;

namespace {

ede::State two_disks(ede::BoundaryKind boundary, double v1x, double v2x) {
  ede::State s;
  s.boundary = boundary;
  s.lx = s.ly = 1;
  s.x = ede::Column(std::vector<double>{0.25, 0.75});
  s.y = ede::Column(std::vector<double>{0.5, 0.5});
  s.vx = ede::Column(std::vector<double>{v1x, v2x});
  s.vy = ede::Column(std::vector<double>{0, 0});
  s.radius = ede::Column(std::vector<double>{0.1, 0.1});
  s.mass = ede::Column(std::vector<double>{1, 1});
  s.species = {0, 0};
  s.species_names = {"gas"};
  return s;
}

std::string run_to_log(const std::string& text, const std::string& name) {
  const std::string path = temp_path(name);
  auto sim = ede::Simulation::create(ede::parse_scene_text(text, name).value(), {.log_path = path}).value();
  sim.run();
  REQUIRE(sim.close());
  return path;
}

std::string gas(int count, double xi, double stop) {
  return "seed = 3\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n[physics]\nrestitution = " +
         std::to_string(xi) + "\ntc = 1e-5\n[[species]]\nname = \"gas\"\ncount = " + std::to_string(count) +
         "\n[species.placement]\nkind = \"random\"\npacking_fraction = 0.2\n[species.velocity]\nkind = \"speed\"\n"
         "speed = 1.0\n[stop]\ntime = " + std::to_string(stop) + "\n";
}

}  // namespace

TEST_CASE("Henderson's contact value gives his equation of state, Enskog's rate its formula", "[analysis][kinetic]") {
  for (const double phi : {0.01, 0.1, 0.3, 0.5, 0.7})
    CHECK(1 + 2 * phi * ede::henderson_contact_value(phi) == Approx(ede::henderson_z(phi)).epsilon(1e-14));
  CHECK(ede::henderson_contact_value(0) == 1);
  // 2 n sigma g sqrt(pi kT / m) with n = 100, sigma = 0.02, g = 1.5, kT = 2, m = 0.5: 6 sqrt(4 pi).
  CHECK(ede::enskog_collision_rate(100, 0.02, 1.5, 2, 0.5) == Approx(6 * std::sqrt(4 * M_PI)).epsilon(1e-15));
  CHECK(ede::haff_tau(0.9, 10) == Approx(4 / (0.19 * 10)).epsilon(1e-15));
  CHECK(std::isinf(ede::haff_tau(1, 10)));
}

TEST_CASE("kT is taken in the centre-of-mass frame with N - 1 disks when momentum is conserved", "[analysis][kinetic]") {
  // Periodic: two disks moving together carry no heat; opposite velocities give K' = 1 over N - 1 = 1.
  CHECK(ede::temperature_of(two_disks(ede::BoundaryKind::Periodic, 1, 1)).kT == 0);
  const ede::Temperature opposite = ede::temperature_of(two_disks(ede::BoundaryKind::Periodic, 1, -1));
  CHECK(opposite.kT == 1);
  CHECK(opposite.degrees == 1);
  // Walls: the box frame, N disks.
  const ede::Temperature walls = ede::temperature_of(two_disks(ede::BoundaryKind::Walls, 1, 1));
  CHECK(walls.kT == 0.5);
  CHECK(walls.degrees == 2);
  // Enskog: applicable for equal disks; phi = 2 pi 0.01, n = 2.
  const ede::EnskogReference e = ede::enskog_reference(two_disks(ede::BoundaryKind::Periodic, 1, -1));
  REQUIRE(e.applicable);
  CHECK(e.packing_fraction == Approx(2 * M_PI * 0.01).epsilon(1e-15));
  CHECK(e.rate == Approx(2 * 2 * 0.2 * ede::henderson_contact_value(e.packing_fraction) * std::sqrt(M_PI)).epsilon(1e-14));
  ede::State mixed = two_disks(ede::BoundaryKind::Periodic, 1, -1);
  mixed.mass = ede::Column(std::vector<double>{1, 2});
  CHECK(!ede::enskog_reference(mixed).applicable);
}

TEST_CASE("the collision rate of an elastic gas agrees with Enskog's within 4 percent", "[analysis][kinetic][statistical]") {
  const std::string log_path = run_to_log(gas(1000, 1.0, 0.25), "enskog-elastic.ede");
  const ede::Log log = ede::Log::open(log_path).value();
  // From t = 0.05 (about 4 collisions per disk: the start's single speed has relaxed) to the end.
  const auto c = ede::collision_series(log, ede::time_grid_to(0.05, 0.25, 0.01)).value();
  REQUIRE(c.enskog.applicable);
  const auto& s = c.series;
  const double measured = 2.0 * double(s.pair_collisions.back() - s.pair_collisions.front()) /
                          (double(s.disks()) * (s.time.back() - s.time.front()));
  double expected = 0;
  for (std::size_t k = 1; k < s.time.size(); ++k) expected += c.enskog_rate[k] * (s.time[k] - s.time[k - 1]);
  expected /= s.time.back() - s.time.front();
  INFO("measured " << measured << " per disk, Enskog " << expected << ", pairs "
                   << s.pair_collisions.back() - s.pair_collisions.front());
  CHECK(std::abs(measured / expected - 1) < 0.04);
}

TEST_CASE("Haff's law with tau from Enskog's rate at the start holds within its stated uncertainty", "[analysis][kinetic][statistical]") {
  const std::string log_path = run_to_log(gas(2000, 0.9, 0.3), "haff-enskog.ede");
  const ede::Log log = ede::Log::open(log_path).value();
  const auto curve = ede::energy_curve(log, {.points = 31}).value();
  REQUIRE(std::isfinite(curve.enskog_tau));
  CHECK(curve.enskog_tau_error == Approx(ede::kHaffTauRelativeUncertainty * curve.enskog_tau));
  const std::size_t last = curve.series.time.size() - 1;
  const double t = curve.series.time[last], ratio = curve.ratio(last);
  const double tau_measured = t / (1 / std::sqrt(ratio) - 1);
  INFO("tau Enskog " << curve.enskog_tau << ", tau from E(" << t << ")/E(0) = " << ratio << ": " << tau_measured);
  CHECK(std::abs(tau_measured / curve.enskog_tau - 1) < ede::kHaffTauRelativeUncertainty);
}

TEST_CASE("time averages per species are the means over the grid", "[analysis][kinetic]") {
  const std::string log_path = run_to_log(gas(300, 1.0, 0.2), "species-average.ede");
  const ede::Log log = ede::Log::open(log_path).value();
  const auto rows = ede::species_time_averages(log, 0.05, 0.2, 200, 10).value();
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].name == "gas");
  CHECK(rows[1].name == "all");
  // Elastic: the energy is constant, so the average is E(0)/N and the error is ~0.
  const double e0 = ede::log_series(log, {0.0}).value().kinetic_energy[0] / 300;
  CHECK(rows[1].mean_kinetic_energy == Approx(e0).epsilon(1e-12));
  CHECK(rows[0].error < 1e-12);
  CHECK(!ede::species_time_averages(log, 0.2, 0.1));
}
