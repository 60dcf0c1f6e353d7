// The shear viscosity of sheared runs (ede/viscosity.hpp: sheared_viscosity, zero_shear_viscosity) and
// the stress integral of a Lees-Edwards log it rests on (analysis/stress_walk.cpp): a collision with the
// sliding image in closed form, a thermostatted sheared gas against the integral computed another way
// (every disk summed between events, exact by Simpson's rule), the refusals, and (slow) the zero-shear
// viscosity of a dilute gas against Enskog with the energy balance of the thermostat about the flow.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "ede/ede.hpp"
#include "tool_runner.hpp"  // temp_path

using namespace ede;

namespace {

Log run_scene(const std::string& text, const std::string& file) {
  const std::string path = test::temp_path(file);
  auto sim = Simulation::create(parse_scene_text(text, file).value(), {.log_path = path}).value();
  sim.run();
  REQUIRE(sim.close());
  return Log::open(path).value();
}

// The separation r_i - r_j through the sliding image when the pair is across the top or bottom edge,
// written out as the geometry says (not the library's code): j's image above is at (x_j + offset, y_j + ly).
void image_separation(long double& dx, long double& dy, long double offset, long double lx, long double ly) {
  if (dy > ly / 2) dy -= ly, dx -= offset;
  if (dy < -ly / 2) dy += ly, dx += offset;
  while (dx > lx / 2) dx -= lx;
  while (dx < -lx / 2) dx += lx;
}

}  // namespace

TEST_CASE("sheared stress: a disk at rest hit by a sliding image, in closed form", "[analysis][viscosity][shear]") {
  // Box 10 x 10 at rate 0.1 (the images slide at 1): A at rest at (5, 9.9), B at rest at (2, 0.05), radii
  // 0.1. B's image above, at (2 + t, 10.05), touches A at t_c = 3 - d, d = sqrt(0.0175); the contact normal
  // from the image to A is (a, -b)... (tests/engine/test_shear.cpp): A leaves with (a^2, -a b), B with
  // (-a^2, a b), a = d / 0.2, b = 0.75. r_AB (through the image) = (d, -0.15).
  // Impulse terms: r_a dp_b with dp_A = (a^2, -a b). Kinetic part relative to the flow rate * y and the
  // mean: before t_c only c_x = -rate y differs between them (-0.99 and -0.005, mean -0.4975: deviations
  // -+0.4925); after, c_y = -+a b and the deviations of c_x are +-(a^2 - 0.4925 + 0.1 a b tau), tau = t - t_c.
  const std::string text =
      "seed = 1\n[box]\nsize = [10.0, 10.0]\nboundary = \"lees-edwards\"\nshear_rate = 0.1\n[[species]]\nname = \"d\"\n"
      "radius = 0.1\n[species.placement]\nkind = \"explicit\"\npositions = [[5.0, 9.9], [2.0, 0.05]]\n"
      "[species.velocity]\nkind = \"list\"\nvalues = [[0.0, 0.0], [0.0, 0.0]]\n[stop]\ntime = 3.0\n";
  const Log log = run_scene(text, "sheared-image-hit.ede");
  const StressIntegral w = stress_integral(log, 0, 3, 1).value();
  REQUIRE(w.pair_events == 1);
  CHECK(w.shear_rate == 0.1);
  const long double d = std::sqrt(0.0175L), a = d / 0.2L, b = 0.75L, tc = 3 - d, rest = 3 - tc;
  CHECK(double(w.impulse_xx) == Approx(double(d * a * a)).epsilon(1e-12));
  CHECK(double(w.impulse_xy) == Approx(double(-d * a * b)).epsilon(1e-12));
  CHECK(double(w.impulse_yx) == Approx(double(-0.15L * a * a)).epsilon(1e-12));
  CHECK(double(w.impulse_yy) == Approx(double(0.15L * a * b)).epsilon(1e-12));
  const long double d0 = a * a - 0.4925L, k = 0.1L * a * b;
  const long double kxx = 2 * 0.4925L * 0.4925L * tc + 2 * (d0 * d0 * rest + d0 * k * rest * rest + k * k * rest * rest * rest / 3);
  const long double kxy = -2 * a * b * (d0 * rest + k * rest * rest / 2), kyy = 2 * a * a * b * b * rest;
  CHECK(double(w.kinetic_xx) == Approx(double(kxx)).epsilon(1e-12));
  CHECK(double(w.kinetic_xy) == Approx(double(kxy)).epsilon(1e-12));
  CHECK(double(w.kinetic_yy) == Approx(double(kyy)).epsilon(1e-12));
  CHECK(w.kinetic[0] == Approx(double(kxx + kyy)).epsilon(1e-12));
}

TEST_CASE("sheared stress: a thermostatted sheared gas, against every disk summed between events",
          "[analysis][viscosity][shear]") {
  // 30 disks of masses 1 and 2 at packing ~0.2, rate 0.5, the thermostat about the flow, ~3000 events
  // (the walk moves its reference time every 1024: crossed twice). The reference here keeps each disk's
  // height and velocity, and between two events integrates sum m c_a c_b - (sum m c_a)(sum m c_b) / M,
  // c = (v_x - rate y(t), v_y), over all disks by Simpson's rule, exact for these quadratics in t; each
  // pair adds r_a dp_b through the sliding image (image_separation above). Bins of 5 from t = 2.
  const std::string text =
      "seed = 7\n[box]\nsize = [6.0, 6.0]\nboundary = \"lees-edwards\"\nshear_rate = 0.5\n"
      "[thermostat]\ntemperature = 1.0\nrate = 0.2\n"
      "[[species]]\nname = \"light\"\ncount = 20\nradius = 0.3\n[species.velocity]\nkind = \"maxwell\"\ntemperature = 1.0\n"
      "[[species]]\nname = \"heavy\"\ncount = 10\nradius = 0.3\nmass = 2.0\n[species.velocity]\nkind = \"maxwell\"\n"
      "temperature = 1.0\n[stop]\ntime = 40.0\n";
  const Log log = run_scene(text, "sheared-walk-reference.ede");
  const double from = 2, width = 5, rate = 0.5, lx = 6, ly = 6;
  const std::size_t bins = 7;
  const StressIntegral w = stress_integral(log, from, width, bins).value();
  CHECK(w.thermostat_events > 50);

  const State s = log.state_at(from).value();
  const std::size_t n = s.size();
  std::vector<long double> m(n), y(n), vx(n), vy(n), t0(n, from);
  long double total = 0;
  for (std::size_t i = 0; i < n; ++i)
    m[i] = s.mass[i], y[i] = s.y[i], vx[i] = s.vx[i], vy[i] = s.vy[i], total += m[i];
  std::vector<long double> xx(bins, 0), yy(bins, 0), xy(bins, 0), yx(bins, 0);
  long double t_prev = from;
  const auto integrand = [&](long double t, long double& fxx, long double& fyy, long double& fxy) {
    long double sxx = 0, syy = 0, sxy = 0, px = 0, py = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const long double cx = vx[i] - rate * (y[i] + vy[i] * (t - t0[i])), cy = vy[i];
      sxx += m[i] * cx * cx, syy += m[i] * cy * cy, sxy += m[i] * cx * cy, px += m[i] * cx, py += m[i] * cy;
    }
    fxx = sxx - px * px / total, fyy = syy - py * py / total, fxy = sxy - px * py / total;
  };
  const auto integrate_to = [&](long double t) {
    while (t_prev < t) {
      const std::size_t k = std::min<std::size_t>(bins - 1, std::size_t((t_prev - from) / width));
      const long double end = std::min<long double>(t, from + width * (k + 1));
      long double a[3], b[3], c[3];
      integrand(t_prev, a[0], a[1], a[2]);
      integrand((t_prev + end) / 2, b[0], b[1], b[2]);
      integrand(end, c[0], c[1], c[2]);
      const long double h = (end - t_prev) / 6;
      xx[k] += h * (a[0] + 4 * b[0] + c[0]), yy[k] += h * (a[1] + 4 * b[1] + c[1]);
      xy[k] += h * (a[2] + 4 * b[2] + c[2]), yx[k] += h * (a[2] + 4 * b[2] + c[2]);
      t_prev = end;
    }
  };
  EventRange range;
  range.from_time = std::nextafter(from, 100.0);
  range.to_time = from + width * bins;
  const EventColumns e = log.event_columns(range, true, true).value();
  REQUIRE(e.size() > 2000);
  for (std::size_t k = 0; k < e.size(); ++k) {
    const long double t = e.time[k];
    integrate_to(t);
    const auto kind = EventKind(e.kind[k]);
    const auto i = std::size_t(e.i[k]);
    const std::size_t bin = std::min<std::size_t>(bins - 1, std::size_t((t - from) / width));
    if (kind == EventKind::Pair) {
      const auto j = std::size_t(e.j[k]);
      long double dx = (long double)e.xi[k] - e.xj[k], dy = (long double)e.yi[k] - e.yj[k];
      image_separation(dx, dy, std::fmod((long double)rate * ly * t, (long double)lx), lx, ly);
      const long double px = m[i] * ((long double)e.vix[k] - e.vix_before[k]);
      const long double py = m[i] * ((long double)e.viy[k] - e.viy_before[k]);
      xx[bin] += dx * px, yy[bin] += dy * py, xy[bin] += dx * py, yx[bin] += dy * px;
      y[j] = e.yj[k], vx[j] = e.vjx[k], vy[j] = e.vjy[k], t0[j] = t;
    }
    if (kind == EventKind::Pair || kind == EventKind::Shear || kind == EventKind::Thermostat)
      y[i] = e.yi[k], vx[i] = e.vix[k], vy[i] = e.viy[k], t0[i] = t;
  }
  integrate_to(from + width * bins);
  for (std::size_t k = 0; k < bins; ++k) {
    INFO("bin " << k);
    CHECK(w.xx[k] == Approx(double(xx[k])).epsilon(1e-10));
    CHECK(w.yy[k] == Approx(double(yy[k])).epsilon(1e-10));
    CHECK(w.xy[k] == Approx(double(xy[k])).epsilon(1e-9).margin(1e-9 * double(yy[k])));
    CHECK(w.yx[k] == Approx(double(yx[k])).epsilon(1e-9).margin(1e-9 * double(yy[k])));
  }
}

TEST_CASE("sheared viscosity: what it refuses, and the zero-shear fit's checks", "[analysis][viscosity][shear]") {
  const std::string periodic =
      "seed = 2\n[box]\nsize = [6.0, 6.0]\nboundary = \"periodic\"\n[[species]]\nname = \"gas\"\ncount = 20\n"
      "radius = 0.3\n[species.velocity]\nkind = \"maxwell\"\ntemperature = 1.0\n[stop]\ntime = 5.0\n";
  const Log plain = run_scene(periodic, "sheared-refuse-periodic.ede");
  using Catch::Matchers::Contains;
  CHECK_THAT(sheared_viscosity(plain).error().message, Contains("not sheared") && Contains("shear_viscosity"));
  std::string text = periodic;
  text.replace(text.find("\"periodic\""), 10, "\"lees-edwards\"\nshear_rate = 0.2");
  const Log sheared = run_scene(text, "sheared-refuse-sheared.ede");
  ViscosityOptions equilibrium;
  equilibrium.lag_step = 0.01, equilibrium.max_lag = 0.1;
  CHECK_THAT(shear_viscosity(sheared, equilibrium).error().message, Contains("sheared") && Contains("sheared_viscosity"));
  ShearedOptions o;
  o.blocks = 1;
  CHECK_THAT(sheared_viscosity(sheared, o).error().message, Contains("2 blocks"));
  const ShearedViscosity one = sheared_viscosity(sheared).value();
  CHECK(one.shear_rate == 0.2);
  CHECK(one.sigma == 0.6);
  CHECK(one.reduced_rate == Approx(0.2 * 0.6 / std::sqrt(one.kT)).epsilon(1e-14));
  CHECK(one.reduced_viscosity == Approx(one.viscosity * 0.6 / std::sqrt(one.kT)).epsilon(1e-14));
  CHECK_THAT(zero_shear_viscosity({one}).error().message, Contains("two rates"));
  CHECK_THAT(zero_shear_viscosity({one, one}).error().message, Contains("different shear rates"));
  // An exact line through three points: the fit recovers it, with chi2 0.
  std::vector<ShearedViscosity> line(3, one);
  for (std::size_t k = 0; k < 3; ++k) {
    line[k].reduced_rate = 0.1 * double(k + 1);
    line[k].reduced_viscosity = 0.3 - 2 * line[k].reduced_rate * line[k].reduced_rate;
    line[k].reduced_viscosity_error = 0.01 * double(k + 1);
  }
  const ZeroShearFit f = zero_shear_viscosity(line).value();
  CHECK(f.reduced_viscosity == Approx(0.3).epsilon(1e-12));
  CHECK(f.slope == Approx(-2).epsilon(1e-12));
  CHECK(f.chi2 == Approx(0).margin(1e-20));
  CHECK(f.reduced_viscosity_error > 0.01);  // an intercept extrapolated beyond the points is less certain than they
}

namespace {

// 400 unit disks (sigma = 1, m = 1) at packing phi in a Lees-Edwards box sheared at `rate`, the thermostat
// about the flow at kT = 1 and rate nu per disk, run to `until`.
Log sheared_gas(double phi, double rate, double nu, double until, const std::string& file) {
  const double side = std::sqrt(400 * std::numbers::pi * 0.25 / phi);
  const std::string text =
      "seed = 5\n[box]\nsize = [" + general_text(side, 17) + ", " + general_text(side, 17) +
      "]\nboundary = \"lees-edwards\"\nshear_rate = " + general_text(rate, 17) + "\n[thermostat]\ntemperature = 1.0\n"
      "rate = " + general_text(nu, 17) + "\n[[species]]\nname = \"gas\"\ncount = 400\nradius = 0.5\n"
      "[species.velocity]\nkind = \"maxwell\"\ntemperature = 1.0\n[stop]\ntime = " + general_text(until, 17) + "\n";
  return run_scene(text, file);
}

// The energy the flow-relative kinetic energy E' = sum m (v - u(y))^2 / 2, u = rate (y - ly/2), gains over
// [from, to] in three parts: the shear's work on the peculiar motion, -rate * (the xy stress integral),
// the work on the centre-of-mass motion U relative to the flow, -rate * integral of M U_x U_y (between
// redraws U_y is constant and U_x falls at rate * U_y: the sliding edges turn a net vertical drift into a
// horizontal one), and the redraws' changes of E'. Their sum must equal E'(to) - E'(from) to round-off.
void check_energy_identity(const Log& log, double from, double to) {
  const double rate = *log.scene().value().shear_rate, ly = log.info().ly;
  const StressIntegral w = stress_integral(log, from, to - from, 1).value();
  const long double stress_work = -rate * 0.5L * ((long double)w.xy[0] + w.yx[0]);
  EventRange range;
  range.from_time = std::nextafter(from, to), range.to_time = to;
  const EventColumns e = log.event_columns(range, true, true).value();
  const State s0 = log.state_at(from).value(), s1 = log.state_at(to).value();
  const auto flow_energy = [&](const State& s) {
    long double energy = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      energy += 0.5L * s.mass[i] * (std::pow((long double)s.vx[i] - rate * ((long double)s.y[i] - ly / 2), 2) +
                                    std::pow((long double)s.vy[i], 2));
    return energy;
  };
  long double mass = 0, px = 0, py = 0;  // M, M U_x, M U_y (all disks of unit mass here)
  for (std::size_t i = 0; i < s0.size(); ++i)
    mass += 1, px += s0.vx[i] - rate * ((long double)s0.y[i] - ly / 2), py += s0.vy[i];
  long double t_prev = from, drift = 0, redraws = 0;
  const auto drift_to = [&](long double t) {
    const long double dt = t - t_prev;
    drift += (px * py * dt - rate * py * py * dt * dt / 2) / mass;
    px -= rate * py * dt, t_prev = t;
  };
  for (std::size_t k = 0; k < e.size(); ++k) {
    if (EventKind(e.kind[k]) != EventKind::Thermostat) continue;
    drift_to(e.time[k]);
    const long double u = rate * ((long double)e.yi[k] - ly / 2);
    const auto energy = [&](long double vx, long double vy) { return 0.5L * ((vx - u) * (vx - u) + vy * vy); };
    redraws += energy(e.vix[k], e.viy[k]) - energy(e.vix_before[k], e.viy_before[k]);
    px += (long double)e.vix[k] - e.vix_before[k], py += (long double)e.viy[k] - e.viy_before[k];
  }
  drift_to(to);
  const long double gained = flow_energy(s1) - flow_energy(s0), drift_work = -rate * drift;
  INFO("stress work " << double(stress_work) << ", drift work " << double(drift_work) << ", redraws "
                      << double(redraws) << ", E' gained " << double(gained));
  CHECK(std::fabs(double(stress_work + drift_work + redraws - gained)) < 1e-8 * double(stress_work));
}

}  // namespace

TEST_CASE("sheared viscosity: a dilute and a moderately dense gas, extrapolated to zero shear, against Enskog",
          "[analysis][viscosity][shear][slow]") {
  // Three rates per density, the thermostat about the flow at nu = 0.005 (phi = 0.1) and 0.02 (phi = 0.3):
  // its redraws relax the stress besides the collisions, lowering eta by about nu tau_eta ~ 1 % here
  // (docs/analysis.md). The steady temperature rises with the rate (kT - 1 = -P_xy rate A / (nu N) less
  // the drift's share), so the reduced rates are 0.018-0.027 and 0.046-0.074. Tolerances as for the
  // equilibrium route (test_viscosity_enskog.cpp): 4 standard errors plus 5 % at phi = 0.1 and 8 % at
  // phi = 0.3 for Enskog's own error; each run's eta within them too. Measured (seed 5): eta0* / eta_E*
  // 0.974 +- 0.024 (phi = 0.1, 20 000 time units), 1.057 +- 0.026 (phi = 0.3, 5 000).
  struct Case {
    double phi, nu, until, from, allowance;
    std::vector<double> rates;
  };
  for (const Case& c : {Case{0.1, 0.005, 12000, 2000, 0.05, {0.02, 0.04, 0.06}},
                        Case{0.3, 0.02, 4000, 500, 0.08, {0.05, 0.1, 0.15}}}) {
    std::vector<ShearedViscosity> runs;
    for (const double rate : c.rates) {
      const Log log = sheared_gas(c.phi, rate, c.nu, c.until, "sheared-gas-" + general_text(c.phi, 3) + "-" +
                                                                  general_text(rate, 3) + ".ede");
      ShearedOptions o;
      o.from = c.from;
      const ShearedViscosity v = sheared_viscosity(log, o).value();
      INFO("phi " << c.phi << ", rate " << rate << ": kT " << v.kT << ", eta* " << v.reduced_viscosity << " +- "
                  << v.reduced_viscosity_error << " at rate* " << v.reduced_rate << ", eta / eta_E "
                  << v.viscosity / v.enskog);
      CHECK(v.packing_fraction == Approx(c.phi).epsilon(1e-6));
      CHECK(v.reduced_viscosity_error < 0.03 * v.reduced_viscosity);
      CHECK(std::fabs(v.viscosity / v.enskog - 1) < c.allowance + 4 * v.viscosity_error / v.enskog);
      CHECK(v.shear_stress < 0);
      if (rate == c.rates.front()) check_energy_identity(log, c.from, c.until);
      runs.push_back(v);
    }
    const ZeroShearFit f = zero_shear_viscosity(runs).value();
    INFO("phi " << c.phi << ": eta0* " << f.reduced_viscosity << " +- " << f.reduced_viscosity_error << ", Enskog "
                << f.enskog_reduced << ", chi2 " << f.chi2);
    CHECK(std::fabs(f.reduced_viscosity / f.enskog_reduced - 1) <
          c.allowance + 4 * f.reduced_viscosity_error / f.enskog_reduced);
    CHECK(f.reduced_viscosity_error < 0.05 * f.reduced_viscosity);
  }
}
