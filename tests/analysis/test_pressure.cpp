// Pressure from a log (pressure.hpp) and the block statistics behind its error bars (block_average.hpp):
// closed forms on hand-made logs, then the physics of gases within stated tolerances.
//
// Tolerances for the statistical tests: |measured - expected| < 4 sigma + the systematic error of the
// expectation itself, with sigma the reported standard error of B = 20 block means. The block error has a
// relative uncertainty of 1/sqrt(2 (B - 1)) ~ 16%, so 4 of them are at least ~3.4 true sigma: a false alarm
// is rarer than 1 in 1000 per check, and every run here is deterministic (fixed seeds), so a pass is a pass.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "ede/analysis.hpp"
#include "ede/pressure.hpp"
#include "ede/kinetic_theory.hpp"
#include "ede/simulation.hpp"
#include "log_test_support.hpp"
#include "tool_runner.hpp"  // temp_path

using namespace ede;
using namespace ede::test;

namespace {

PressureReport measure(const std::string& path, PressureOptions o = {}) {
  auto r = measure_pressure(open_public_log(path), o);
  INFO((r ? "" : r.error().message));
  REQUIRE(r);
  return r.value();
}

PressureOptions window(double from, double to, std::size_t blocks = 4) {
  PressureOptions o;
  o.from = from, o.to = to, o.blocks = blocks, o.bins_per_block = 8;
  return o;
}

EngineOptions periodic_until(double t) {
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.time = t;
  return o;
}

// Gaussian AR(1) series x_k = rho x_{k-1} + sqrt(1 - rho^2) e_k (unit variance), from a fixed seed. The
// standard error of its mean over n values is sqrt((1 + rho) / (1 - rho) / n) for large n.
std::vector<double> ar1(std::size_t n, double rho, unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<double> x(n);
  double prev = 0;
  for (double& v : x) {
    // Box-Muller from raw bits: no std::normal_distribution (its output differs between libraries).
    const double u1 = (double(g() >> 11) + 0.5) * 0x1.0p-53, u2 = double(g() >> 11) * 0x1.0p-53;
    const double e = std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
    v = prev = rho * prev + std::sqrt(1 - rho * rho) * e;
  }
  return x;
}

}  // namespace

TEST_CASE("block_stats: mean, standard error and lag-1 correlation of a small series", "[analysis][pressure]") {
  const BlockStats s = block_stats({1, 2, 3, 4});
  CHECK(s.blocks == 4);
  CHECK(s.mean == 2.5);
  CHECK(s.error == Approx(std::sqrt((2.25 + 0.25 + 0.25 + 2.25) / 3 / 4)).epsilon(1e-15));
  // sum (x_k - m)(x_{k+1} - m) = (-1.5)(-0.5) + (-0.5)(0.5) + (0.5)(1.5) = 1.25; over sum of squares 5.
  CHECK(s.lag1 == Approx(0.25).epsilon(1e-15));
  CHECK(block_stats({7, 7, 7}).error == 0);
  CHECK(block_stats({7, 7, 7}).lag1 == 0);
  CHECK(coarse_grain({1, 2, 3, 4, 5}, 2) == std::vector<double>{1.5, 3.5});
}

TEST_CASE("blocking analysis: flat for independent values, finds the plateau of correlated ones", "[analysis][pressure]") {
  const std::size_t n = 1 << 16;
  SECTION("independent values: the plateau is the naive error") {
    const BlockingAnalysis b = blocking_analysis(ar1(n, 0.0, 1));
    REQUIRE(b.converged);
    CHECK(b.trend == BlockingTrend::Plateau);
    CHECK(b.levels[0].blocks == n);
    CHECK(b.error == Approx(1 / std::sqrt(double(n))).epsilon(0.05));
  }
  SECTION("rho = 0.9: the naive error is 4.4 times too small, the plateau is right") {
    const double expected = std::sqrt(1.9 / 0.1 / double(n));
    const BlockingAnalysis b = blocking_analysis(ar1(n, 0.9, 2));
    REQUIRE(b.converged);
    CHECK(b.levels[0].error < expected / 4);
    CHECK(b.plateau >= 4);  // correlation time ~ 19 values: blocks of >= 16 before the plateau
    CHECK(std::fabs(b.error - expected) < 3 * b.levels[b.plateau].error_of_error + 0.05 * expected);
  }
  SECTION("anticorrelated values (a constant plus differences of noise): the estimates fall") {
    const std::vector<double> u = ar1(n + 1, 0.0, 5);
    std::vector<double> x(n);
    for (std::size_t k = 0; k < n; ++k) x[k] = 3 + u[k + 1] - u[k];
    const BlockingAnalysis b = blocking_analysis(x);
    CHECK_FALSE(b.converged);
    CHECK(b.trend == BlockingTrend::Falling);
    CHECK(b.error < b.levels[0].error / 8);
    CHECK(block_stats(coarse_grain(x, 64)).lag1 < -0.3);  // the -1/2 of a difference series, with noise
  }
  SECTION("a series too short for its correlations is not converged") {
    // Correlation time ~ 2000 values, 1024 of them: the error grows at every level.
    CHECK(blocking_analysis(ar1(1024, 0.999, 3)).trend == BlockingTrend::Rising);
    CHECK_FALSE(blocking_analysis(ar1(64, 0.999, 4)).converged);
  }
}

TEST_CASE("Henderson's equation of state: 1 at phi = 0, the exact second virial coefficient", "[analysis][pressure]") {
  CHECK(henderson_z(0) == 1);
  // Z = 1 + 2 phi + (25/8) phi^2 + O(phi^3); the exact B3 term of hard disks is 3.128 phi^2.
  const double phi = 1e-3;
  CHECK(henderson_z(phi) == Approx(1 + 2 * phi + 25.0 / 8 * phi * phi).epsilon(1e-8));
  CHECK(henderson_z(0.3) == Approx((1 + 0.09 / 8) / 0.49).epsilon(1e-15));
}

TEMPLATE_TEST_CASE("one disk bouncing between two walls: P = m v^2 / ((L - 2r) L) exactly", "[analysis][pressure]",
                   float, double, long double) {
  // m = 3, v = 2, r = 0.1, L = 1: the disk crosses L - 2r = 0.8 in 0.4, so a period is 0.8 with one hit
  // on each side wall; hits at t = 0.2 + 0.4 k, none at a window end. P = 3 * 4 / 0.8 = 15.
  InitialState s = box();
  s.add(0.5, 0.5, 2.0, 0.0, 0.1, 3.0, 0);
  const auto run = run_logged<TestType>(s, walls_until(8.5), "pressure-bounce.ede");
  const PressureReport r = measure(run.path, window(0, 8));
  const double tol = std::is_same_v<TestType, float> ? 1e-6 : 1e-12;
  CHECK(r.totals.wall_collisions == 20);
  CHECK(r.totals.wall_impulse[kWallLeft] == Approx(10 * 12.0).epsilon(tol));
  CHECK(r.totals.wall_impulse[kWallRight] == Approx(10 * 12.0).epsilon(tol));
  CHECK(r.wall[kWallLeft].stats.mean == Approx(15).epsilon(tol));
  CHECK(r.wall[kWallRight].stats.mean == Approx(15).epsilon(tol));
  CHECK(r.wall[kWallBottom].stats.mean == 0);
  CHECK(r.wall[kWallTop].stats.mean == 0);
  // Mean over the perimeter, and the virial with A_v = 1 - 0.1 * 2 = 0.8: K / A_v = 6 / 0.8 = 7.5, the same.
  CHECK(r.wall_mean.stats.mean == Approx(7.5).epsilon(tol));
  CHECK(r.virial_area == Approx(0.8).epsilon(tol));
  CHECK(r.totals.virial_sum == 0);
  CHECK(r.virial.stats.mean == Approx(7.5).epsilon(tol));
  CHECK(r.kT.stats.mean == Approx(6).epsilon(tol));
  CHECK(r.totals.kinetic_integral == Approx(6 * 8).epsilon(tol));
}

TEST_CASE("two disks colliding head-on once: the virial sum is r_ij . dp_i by hand", "[analysis][pressure]") {
  // Masses 1 and 2, r = 0.05, at x = 0.3 and 0.7 with v = +1 and -1: contact at t = 0.15 (gap 0.3, closing
  // speed 2). Elastic: dp_1 = 2 mu (v_2 - v_1) = 2 (2/3)(-2) = -8/3 along x; r_12 = x_1 - x_2 = -0.1, so
  // r_12 . dp_1 = 0.8/3 > 0. Afterwards v_1 = -5/3, v_2 = 1/3: no wall before t = 0.3.
  InitialState s = box();
  s.add(0.3, 0.5, 1.0, 0.0, 0.05, 1.0, 0);
  s.add(0.7, 0.5, -1.0, 0.0, 0.05, 2.0, 0);
  const auto run = run_logged<double>(s, walls_until(0.3), "pressure-head-on.ede");
  const PressureReport r = measure(run.path, window(0, 0.3));
  CHECK(r.totals.pair_collisions == 1);
  CHECK(r.totals.wall_collisions == 0);
  CHECK(r.totals.virial_sum == Approx(0.8 / 3).epsilon(1e-14));
  // P A_v = K + W / (2 tau): K = 1/2 + 1 = 3/2, W / (2 tau) = (0.8/3) / 0.6, A_v = 1 - 0.05 * 2 = 0.9.
  CHECK(r.virial.stats.mean == Approx((1.5 + 0.8 / 3 / 0.6) / 0.9).epsilon(1e-13));
}

TEST_CASE("a head-on collision across a periodic edge uses the minimum image, and xi enters the impulse",
          "[analysis][pressure]") {
  // Equal masses 1 at x = 0.85 (moving +1) and 0.15 (moving -1) in the unit periodic box: they meet across
  // the edge at t = 0.1, at x = 0.95 and 0.05 (raw difference 0.9, minimum image -0.1). With restitution
  // xi, dp_1 = -(1 + xi) mu |g_n| = -(1 + xi) (1/2)(2) and r_12 . dp_1 = 0.1 (1 + xi).
  const double xi = GENERATE(1.0, 0.5);
  InitialState s = box();
  s.add(0.85, 0.5, 1.0, 0.0, 0.05, 1.0, 0);
  s.add(0.15, 0.5, -1.0, 0.0, 0.05, 1.0, 0);
  EngineOptions o = periodic_until(0.2);
  o.physics.restitution = xi;
  const auto run = run_logged<double>(s, o, "pressure-periodic-pair.ede");
  const PressureReport r = measure(run.path, window(0, 0.2));
  CHECK(r.totals.pair_collisions == 1);
  CHECK(r.totals.virial_sum == Approx(0.1 * (1 + xi)).epsilon(1e-12));
  // Total momentum is zero: K in the centre-of-mass frame is the lab K, 1 before and xi^2 after t = 0.1.
  CHECK(r.totals.kinetic_integral == Approx(0.1 * 1 + 0.1 * xi * xi).epsilon(1e-12));
  if (xi < 1) {
    bool warned = false;
    for (const std::string& w : r.warnings) warned = warned || w.find("collisional stress") != std::string::npos;
    CHECK(warned);
  }
}

TEST_CASE("a dilute gas with walls: P_wall is the ideal gas's plus the small hard-disk correction",
          "[analysis][pressure]") {
  // 400 disks of r = 0.0035 in the unit box: phi = 0.0154, kT = 1/2 exactly (speed 1, elastic walls).
  // Expected: P = Z_H(phi) N kT / A_v, A_v = 1 - 2r (the centres stay r from the walls). Z_H - 1 = 3.1% is
  // resolved; the neglected terms (excess density at the walls, O(phi r / L) ~ 1e-4, and Henderson's own
  // error at phi = 0.015, < 1e-4) are far below the error bar.
  const auto run = run_logged<double>(lattice_gas(20, 0.0035, 1.0, 7), walls_until(100), "pressure-dilute.ede");
  PressureOptions o;
  o.from = 10;  // 70 mean free times (tau = 0.14) and ~10 wall-to-wall crossings per disk
  const PressureReport r = measure(run.path, o);
  REQUIRE(r.kT.stats.mean == Approx(0.5).epsilon(1e-12));
  const double expected = henderson_z(r.packing_fraction) * 400 * 0.5 / r.virial_area;
  const double sigma = r.wall_mean.stats.error;
  INFO("P_wall = " << r.wall_mean.stats.mean << " +- " << sigma << ", expected " << expected);
  CHECK(sigma < 0.01 * expected);
  CHECK(std::fabs(r.wall_mean.stats.mean - expected) < 4 * sigma + 1e-4 * expected);
  // Ideal gas in the box's own area is off by the excluded strip (2r / L = 0.7%) and Z - 1 (3.1%).
  CHECK(r.wall_mean.stats.mean > r.ideal());
}

TEST_CASE("wall and virial pressures agree within their errors in one walled run", "[analysis][pressure]") {
  // phi = 0.2, walls: the two pressures see different events (walls vs pairs) but the virial theorem ties
  // them: P_wall - P_virial = 0 in expectation (A_v, square box). The difference is taken block by block,
  // so its error includes the correlation between the two in one run.
  const double r0 = std::sqrt(0.2 / (400 * M_PI));
  const auto run = run_logged<double>(lattice_gas(20, r0, 1.0, 11), walls_until(40), "pressure-agree.ede");
  const PressureReport r = measure(run.path);
  INFO("P_wall = " << r.wall_mean.stats.mean << " +- " << r.wall_mean.stats.error << ", P_virial = "
                   << r.virial.stats.mean << " +- " << r.virial.stats.error);
  CHECK(std::fabs(r.wall_minus_virial.stats.mean) < 4 * r.wall_minus_virial.stats.error);
  CHECK(std::fabs(r.wall_mean.stats.mean - r.virial.stats.mean) <
        4 * std::hypot(r.wall_mean.stats.error, r.virial.stats.error));
  CHECK(r.wall_mean.stats.error < 0.02 * r.wall_mean.stats.mean);
}

TEST_CASE("a periodic gas at phi = 0.3: the virial pressure follows Henderson's equation of state",
          "[analysis][pressure]") {
  // 400 disks, phi = 0.3: Z_H = 2.0638. Henderson agrees with simulations to ~0.5% here; finite N adds
  // O(1/N) = 0.25%. Tolerance: 4 sigma + 0.5% of Z_H.
  const double r0 = std::sqrt(0.3 / (400 * M_PI));
  const auto run = run_logged<double>(lattice_gas(20, r0, 1.0, 5), periodic_until(30), "pressure-dense.ede");
  const PressureReport r = measure(run.path);
  const double z_h = henderson_z(0.3);
  REQUIRE(r.packing_fraction == Approx(0.3).epsilon(1e-12));
  INFO("Z_virial = " << r.z_virial.stats.mean << " +- " << r.z_virial.stats.error << ", Henderson " << z_h);
  CHECK(r.z_virial.stats.error < 0.005 * z_h);
  CHECK(std::fabs(r.z_virial.stats.mean - z_h) < 4 * r.z_virial.stats.error + 0.005 * z_h);
  CHECK(r.default_start);
  CHECK(r.t0 == Approx(20 * r.mean_free_time).epsilon(1e-12));
  CHECK(r.totals.wall_collisions == 0);
}

TEST_CASE("measure_pressure refuses an empty window, a window past the log's end, and one block",
          "[analysis][pressure]") {
  InitialState s = box();
  s.add(0.5, 0.5, 2.0, 0.0, 0.1, 3.0, 0);
  const auto run = run_logged<double>(s, walls_until(2), "pressure-refuse.ede");
  const auto log = open_public_log(run.path);
  const auto error_of = [&](const PressureOptions& o) {
    auto r = measure_pressure(log, o);
    return r ? std::string() : r.error().message;
  };
  CHECK_THAT(error_of(window(1, 1)), Catch::Contains("empty"));
  CHECK_THAT(error_of(window(1.5, 0.5)), Catch::Contains("empty"));
  CHECK_THAT(error_of(window(0, 3)), Catch::Contains("after the end of the log"));
  CHECK_THAT(error_of(window(0, 1, 1)), Catch::Contains("at least 2 blocks"));
  CHECK(error_of(window(0, 2)).empty());
}

TEST_CASE("pressure: the thermostat's redraws change the kinetic energy the pressure pass integrates",
          "[analysis][pressure][thermostat]") {
  // Found while writing the stress integral: the pressure pass skipped thermostat events, so its mirror of
  // the velocities went stale and K drifted from the state's. K at the window's end must be the state's.
  const std::string path = temp_path("pressure-thermostat.ede");
  auto sim = Simulation::create(parse_scene_text(R"(seed = 6
[box]
size = [1.0, 1.0]
boundary = "periodic"
[thermostat]
temperature = 2.0
rate = 5.0
[[species]]
name = "gas"
count = 100
radius = 0.01
[species.velocity]
kind = "maxwell"
temperature = 0.5
[stop]
time = 1.0
)", "thermostat.toml").value(), {.log_path = path}).value();
  REQUIRE(sim.run() == RunStatus::ReachedTime);
  REQUIRE(sim.close());
  const Log log = Log::open(path).value();
  PressureOptions p;
  p.from = 0.1, p.to = 1.0;
  const PressureReport r = measure_pressure(log, p).value();
  const Temperature end = temperature_of(log.state_at(1.0).value());
  CHECK(r.totals.kinetic_end == Approx(end.kinetic_cm).epsilon(1e-12));
}
