// Lees-Edwards shear (engine/lees_edwards.hpp, room_shear.hpp, the sheared pair scan in room_pair.hpp):
// the crossing of a sliding edge to the bit on hand-picked numbers, a collision with a sliding image, no
// overlap ever in a dense sheared gas, the same physics as a periodic box at shear rate 0, and the linear
// velocity profile of a sheared granular gas in its steady state with the energy balance of its heating
// (the shear stress times the rate against the collisions' losses).
//
// Tolerances: the crossing is exact (every number is a binary fraction); the image collision within 1e-12
// (one square root); the profile's slope within four standard errors of its mean over independent blocks
// (derived beside the test), and the standard error itself below a tenth of the rate, so the test can tell
// a profile that is not there.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "ede/distributions.hpp"
#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

EngineOptions sheared(double rate, double until, double xi = 1) {
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.shear_rate = rate;
  o.physics.restitution = xi;
  o.stop.time = until;
  return o;
}

// Mean and standard error of the mean of values taken as `blocks` consecutive blocks.
struct MeanError {
  double mean = 0, error = 0;
};
MeanError block_mean(const std::vector<double>& v, std::size_t blocks) {
  const std::size_t per = v.size() / blocks;
  std::vector<double> means(blocks, 0);
  for (std::size_t b = 0; b < blocks; ++b) {
    for (std::size_t k = 0; k < per; ++k) means[b] += v[b * per + k];
    means[b] /= double(per);
  }
  MeanError m;
  for (double x : means) m.mean += x / double(blocks);
  double var = 0;
  for (double x : means) var += (x - m.mean) * (x - m.mean) / double(blocks - 1);
  m.error = std::sqrt(var / double(blocks));
  return m;
}

}  // namespace

TEST_CASE("shear: crossing the top and the bottom edge moves x by the offset and vx by the slide, exactly",
          "[shear]") {
  // Box 10 x 10, rate 0.3: the images slide at u = 3, offset(t) = 3 t. Disk 0 reaches the top at t = 0.5
  // (offset 1.5), disk 1 the bottom at t = 0.5.
  InitialState s = box(10, 10);
  s.add(2, 9.5, 0.5, 1, 0.1, 1, 0);
  s.add(5, 0.5, 0, -1, 0.1, 1, 0);
  auto run = run_recorded(s, sheared(0.3, 0.6));
  const auto crossings = run.recorder->of_kind(EventKind::Shear);
  REQUIRE(crossings.size() == 2);
  const auto& up = crossings[0].i == 0 ? crossings[0] : crossings[1];
  const auto& down = crossings[0].i == 0 ? crossings[1] : crossings[0];
  CHECK(up.time == 0.5);
  CHECK(up.j == kWrapTop);
  CHECK(up.vjx == 0.75);  // the new x: 2.25 - 1.5
  CHECK(up.vix == -2.5);  // 0.5 - 3
  CHECK(up.viy == 1);
  CHECK(up.vix0 == 0.5);
  CHECK(down.time == 0.5);
  CHECK(down.j == kWrapBottom);
  CHECK(down.vjx == 6.5);  // 5 + 1.5
  CHECK(down.vix == 3);
  const Particles<double>& p = run.engine->particles();
  CHECK(p.disk[0].x == 0.75);
  CHECK(p.disk[0].y == 0);
  CHECK(p.disk[0].vx == -2.5);
  CHECK(p.disk[1].x == 6.5);
  CHECK(p.disk[1].y == 10);
  CHECK(p.disk[1].vx == 3);
  CHECK(run.engine->counts().of(EventKind::Shear) == 2);
  CHECK(run.engine->counts().events() == run.engine->counts().events_but_redraws() + 2);
}

TEST_CASE("shear: the offset wraps around the box and x is brought back into it", "[shear]") {
  // Rate 1 in a 4 x 4 box (u = 4): at t = 2.75 the offset is fmod(11, 4) = 3; a disk at x = 2.5 crossing
  // the top lands at -0.5 + 4 = 3.5, one at x = 2 crossing the bottom at 5 - 4 = 1 (each clear of the
  // other's image as they cross).
  InitialState s = box(4, 4);
  s.add(2.5, 4 - 2.75 * 0.5, 0, 0.5, 0.1, 1, 0);
  s.add(2, 2.75 * 0.5, 0, -0.5, 0.1, 1, 0);
  auto run = run_recorded(s, sheared(1, 2.8));
  const auto crossings = run.recorder->of_kind(EventKind::Shear);
  REQUIRE(crossings.size() == 2);
  for (const auto& c : crossings) {
    CHECK(c.time == 2.75);
    CHECK(c.vjx == (c.i == 0 ? 3.5 : 1.0));
    CHECK(c.vix == (c.i == 0 ? -4 : 4));
  }
}

TEST_CASE("shear: a disk at rest is hit by a sliding image with the image's velocity", "[shear]") {
  // A at rest at (5, 9.9), B at rest at (2, 0.05), radii 0.1, rate 0.1 in a 10 x 10 box: B's image above
  // is at (2 + t, 10.05), moving at (1, 0). They touch when dx = -sqrt(0.04 - 0.0225), at
  // t = 3 - sqrt(0.0175). The line of centres from A to the image is n = (-a, b), a = sqrt(0.0175) / 0.2,
  // b = 0.75; the elastic rule for equal masses gives A the image's velocity (1, 0) along it:
  // v_A' = -a n = (a^2, -a b), and the image the rest, (1 - a^2, a b): B's own velocity is that less the
  // image's slide, (-a^2, a b).
  InitialState s = box(10, 10);
  s.add(5, 9.9, 0, 0, 0.1, 1, 0);
  s.add(2, 0.05, 0, 0, 0.1, 1, 0);
  auto run = run_recorded(s, sheared(0.1, 3));
  const auto pairs = run.pairs();
  REQUIRE(pairs.size() == 1);
  const double d = std::sqrt(0.0175), nx = d / 0.2, ny = 0.15 / 0.2;
  const auto& e = pairs[0];
  CHECK(std::abs(e.time - (3 - d)) < 1e-12);
  CHECK(std::abs(e.vix - nx * nx) < 1e-12);
  CHECK(std::abs(e.viy - (-nx * ny)) < 1e-12);
  CHECK(std::abs(e.vjx - (-nx * nx)) < 1e-12);
  CHECK(std::abs(e.vjy - nx * ny) < 1e-12);
  CHECK_FALSE(e.v2_velocities_exact);  // the format's rule knows no sliding image: not vouched for
}

TEST_CASE("shear: no two disks ever overlap in a dense sheared gas, and nothing is predicted in the past",
          "[shear]") {
  // 900 disks at packing 0.45, sheared fast (u = 0.5 * 30 = 15 against thermal speeds ~1), so that the
  // images slide across many cells between a boundary disk's events: every pair the slid rows bring
  // within reach must be found (a missed one overlaps at once). Again with the thermostat redrawing about
  // the flow, far more often than the rows are realigned (every 0.03): a realignment must not be passed
  // over by a redraw (taken later, it would set the clock back).
  const double l = 30, r = std::sqrt(0.45 * l * l / (900 * M_PI));
  const InitialState s = lattice_gas(30, r, l, 5);
  for (const bool heated : {false, true}) {
    EngineOptions o = sheared(0.5, 1e9, 0.95);
    if (heated) o.physics.thermostat = ThermostatSpec{1.0, 2.0, {}};
    auto e = engine(s, o);
    std::uint64_t shears = 0;
    for (int step = 1; step <= 40; ++step) {
      e->run_until(0.25 * step, std::uint64_t(-1));
      INFO("thermostat " << heated << ", t = " << e->time());
      REQUIRE(e->check_invariants(1e-9).empty());
      CHECK(e->largest_overlap() < 1e-9);
      shears = e->counts().of(EventKind::Shear);
    }
    CHECK(shears > 100);  // the edges were crossed often
    CHECK(e->counts().of(EventKind::Pair) > 10000);
    if (heated) CHECK(e->counts().of(EventKind::Thermostat) > 10000);
  }
}

TEST_CASE("shear: at shear rate 0 a Lees-Edwards box is a periodic box", "[shear]") {
  // The same gas for about two collisions per disk: the same pair collisions, every periodic wrap through
  // the top or bottom a shear event instead, and the same state to round-off (the sheared engine predicts
  // the boundary rows' disks afresh at other times, so the roundings differ; chaos has not amplified them
  // past 1e-9 yet).
  const InitialState s = lattice_gas(12, 0.3, 12, 7);
  EngineOptions periodic = sheared(0, 2);
  periodic.shear_rate.reset();
  auto a = run_recorded(s, periodic);
  auto b = run_recorded(s, sheared(0, 2));
  CHECK(b.engine->effects().rfind("lees-edwards", 0) == 0);
  CHECK(a.engine->counts().of(EventKind::Pair) == b.engine->counts().of(EventKind::Pair));
  CHECK(a.engine->counts().of(EventKind::Wrap) ==
        b.engine->counts().of(EventKind::Wrap) + b.engine->counts().of(EventKind::Shear));
  CHECK(b.engine->counts().of(EventKind::Shear) > 10);
  const Particles<double>& pa = a.engine->particles();
  const Particles<double>& pb = b.engine->particles();
  for (std::size_t i = 0; i < s.size(); ++i) {
    CHECK(std::abs(pa.x_at(i, 2.0) - pb.x_at(i, 2.0)) < 1e-9);
    CHECK(std::abs(pa.y_at(i, 2.0) - pb.y_at(i, 2.0)) < 1e-9);
    CHECK(std::abs(pa.disk[i].vx - pb.disk[i].vx) < 1e-9);
  }
}

TEST_CASE("shear: a sheared granular gas settles into the linear velocity profile of the shear rate",
          "[shear][slow]") {
  // 576 disks at packing 0.1 with xi = 0.9, sheared at rate 0.05 in a 60 x 60 box (u = 3): viscous heating
  // balances the collisions' losses at a granular temperature of order (rate * mean free path)^2 / (1 -
  // xi^2) (docs/physics.md). After 400 time units (tens of cooling times) the mean x-velocity in 12
  // horizontal slabs, sampled every 2 time units for 1600 more, is fitted by a line: its slope is the
  // shear rate. Each sample's slope is noisy (a few hundred disks), successive ones correlated: their
  // mean over 16 blocks of 50 samples, with the standard error of the block means, is within 4 of it of
  // 0.05, and that error below 0.005 (a profile half as steep would be 5 errors off).
  const double l = 60, rate = 0.05, r = std::sqrt(0.1 * l * l / (576 * M_PI));
  const InitialState s = lattice_gas(24, r, l, 13);
  EngineOptions o = sheared(rate, 2000, 0.9);
  o.sample_interval = 2;
  auto e = engine(s, o);
  Recorder<double> rec;
  rec.keep_states = true;
  e->add_sink(&rec);
  e->run();
  std::vector<double> slopes;
  const int slabs = 12;
  for (std::size_t k = 0; k < rec.sample_times.size(); ++k) {
    if (rec.sample_times[k] <= 400) continue;
    std::vector<double> sum(slabs, 0), count(slabs, 0);
    for (const Disk<double>& d : rec.sample_states[k]) {
      const int b = std::min(slabs - 1, std::max(0, int(d.y / (l / slabs))));
      sum[std::size_t(b)] += d.vx, count[std::size_t(b)] += 1;
    }
    double sy = 0, sv = 0, syy = 0, syv = 0, n = 0;
    for (int b = 0; b < slabs; ++b) {
      if (count[std::size_t(b)] == 0) continue;
      const double y = (b + 0.5) * l / slabs, v = sum[std::size_t(b)] / count[std::size_t(b)];
      sy += y, sv += v, syy += y * y, syv += y * v, n += 1;
    }
    slopes.push_back((n * syv - sy * sv) / (n * syy - sy * sy));
  }
  REQUIRE(slopes.size() == 800);
  const MeanError m = block_mean(slopes, 16);
  INFO("slope " << m.mean << " +- " << m.error);
  CHECK(std::abs(m.mean - rate) < 4 * m.error);
  CHECK(m.error < 0.1 * rate);

  // The energy balance of the same steady state, in 16 blocks of 100 time units: the shear's work
  // -P_xy rate A against the collisions' losses D (docs/physics.md). P_xy A is the kinetic part
  // sum m (v_x - rate y)(v_y - V_y) (peculiar velocities; V_y the mean, which the profile's offset then
  // drops out of), averaged over the block's samples, plus the collisional part, the y-distance from i to
  // j's image times j's x-impulse, summed over the block's pairs per unit time. A pair's loss is the drop
  // of its kinetic energy with j's velocity taken as its image's (+-u across the sliding edge). The two
  // differ in a block by the change of the peculiar kinetic energy over it (a few percent of the losses):
  // their difference's mean over the blocks is within 4 standard errors of 0, and that error below 3 % of
  // the losses (a stress off by a tenth would show).
  const double u = rate * l, area = l * l, block = 100;
  std::vector<double> heating(16, 0), losses(16, 0), kinetic_samples(16, 0);
  for (std::size_t k = 0; k < rec.sample_times.size(); ++k) {
    if (rec.sample_times[k] <= 400) continue;
    const std::size_t b = std::min<std::size_t>(15, std::size_t((rec.sample_times[k] - 400) / block));
    double vy_mean = 0;
    for (const Disk<double>& d : rec.sample_states[k]) vy_mean += d.vy / double(s.size());
    double pxy = 0;
    for (const Disk<double>& d : rec.sample_states[k]) pxy += (d.vx - rate * d.y) * (d.vy - vy_mean);  // m = 1
    heating[b] += -pxy * rate;  // averaged below
    kinetic_samples[b] += 1;
  }
  for (std::size_t b = 0; b < 16; ++b) heating[b] /= kinetic_samples[b];
  for (const auto& e : rec.events) {
    if (e.kind != EventKind::Pair || e.time <= 400) continue;
    const std::size_t b = std::min<std::size_t>(15, std::size_t((e.time - 400) / block));
    const double yi = e.before_i.y + e.before_i.vy * (e.time - e.before_i.t);
    const double yj = e.before_j.y + e.before_j.vy * (e.time - e.before_j.t);
    double dy = yj - yi, slide = 0;
    if (dy > l / 2) dy -= l, slide = -u;
    if (dy < -l / 2) dy += l, slide = u;
    const auto energy = [](double vx, double vy) { return 0.5 * (vx * vx + vy * vy); };
    const double before = energy(e.vix0, e.viy0) + energy(e.vjx0 + slide, e.vjy0);
    const double after = energy(e.vix, e.viy) + energy(e.vjx + slide, e.vjy);
    losses[b] += (before - after) / block;
    heating[b] += -(dy * (e.vjx - e.vjx0)) * rate / block;
  }
  std::vector<double> difference(16);
  double mean_loss = 0;
  for (std::size_t b = 0; b < 16; ++b) difference[b] = heating[b] - losses[b], mean_loss += losses[b] / 16;
  const MeanError balance = block_mean(difference, 16);
  INFO("losses " << mean_loss << " per unit time, heating - losses " << balance.mean << " +- " << balance.error);
  CHECK(mean_loss > 0);
  CHECK(std::abs(balance.mean) < 4 * balance.error);
  CHECK(balance.error < 0.03 * mean_loss);
}

TEST_CASE("shear: the thermostat draws about the flow at the disk's height, not about rest", "[shear][thermostat]") {
  // 100 disks in a 20 x 20 box sheared at rate 0.2: the flow spans -2 .. 2 across the box, twice the
  // thermal speed at kT = 1. Each redraw's velocity less the flow rate (y - 10) at its disk's height must
  // follow Maxwell-Boltzmann at kT = 1 (KS p > 0.001; the same test on the velocities themselves, which
  // carry the flow's spread too, gives p < 1e-4), and the x-components less the flow average to 0 (within
  // 5 standard errors: about 10 000 draws of unit variance).
  const double l = 20, rate = 0.2, kT = 1;
  const InitialState s = lattice_gas(10, 0.2, l, 5);
  EngineOptions o = sheared(rate, 100);
  o.physics.thermostat = ThermostatSpec{kT, 1.0, {}};
  o.seed = 17;
  auto run = run_recorded(s, o);
  const auto redraws = run.recorder->of_kind(EventKind::Thermostat);
  REQUIRE(redraws.size() > 9000);
  std::vector<double> relative, lab;
  double sum_x = 0;
  for (const auto& e : redraws) {
    const double y = e.before_i.y + e.before_i.vy * (e.time - e.before_i.t);
    const double cx = e.vix - rate * (y - l / 2);
    relative.push_back(mb_speed_cdf(std::hypot(cx, e.viy), 1, kT));
    lab.push_back(mb_speed_cdf(std::hypot(e.vix, e.viy), 1, kT));
    sum_x += cx;
  }
  const auto uniform = [](double x) { return x; };
  CHECK(ks_test(relative, uniform).p_value > 1e-3);
  CHECK(ks_test(lab, uniform).p_value < 1e-4);
  CHECK(std::abs(sum_x / double(redraws.size())) < 5 / std::sqrt(double(redraws.size())));
}
