// Collision statistics per event (ede/collision_stats.hpp): exact records for hand-made collisions (a
// head-on pair of unequal masses, the impact parameter (r1 + r2) / sqrt(2), a head-on pair across a
// periodic edge, a wall), then an equilibrium periodic gas whose |b| / sigma must be uniform on [0, 1] and
// whose mu g^2 / 2kT must follow Gamma(3/2) (the flux-weighted Maxwellian), each by a KS test with
// p > 1e-3; and a start of equal speeds, far from Maxwell's law, that the speed test must reject.
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/collision_stats.hpp"
#include "log_test_support.hpp"
#include "public_log_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

std::vector<std::pair<Event, CollisionRecord>> records(const std::string& path) {
  const Log log = Log::open(path).value();
  std::vector<std::pair<Event, CollisionRecord>> out;
  REQUIRE(for_each_collision(log, {}, [&](const Event& e, const CollisionRecord& c) {
    out.emplace_back(e, c);
    return true;
  }));
  return out;
}

const std::pair<Event, CollisionRecord>& first_of(const std::vector<std::pair<Event, CollisionRecord>>& all, EventKind k) {
  for (const auto& r : all)
    if (r.first.kind == k) return r;
  FAIL("no event of kind " << to_string(k));
  return all.front();
}

}  // namespace

TEST_CASE("head-on pair of masses 1 and 3: b = 0, g_n = 2, impulse 2 mu g = 3", "[analysis][collision_stats]") {
  InitialState s = box();
  s.add(0.3, 0.5, 1.0, 0.0, 0.05, 1.0, 0);
  s.add(0.7, 0.5, -1.0, 0.0, 0.05, 3.0, 0);
  const auto run = run_logged<double>(s, walls_until(0.2), "collision-head-on.ede");
  const auto all = records(run.path);
  const auto& [e, c] = first_of(all, EventKind::Pair);
  CHECK(double(e.time) == Approx(0.15).epsilon(1e-12));
  REQUIRE(c.pair);
  CHECK(c.impact_parameter == Approx(0).margin(1e-15));
  CHECK(c.relative_speed == Approx(2).epsilon(1e-15));
  CHECK(c.normal_speed == Approx(2).epsilon(1e-15));
  CHECK(c.tangential_speed == Approx(0).margin(1e-15));
  CHECK(c.reduced_mass == Approx(0.75).epsilon(1e-15));
  // Elastic: J = (1 + xi) mu g_n = 3 along -x on disk i (it bounces back at v' = -2).
  CHECK(c.impulse_x == Approx(-3).epsilon(1e-14));
  CHECK(c.impulse_y == Approx(0).margin(1e-15));
  CHECK(c.impulse == Approx(3).epsilon(1e-14));
}

TEST_CASE("impact parameter (r1 + r2) / sqrt(2): |b| / sigma = 1 / sqrt 2, impulse mu g / sqrt 2 at 45 degrees", "[analysis][collision_stats]") {
  // Disk i moves along +x at speed 1; j, at rest, sits sigma / sqrt(2) below its path: r = x_i - x_j has
  // r_y = +sigma / sqrt 2, so b = (r x g) / |g| = -r_y (signed: -1/sqrt 2). Equal masses: i leaves at
  // (1/2, 1/2), j at (1/2, -1/2); J on i = (-1/2, 1/2), |J| = 1/sqrt 2.
  const double sigma = 0.1, h = sigma / std::sqrt(2.0);
  InitialState s = box();
  s.add(0.2, 0.5, 1.0, 0.0, 0.05, 1.0, 0);
  s.add(0.5, 0.5 - h, 0.0, 0.0, 0.05, 1.0, 0);
  const auto run = run_logged<double>(s, walls_until(0.3), "collision-45.ede");
  const auto all = records(run.path);
  const auto& [e, c] = first_of(all, EventKind::Pair);
  CHECK(double(e.time) == Approx(0.3 - h).epsilon(1e-12));
  CHECK(c.impact_parameter == Approx(-1 / std::sqrt(2.0)).epsilon(1e-12));
  CHECK(c.relative_speed == Approx(1).epsilon(1e-15));
  CHECK(c.normal_speed == Approx(1 / std::sqrt(2.0)).epsilon(1e-12));
  CHECK(c.tangential_speed == Approx(-1 / std::sqrt(2.0)).epsilon(1e-12));
  CHECK(c.impulse_x == Approx(-0.5).epsilon(1e-12));
  CHECK(c.impulse_y == Approx(0.5).epsilon(1e-12));
  CHECK(c.impulse == Approx(1 / std::sqrt(2.0)).epsilon(1e-12));
  CHECK(std::fabs(c.impact_parameter) == Approx(std::fabs(c.tangential_speed) / c.relative_speed).epsilon(1e-12));
}

TEST_CASE("a head-on pair across a periodic edge uses the nearest image", "[analysis][collision_stats]") {
  // i at x = 0.05 moving left, j at x = 0.9 moving right: they meet across x = 0 at t = 0.025, where
  // the stored positions are ~0.1 box apart only through the edge.
  InitialState s = box();
  s.add(0.05, 0.5, -1.0, 0.0, 0.05, 1.0, 0);
  s.add(0.9, 0.5, 1.0, 0.0, 0.05, 1.0, 0);
  EngineOptions o = walls_until(0.03);
  o.boundary = BoundaryKind::Periodic;
  const auto run = run_logged<double>(s, o, "collision-periodic.ede");
  const auto all = records(run.path);
  const auto& [e, c] = first_of(all, EventKind::Pair);
  CHECK(c.normal_speed == Approx(2).epsilon(1e-12));
  CHECK(c.impact_parameter == Approx(0).margin(1e-12));
  CHECK(c.impulse_x == Approx(2).epsilon(1e-12));  // i was moving left, leaves moving right
}

TEST_CASE("a wall collision: impulse -2 m v_n, normal speed |v_n|", "[analysis][collision_stats]") {
  InitialState s = box();
  s.add(0.5, 0.5, 1.0, 0.5, 0.05, 2.0, 0);
  const auto run = run_logged<double>(s, walls_until(0.5), "collision-wall.ede");
  const auto all = records(run.path);
  const auto& [e, c] = first_of(all, EventKind::Wall);
  REQUIRE(c.wall);
  CHECK_FALSE(c.pair);
  CHECK(e.j == kWallRight);
  CHECK(c.impulse_x == -4);
  CHECK(c.impulse_y == 0);
  CHECK(c.normal_speed == 1);
  CHECK(c.relative_speed == Approx(std::sqrt(1.25)).epsilon(1e-15));
}

TEST_CASE("the laws at collision: Gamma(3/2) CDF and the flux-weighted speed density", "[analysis][collision_stats]") {
  CHECK(collision_u_cdf(0) == 0);
  CHECK(collision_u_cdf(1e6) == Approx(1));
  // Mean of Gamma(3/2) is 3/2: integral of (1 - P(u)) du.
  double mean = 0;
  for (double u = 0.0005; u < 40; u += 0.001) mean += (1 - collision_u_cdf(u)) * 0.001;
  CHECK(mean == Approx(1.5).epsilon(1e-4));
  // The density integrates to its CDF.
  double integral = 0;
  const double mu = 0.5, kT = 0.7;
  for (double g = 0.00005; g < 2; g += 0.0001) integral += collision_speed_density(g, mu, kT) * 0.0001;
  CHECK(integral == Approx(collision_speed_cdf(2, mu, kT)).epsilon(1e-6));
}

TEST_CASE("equilibrium gas: |b|/sigma uniform and the relative speed flux-weighted Maxwellian (KS p > 1e-3)", "[analysis][collision_stats]") {
  // 1000 disks, r = 0.006, phi = 0.113 in a periodic unit box, all at speed 1 at t = 0; Maxwell's law
  // is reached within a few collisions per disk (~36 per disk per unit time), so the range starts at
  // t = 1. Both laws hold exactly in equilibrium at any density (velocities independent of positions);
  // the finite microcanonical gas is off by O(1/N). Tolerance: KS p-value above 1e-3 for ~9e4 samples
  // (a deviation of the CDF by ~0.006 would be rejected), and <|b|/sigma> within 4 standard errors of 1/2.
  const Log log = public_log(gas_toml(1000, 0.006, "time = 6.0", "", "periodic"), "collision-gas.ede");
  ImpactRequest req;
  req.range.from_time = 1.0;
  const ImpactStatistics r = impact_statistics(log, req).value();
  INFO("pairs " << r.pair_collisions << ", kT " << r.kT << ", impact D " << r.impact_ks.statistic << " p "
                << r.impact_ks.p_value << ", speed D " << r.speed_ks.statistic << " p " << r.speed_ks.p_value);
  REQUIRE(r.pair_collisions > 50000);
  CHECK(r.kT == Approx(0.5).epsilon(0.01));
  CHECK(r.impact_ks.p_value > 1e-3);
  CHECK(r.speed_ks.p_value > 1e-3);
  CHECK(std::fabs(r.mean_impact - 0.5) < 4 * std::sqrt(1.0 / 12 / double(r.pair_collisions)));
  // The histogram agrees with the law bin by bin within 5 standard errors (Poisson counts).
  for (std::size_t k = 0; k < r.speed.bins(); ++k) {
    const double width = r.speed.edges[k + 1] - r.speed.edges[k];
    const double expected = r.speed_law[k] * width * double(r.pair_collisions);
    INFO("bin " << k);
    CHECK(std::fabs(double(r.speed.count[k]) - expected) < 5 * std::sqrt(expected) + 1);
  }
}

TEST_CASE("equal speeds at the start are not the flux-weighted law: the speed test rejects them", "[analysis][collision_stats]") {
  // The same gas over its first 0.02 time units (under one collision per disk): every speed is still 1,
  // so g = 2 sin(theta / 2) <= 2 and u has no tail; the KS test must see it (p < 1e-6).
  const Log log = public_log(gas_toml(1000, 0.006, "time = 0.02", "", "periodic"), "collision-gas-start.ede");
  const ImpactStatistics r = impact_statistics(log).value();
  INFO("pairs " << r.pair_collisions << ", speed D " << r.speed_ks.statistic << " p " << r.speed_ks.p_value);
  REQUIRE(r.pair_collisions > 200);
  CHECK(r.speed_ks.p_value < 1e-6);
}
