// Transport from logs (transport.hpp): exact MSD and VACF of one free disk crossing periodic edges and of
// two disks colliding head-on, computed by hand; then a dilute periodic gas whose g(sigma) and D are
// compared with Enskog and Henderson within stated tolerances, and g(sigma) from the collision rate with
// the one from the pressure.
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/log.hpp"
#include "ede/structure.hpp"
#include "ede/kinetic_theory.hpp"
#include "ede/transport.hpp"
#include "log_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

Log public_log(const std::string& path) { return Log::open(path).value(); }

EngineOptions periodic_until(double t) {
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.time = t;
  return o;
}

TransportOptions lags(double step, double max, std::size_t origins = 0) {
  TransportOptions o;
  o.lag_step = step, o.max_lag = max, o.origins = origins;
  o.groups = 1;
  return o;
}

}  // namespace

TEST_CASE("one free disk crossing periodic edges: MSD = v^2 tau^2 and VACF = v^2 exactly", "[analysis][transport]") {
  // v = (0.7, 0.3) in the unit periodic box for t = 10: 7 crossings of the x edge, 3 of the y edge, each a
  // wrap event that moves the stored position by one box length; unwrapping must undo every one of them.
  InitialState s = box();
  s.add(0.5, 0.5, 0.7, 0.3, 0.05, 1.0, 0);
  const auto run = run_logged<double>(s, periodic_until(10), "transport-free.ede");
  const Log log = public_log(run.path);
  const MeanSquareDisplacement m = mean_square_displacement(log, lags(0.5, 4, 5)).value();
  REQUIRE(m.lag.size() == 9);
  for (std::size_t k = 0; k < m.lag.size(); ++k) CHECK(m.msd[k] == Approx(0.58 * m.lag[k] * m.lag[k]).epsilon(1e-12));
  const VelocityAutocorrelation v = velocity_autocorrelation(log, lags(0.5, 4)).value();
  for (std::size_t k = 0; k < v.lag.size(); ++k) CHECK(v.c[k] == Approx(0.58).epsilon(1e-12));
  // Green-Kubo: D(t) = (1/2) integral of C = 0.29 t, growing without bound for a free disk.
  CHECK(v.green_kubo.back() == Approx(0.29 * 4).epsilon(1e-12));
}

TEST_CASE("two disks colliding head-on: MSD and VACF by hand", "[analysis][transport]") {
  // Equal masses, r = 0.05, x = 0.3 (v = +1) and 0.7 (v = -1) in a walled unit box: they meet at
  // t_c = 0.15 and swap velocities; no wall is hit before t = 0.55. Window [0, 0.5].
  // VACF of each: integral over t0 in [0, T - tau] of v(t0) v(t0 + tau) = (T - tau) - 2 L, with L the
  // length of the origins [max(0, t_c - tau), min(t_c, T - tau)) whose lag straddles t_c.
  InitialState s = box();
  s.add(0.3, 0.5, 1.0, 0.0, 0.05, 1.0, 0);
  s.add(0.7, 0.5, -1.0, 0.0, 0.05, 1.0, 0);
  const auto run = run_logged<double>(s, walls_until(0.5), "transport-head-on.ede");
  const Log log = public_log(run.path);
  const double tc = 0.15, T = 0.5;
  const VelocityAutocorrelation v = velocity_autocorrelation(log, lags(0.05, 0.45)).value();
  REQUIRE(v.lag.size() == 10);
  for (std::size_t k = 0; k < v.lag.size(); ++k) {
    const double tau = v.lag[k];
    const double l = std::max(0.0, std::min(tc, T - tau) - std::max(0.0, tc - tau));
    INFO("tau = " << tau);
    CHECK(v.c[k] == Approx((T - tau - 2 * l) / (T - tau)).epsilon(1e-12).margin(1e-14));
  }
  // MSD with 3 origins at 0, 0.15, 0.3 (max lag 0.2): x1(t) = 0.3 + t before t_c, 0.45 - (t - t_c) after;
  // disk 2 mirrors it, so both have the same squared displacement.
  const MeanSquareDisplacement m = mean_square_displacement(log, lags(0.05, 0.2, 3)).value();
  const auto x1 = [&](double t) { return t < tc ? 0.3 + t : 0.45 - (t - tc); };
  for (std::size_t k = 0; k < m.lag.size(); ++k) {
    double expected = 0;
    for (const double t0 : {0.0, 0.15, 0.3}) expected += std::pow(x1(t0 + m.lag[k]) - x1(t0), 2) / 3;
    INFO("lag " << m.lag[k]);
    CHECK(m.msd[k] == Approx(expected).epsilon(1e-12).margin(1e-15));
  }
}

TEST_CASE("transport refuses gravity, an empty window and lags longer than the window", "[analysis][transport]") {
  InitialState s = box();
  s.add(0.5, 0.5, 0.7, 0.3, 0.05, 1.0, 0);
  const auto run = run_logged<double>(s, periodic_until(1), "transport-refuse.ede");
  const Log log = public_log(run.path);
  auto too_long = mean_square_displacement(log, lags(0.5, 2));
  REQUIRE(!too_long);
  CHECK_THAT(too_long.error().message, Catch::Contains("max lag < window length"));
  TransportOptions o = lags(0.1, 0.5);
  o.from = 0.5, o.to = 0.5;
  CHECK(!velocity_autocorrelation(log, o));
  EngineOptions g = walls_until(1);
  g.physics.gravity = {0, -1};
  const auto fall = run_logged<double>(s, g, "transport-gravity.ede");
  auto refused = velocity_autocorrelation(public_log(fall.path), lags(0.1, 0.5));
  REQUIRE(!refused);
  CHECK_THAT(refused.error().message, Catch::Contains("gravity"));
}

TEST_CASE("a dilute periodic gas: g(sigma) three ways agree, and D is Enskog's within 10 percent", "[analysis][transport][slow]") {
  // 400 disks at phi = 0.05 (unit speed: kT = 1/2, m = 1) for t = 60, window from t = 5 (~70 collisions
  // per disk after the lattice start): ~1.5e5 pair collisions in the window.
  // Tolerances: g(sigma) from the collision rate against Henderson's (1 - 7 phi / 16) / (1 - phi)^2: 4 sigma
  // + 0.5% (Henderson is within ~0.1% of simulations here; finite N adds O(1/N)); the three routes against
  // each other: 4 sigma of the difference (the collision and pressure routes share the collisions, so this
  // is loose for that pair). D from the MSD against Enskog's D_E with Henderson's g(sigma): 10% + 4 sigma,
  // because the first Sonine approximation is low by ~2% in 2D and correlated motion (the long-time tail,
  // which makes D of a 2D fluid grow as ln t) adds a few percent at lags of 15-30 collision times: the run
  // measures D / D_E = 1.06. A factor-of-two error in either formula or in unwrapping fails.
  const double phi = 0.05, r0 = std::sqrt(phi / (400 * M_PI));
  const auto run = run_logged<double>(lattice_gas(20, r0, 1.0, 3), periodic_until(60), "transport-dilute.ede");
  const Log log = public_log(run.path);
  FrameTimes f;
  f.from = 5, f.to = 60, f.frames = 200;
  const ContactValues c = contact_values(log, f, 0.1, 8).value();
  const double g_h = henderson_contact_value(phi);
  INFO("g(sigma): Henderson " << g_h << ", from g(r) " << c.from_gr.value << " +- " << c.from_gr.error
                              << ", from collisions " << c.from_collisions.value << " +- " << c.from_collisions.error
                              << ", from pressure " << c.from_pressure.value << " +- " << c.from_pressure.error);
  CHECK(c.kT == Approx(0.5).epsilon(2e-3));  // in the centre-of-mass frame: the lattice start has a small net momentum
  CHECK(c.from_collisions.error < 0.005 * g_h);
  CHECK(std::fabs(c.from_collisions.value - g_h) < 4 * c.from_collisions.error + 0.005 * g_h);
  CHECK(std::fabs(c.from_collisions.value - c.from_pressure.value) <
        4 * std::hypot(c.from_collisions.error, c.from_pressure.error));
  CHECK(std::fabs(c.from_gr.value - c.from_collisions.value) < 4 * std::hypot(c.from_gr.error, c.from_collisions.error));
  CHECK(c.from_gr.error < 0.08 * g_h);  // the quadratic fit's error: 1.5 times the straight line's (5 %) for 200 frames

  TransportOptions o;
  o.from = 5, o.lag_step = 0.05, o.max_lag = 2, o.origins = 50;
  const MeanSquareDisplacement m = mean_square_displacement(log, o).value();
  const double d_e = enskog_diffusion(c.density, c.sigma, g_h, c.kT, 1.0);
  INFO("D = " << m.diffusion << " +- " << m.diffusion_error << ", Enskog " << d_e);
  CHECK(m.diffusion_error < 0.03 * d_e);
  CHECK(std::fabs(m.diffusion - d_e) < 0.1 * d_e + 4 * m.diffusion_error);
  // The VACF starts at <v^2> = 1 (unit speeds) and its Green-Kubo integral gives D too.
  const VelocityAutocorrelation v = velocity_autocorrelation(log, o).value();
  CHECK(v.c[0] == Approx(1).epsilon(1e-12));
  CHECK(std::fabs(v.green_kubo.back() - d_e) < 0.15 * d_e);
}
