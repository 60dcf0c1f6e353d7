// The exact stress integral (ede/viscosity.hpp, analysis/stress_walk.cpp) on runs small enough to compute
// by hand: a head-on pair (every bin in closed form), a pair meeting obliquely across a periodic edge with
// unequal masses and a net momentum (the integral from the logged events with the formula written out
// here), a pass through a square well (the steps' impulses in closed form), the trace against the pressure
// analysis, and the logs the analysis must refuse.
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/ede.hpp"
#include "log_test_support.hpp"
#include "tool_runner.hpp"  // temp_path

using namespace ede;
using namespace ede::test;

namespace {

EngineOptions periodic_until(double t) {
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.time = t;
  return o;
}

long double sum(const std::vector<double>& v) {
  long double s = 0;
  for (const double x : v) s += x;
  return s;
}

Log run_scene(const char* text, const std::string& file) {
  const std::string path = temp_path(file);
  auto sim = Simulation::create(parse_scene_text(text, file).value(), {.log_path = path}).value();
  sim.run();
  REQUIRE(sim.close());
  return Log::open(path).value();
}

// Disks of radius 0.1 and unit mass at (0.25, 0.425) with v = (1, 0.5) and (0.75, 0.575) with v = (-1, -0.5),
// periodic unit box, t = 0.3: one collision, at t_c = 0.15.
Log head_on_pair(const std::string& file) {
  InitialState s = box();
  s.add(0.25, 0.425, 1, 0.5, 0.1, 1, 0);
  s.add(0.75, 0.575, -1, -0.5, 0.1, 1, 0);
  return Log::open(run_logged<double>(s, periodic_until(0.3), file).path).value();
}

}  // namespace

TEST_CASE("stress integral: a head-on pair in a periodic box, every bin by hand", "[analysis][viscosity]") {
  // Disks of radius 0.1 and unit mass at (0.25, 0.425) with v = (1, 0.5) and (0.75, 0.575) with v = (-1, -0.5):
  // at t_c = 0.15 both are at y = 0.5, 0.2 apart along x, and swap their x velocities. Total momentum 0.
  // Per unit time: sum m vx^2 = 2, sum m vy^2 = 0.5, sum m vx vy = 1 before and -1 after. The impulse on
  // disk 0 is (-2, 0) at r_01 = (-0.2, 0): +0.4 on xx, nothing off the diagonal.
  const Log log = head_on_pair("viscosity-head-on.ede");
  const StressIntegral w = stress_integral(log, 0, 0.1, 3).value();
  REQUIRE(w.bins() == 3);
  CHECK(w.pair_events == 1);
  CHECK(w.area == 1);
  const double xx[] = {0.2, 0.6, 0.2}, yy[] = {0.05, 0.05, 0.05}, xy[] = {0.1, 0, -0.1};
  for (std::size_t k = 0; k < 3; ++k) {
    INFO("bin " << k);
    CHECK(w.xx[k] == Approx(xx[k]).epsilon(1e-14));
    CHECK(w.yy[k] == Approx(yy[k]).epsilon(1e-14));
    CHECK(w.xy[k] == Approx(xy[k]).epsilon(1e-14).margin(1e-15));
    CHECK(w.yx[k] == w.xy[k]);
  }
  CHECK(double(w.impulse_xx) == Approx(0.4).epsilon(1e-14));
  CHECK(double(w.impulse_xy) == Approx(0).margin(1e-15));  // the contact normal is x to round-off
  CHECK(double(w.kinetic_xx) == Approx(0.6).epsilon(1e-14));
}

TEST_CASE("stress integral: an oblique collision across a periodic edge, masses 1 and 3, with net momentum",
          "[analysis][viscosity]") {
  // Disk 0 near the right edge moving right and up, disk 1 just across the edge moving left: they meet
  // through the edge, so r_01 is the nearest image's. The expected integral is the definition evaluated on
  // the logged events: the kinetic sum relative to the centre of mass over each interval, and r_01,a dp_0,b.
  InitialState s = box();
  s.add(0.9, 0.48, 0.8, 0.3, 0.05, 1, 0);
  s.add(0.1, 0.53, -0.6, 0.1, 0.05, 3, 0);
  const auto run = run_logged<double>(s, periodic_until(0.4), "viscosity-oblique.ede");
  const Log log = Log::open(run.path).value();
  std::vector<Event> events;
  REQUIRE(log.for_each_event({}, [&](const Event& e) { events.push_back(e); return true; }));
  std::size_t pairs = 0;
  for (const Event& e : events) pairs += e.kind == EventKind::Pair;
  REQUIRE(pairs == 1);

  // The definition, event by event, in long double.
  long double m[2] = {1, 3}, vx[2] = {0.8, -0.6}, vy[2] = {0.3, 0.1};
  long double t_prev = 0, xx = 0, yy = 0, xy = 0, yx = 0, impulse_xy = 0;
  const auto kinetic_to = [&](long double t) {
    const long double px = m[0] * vx[0] + m[1] * vx[1], py = m[0] * vy[0] + m[1] * vy[1], mass = m[0] + m[1];
    const long double dt = t - t_prev;
    xx += (m[0] * vx[0] * vx[0] + m[1] * vx[1] * vx[1] - px * px / mass) * dt;
    yy += (m[0] * vy[0] * vy[0] + m[1] * vy[1] * vy[1] - py * py / mass) * dt;
    const long double k = (m[0] * vx[0] * vy[0] + m[1] * vx[1] * vy[1] - px * py / mass) * dt;
    xy += k, yx += k;
    t_prev = t;
  };
  for (const Event& e : events) {
    if (e.kind != EventKind::Pair) continue;
    kinetic_to(e.time);
    long double rx = e.xi - e.xj, ry = e.yi - e.yj;
    rx -= std::nearbyint(rx), ry -= std::nearbyint(ry);  // unit box
    CHECK(std::fabs(double(rx)) < 0.11);                 // the image across the edge, not 0.8 apart
    const long double dpx = m[e.i] * (e.vix - e.vix_before), dpy = m[e.i] * (e.viy - e.viy_before);
    xx += rx * dpx, yy += ry * dpy, xy += rx * dpy, yx += ry * dpx, impulse_xy = rx * dpy;
    vx[e.i] = e.vix, vy[e.i] = e.viy, vx[e.j] = e.vjx, vy[e.j] = e.vjy;
  }
  kinetic_to(0.4);
  CHECK(std::fabs(double(impulse_xy)) > 1e-3);  // the collision is oblique: it shears

  const StressIntegral w = stress_integral(log, 0, 0.05, 8).value();
  CHECK(double(sum(w.xx)) == Approx(double(xx)).epsilon(1e-14));
  CHECK(double(sum(w.yy)) == Approx(double(yy)).epsilon(1e-14));
  CHECK(double(sum(w.xy)) == Approx(double(xy)).epsilon(1e-14));
  CHECK(double(sum(w.yx)) == Approx(double(yx)).epsilon(1e-14));
  CHECK(double(w.impulse_xy) == Approx(double(impulse_xy)).epsilon(1e-14));
}

TEST_CASE("stress integral: a pass through a square well adds the steps' impulses like collisions",
          "[analysis][viscosity][steps]") {
  // Unit masses at x = 0.2 and 0.8 (y = 0.5), v = +-1, sigma = 1/8, a well of depth 3/4 out to 1/4 (as
  // tests/engine/test_steps.cpp): they enter the well at t1 = 0.175 with vx = +-sqrt(7)/2, collide at
  // t1 + 0.125/sqrt(7) and leave at t3 = t1 + 0.25/sqrt(7) with vx = -+1. Impulses on disk 0 along x at
  // r_01 = -1/4, -1/8, -1/4: sqrt(7)/2 - 1, -sqrt(7), sqrt(7)/2 - 1, so the impulse sum on xx is
  // 1/2 - sqrt(7)/8 (the well's pull is a negative virial). Kinetic: sum m vx^2 = 2 outside, 7/2 inside.
  InitialState s = box();
  s.add(0.2, 0.5, 1, 0, 1.0 / 16, 1, 0);
  s.add(0.8, 0.5, -1, 0, 1.0 / 16, 1, 0);
  EngineOptions o = periodic_until(0.5);
  o.physics.steps.push_back({"", "", {0.25}, {-0.75}});
  const auto run = run_logged<double>(s, o, "viscosity-well.ede");
  const Log log = Log::open(run.path).value();
  const StressIntegral w = stress_integral(log, 0, 0.1, 5).value();
  CHECK(w.pair_events == 1);
  CHECK(w.step_events == 2);
  const double s7 = std::sqrt(7.0), t1 = 0.175, t3 = t1 + 0.25 / s7;
  CHECK(double(w.impulse_xx) == Approx(0.5 - s7 / 8).epsilon(1e-14));
  CHECK(double(w.kinetic_xx) == Approx(2 * t1 + 3.5 * (t3 - t1) + 2 * (0.5 - t3)).epsilon(1e-14));
  CHECK(double(sum(w.xx)) == Approx(0.5 - s7 / 8 + 2 * t1 + 3.5 * (t3 - t1) + 2 * (0.5 - t3)).epsilon(1e-14));
  CHECK(double(sum(w.yy)) == 0);
  CHECK(double(sum(w.xy)) == 0);
}

TEST_CASE("stress integral: its trace is the pressure analysis's virial and kinetic integral", "[analysis][viscosity]") {
  // Two independent walks over the same window (pressure_pass.cpp replays with the internal reader,
  // stress_walk.cpp reads columns): sum r . dp and 2 integral K' dt must agree to round-off.
  const Log log = run_scene(R"(seed = 4
[box]
size = [1.0, 1.0]
boundary = "periodic"
[[species]]
name = "gas"
count = 200
radius = 0.012
[species.velocity]
kind = "maxwell"
temperature = 1.0
[stop]
time = 1.0
)", "viscosity-trace.ede");
  PressureOptions p;
  p.from = 0.2, p.to = 1.0;
  const PressureReport r = measure_pressure(log, p).value();
  const StressIntegral w = stress_integral(log, 0.2, 0.01, 80).value();
  CHECK(w.pair_events == r.totals.pair_collisions);
  CHECK(double(w.impulse_xx + w.impulse_yy) == Approx(r.totals.virial_sum).epsilon(1e-12));
  CHECK(double(w.kinetic_xx + w.kinetic_yy) == Approx(2 * r.totals.kinetic_integral).epsilon(1e-12));
}

TEST_CASE("viscosity: logs it cannot use are refused with the reason", "[analysis][viscosity]") {
  ViscosityOptions o;
  o.lag_step = 0.01, o.max_lag = 0.05;
  SECTION("walls") {
    InitialState s = box();
    s.add(0.3, 0.5, 1, 0.2, 0.05, 1, 0);
    s.add(0.7, 0.5, -1, 0.1, 0.05, 1, 0);
    const auto run = run_logged<double>(s, walls_until(0.5), "viscosity-walls.ede");
    const Log log = Log::open(run.path).value();
    const auto v = shear_viscosity(log, o);
    REQUIRE_FALSE(v.ok());
    CHECK_THAT(v.error().message, Catch::Contains("viscosity-walls.ede") && Catch::Contains("periodic"));
    CHECK_FALSE(stress_integral(log, 0, 0.1, 2).ok());
  }
  const char* gas = R"(seed = 3
[box]
size = [1.0, 1.0]
boundary = "periodic"
[[species]]
name = "gas"
count = 50
radius = 0.01
[species.velocity]
kind = "maxwell"
temperature = 1.0
[stop]
time = 0.5
)";
  SECTION("the Andersen thermostat") {
    const std::string text = std::string(gas) + "[thermostat]\ntemperature = 1.0\nrate = 2.0\n";
    const auto v = shear_viscosity(run_scene(text.c_str(), "viscosity-thermostat.ede"), o);
    REQUIRE_FALSE(v.ok());
    CHECK_THAT(v.error().message, Catch::Contains("thermostat") && Catch::Contains("[start]"));
  }
  SECTION("inelastic collisions") {
    const std::string text = std::string(gas) + "[physics]\nrestitution = 0.9\n";
    const auto v = shear_viscosity(run_scene(text.c_str(), "viscosity-inelastic.ede"), o);
    REQUIRE_FALSE(v.ok());
    CHECK_THAT(v.error().message, Catch::Contains("inelastic"));
  }
  SECTION("a time reversal inside the window, but not before it") {
    const std::string text = std::string(gas) + "[[actions]]\ntime = 0.3\nkind = \"reverse_velocities\"\n";
    const Log log = run_scene(text.c_str(), "viscosity-reversal.ede");
    const auto v = shear_viscosity(log, o);
    REQUIRE_FALSE(v.ok());
    CHECK_THAT(v.error().message, Catch::Contains("action event") && Catch::Contains("window"));
    o.to = 0.25;
    CHECK(shear_viscosity(log, o).ok());
  }
}

TEST_CASE("viscosity: the Helfand moment and the Green-Kubo integral of a known bin sequence", "[analysis][viscosity]") {
  // The head-on pair run for t = 0.3 in bins of 0.1: the shear component is W = (0.1, 0, -0.1), the normal one
  // N = ((0.2 - 0.05) / 2, (0.6 - 0.05) / 2, (0.2 - 0.05) / 2) = (0.075, 0.275, 0.075). One lag (0.1), origins
  // s = 0, 1 in 2 blocks: H = (W_0^2 + W_1^2) / 2 per component; eta = H / (2 V kT dt), with
  // kT = integral K' / ((N - 1) T) = (0.6 + 0.15) / 2 / 0.3 = 1.25.
  const Log log = head_on_pair("viscosity-helfand.ede");
  ViscosityOptions o;
  o.lag_step = 0.1, o.max_lag = 0.1, o.blocks = 2;
  const ShearViscosity v = shear_viscosity(log, o).value();
  REQUIRE(v.lag.size() == 1);
  CHECK(v.kT == Approx(1.25).epsilon(1e-14));
  CHECK(v.origins == 2);
  const double kT = 1.25, dt = 0.1;
  const double h_shear = (0.01 + 0) / 2, h_normal = (0.075 * 0.075 + 0.275 * 0.275) / 2;
  CHECK(v.eta_xy[0] == Approx(h_shear / (2 * kT * dt)).epsilon(1e-13));
  CHECK(v.eta_normal[0] == Approx(h_normal / (2 * kT * dt)).epsilon(1e-13));
  CHECK(v.eta[0] == Approx((h_shear + h_normal) / 2 / (2 * kT * dt)).epsilon(1e-13));
  // Block 0 holds origin 0, block 1 origin 1: eta_b = (W_s^2 + N_s^2) / 2 / (2 kT dt); error = |eta_0 - eta_1| / 2.
  const double e0 = (0.01 + 0.075 * 0.075) / 2 / (2 * kT * dt), e1 = (0 + 0.275 * 0.275) / 2 / (2 * kT * dt);
  CHECK(v.error[0] == Approx(std::fabs(e0 - e1) / 2).epsilon(1e-13));
  // Green-Kubo at lag 1: (C_0 / 2 + C_1 / 2) / (V kT dt), C_m = <(W_s W_s+m + N_s N_s+m) / 2> over s = 0, 1.
  const double c0 = ((0.01 + 0.075 * 0.075) + (0 + 0.275 * 0.275)) / 4;
  const double c1 = ((0.1 * 0 + 0.075 * 0.275) + (0 * -0.1 + 0.275 * 0.075)) / 4;
  CHECK(v.green_kubo[0] == Approx((c0 / 2 + c1 / 2) / (kT * dt)).epsilon(1e-13));
  CHECK(v.acf[0] == Approx(c1 / (kT * dt * dt)).epsilon(1e-13));
  // Pressure: (integral of (xx + yy) / 2) / (V T) = (1.0 + 0.15) / 2 / 0.3.
  CHECK(v.pressure == Approx(1.15 / 2 / 0.3).epsilon(1e-14));
  CHECK(v.mean_shear_stress == Approx(0).margin(1e-14));
}
