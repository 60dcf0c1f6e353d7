// The reports of ede/analysis.hpp on logs written in-process through the public API: species by name,
// the distribution against Maxwell-Boltzmann (exactly what the pure functions give on the same snapshots,
// and statistically Maxwellian after relaxation), species tables, the energy curve with its grids and
// Haff's law, and the collision series. Exact expectations where the result is a composition of exact
// steps; stated tolerances where it is physics.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "ede/analysis.hpp"
#include "public_log_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

// 400 disks at phi ~ 0.05, walls, relaxed for 20 collisions per disk.
const Log& relaxed_gas() {
  static const Log log = public_log(gas_toml(400, 0.006, "collisions_per_particle = 20"), "reports-gas.ede");
  return log;
}

const Log& mixture() {
  static const Log log = public_log(mixture_toml("collisions_per_particle = 10"), "reports-mixture.ede");
  return log;
}

const Log& cooling_gas() {  // xi = 0.9, dilute: Haff's homogeneous cooling
  static const Log log = public_log(gas_toml(1000, 0.004, "collisions_per_particle = 30", "[physics]\nrestitution = 0.9"),
                                    "reports-cooling.ede");
  return log;
}

double end_of(const Log& log) {
  auto o = log_overview(log);
  REQUIRE(o);
  return o.value().end_time;
}

std::vector<GasSnapshot> snapshots(const Log& log, const std::vector<double>& times) {
  std::vector<GasSnapshot> out;
  REQUIRE(for_each_snapshot(log, times, [&](const GasSnapshot& s) { out.push_back(s); }));
  return out;
}

}  // namespace

TEST_CASE("species_index: by name, '' for all, an unknown name lists the species", "[analysis][reports]") {
  const LogInfo& info = mixture().info();
  CHECK(species_index(info, "").value() == kAllSpecies);
  CHECK(species_index(info, "light").value() == 0);
  CHECK(species_index(info, "heavy").value() == 1);
  auto bad = species_index(info, "medium");
  REQUIRE_FALSE(bad);
  CHECK(bad.error().message == "the log has no species 'medium'; its species are: light, heavy");
}

TEST_CASE("measure_distribution is the pure functions on the log's snapshots, exactly", "[analysis][reports]") {
  const Log& log = relaxed_gas();
  const double end = end_of(log);
  const std::vector<double> times = {end / 2, end};
  auto r = measure_distribution(log, {times, kAllSpecies, Quantity::Speed, 25, 100});
  REQUIRE(r);
  const std::vector<GasSnapshot> s = snapshots(log, {0.0, end / 2, end});
  std::vector<double> values, energies;
  for (std::size_t k = 1; k < 3; ++k) {
    const std::vector<double> v = speeds(s[k]), e = kinetic_energies(s[k]);
    values.insert(values.end(), v.begin(), v.end());
    energies.insert(energies.end(), e.begin(), e.end());
  }
  long double sum = 0;
  for (const double e : energies) sum += e;
  CHECK(r.value().disks == 400);
  CHECK(r.value().samples == 800);
  CHECK(r.value().kT == double(sum / energies.size()));
  CHECK(r.value().ks.statistic == ks_test_mb_energies(energies, r.value().kT).statistic);
  CHECK(r.value().initial_kT == 0.5);  // every disk at speed 1, m = 1
  CHECK(r.value().law.masses.size() == 1);
  const std::vector<double>& edges = r.value().histogram.edges;
  REQUIRE(edges.size() == 26);
  CHECK(edges.front() == 0);
  CHECK(edges.back() == *std::max_element(values.begin(), values.end()));  // relaxed speeds exceed 1
  CHECK(r.value().histogram.count == make_histogram(values, edges).count);
  CHECK(r.value().initial.samples() == 400);
  CHECK(r.value().density == densities(r.value().histogram));
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    CHECK(r.value().law_density[k] == r.value().law.bin_density(Quantity::Speed, edges[k], edges[k + 1]));
  REQUIRE(r.value().curve_x.size() == 101);
  CHECK(r.value().curve_x.front() == 0);
  CHECK(r.value().curve_x.back() == edges.back());
  CHECK(r.value().curve_density[50] == r.value().law.density(Quantity::Speed, r.value().curve_x[50]));
}

TEST_CASE("measure_distribution: relaxed speeds are Maxwellian, the initial single speed is not", "[analysis][reports]") {
  auto r = measure_distribution(relaxed_gas(), {{end_of(relaxed_gas())}, kAllSpecies, Quantity::Energy, 20, 400});
  REQUIRE(r);
  CHECK(r.value().kT == Approx(0.5).epsilon(1e-12));  // elastic: the energy is conserved
  CHECK(r.value().ks.p_value > 1e-3);                  // a false alarm 1 time in 1000
  CHECK(r.value().initial_ks.p_value < 1e-10);         // 400 equal energies against an exponential
  double integral = 0;
  for (std::size_t k = 0; k < r.value().density.size(); ++k)
    integral += r.value().density[k] * (r.value().histogram.edges[k + 1] - r.value().histogram.edges[k]);
  CHECK(integral == Approx(1).epsilon(1e-12));
}

TEST_CASE("measure_distribution: one species, and clear errors", "[analysis][reports]") {
  auto heavy = measure_distribution(mixture(), {{end_of(mixture())}, 1, Quantity::Speed, 10, 400});
  REQUIRE(heavy);
  CHECK(heavy.value().disks == 100);
  REQUIRE(heavy.value().law.masses.size() == 1);
  CHECK(heavy.value().law.masses[0].mass == 4);
  CHECK(heavy.value().initial_kT == 2);  // m = 4 at speed 1
  CHECK_FALSE(measure_distribution(mixture(), {{0.1}, kAllSpecies, Quantity::Speed, 0, 400}));
  CHECK_FALSE(measure_distribution(mixture(), {{1e9}, kAllSpecies, Quantity::Speed, 10, 400}));
  const Log rest = public_log("[box]\nsize = [1.0, 1.0]\n[[species]]\nname = \"grain\"\ncount = 20\nradius = 0.01\n"
                              "[stop]\ntime = 1.0\n",
                              "reports-rest.ede");
  auto none = measure_distribution(rest, {{0.0}, kAllSpecies, Quantity::Speed, 10, 400});
  REQUIRE_FALSE(none);
  CHECK(none.error().message.find("at rest (kT = 0)") != std::string::npos);
}

TEST_CASE("species_tables: species_stats of each snapshot, or one species' row", "[analysis][reports]") {
  const Log& log = mixture();
  const std::vector<double> times = {0.0, end_of(log)};
  auto all = species_tables(log, times);
  REQUIRE(all);
  REQUIRE(all.value().size() == 2);
  const std::vector<GasSnapshot> s = snapshots(log, times);
  for (std::size_t k = 0; k < 2; ++k) {
    const std::vector<SpeciesStats> expected = species_stats(s[k]);
    const std::vector<SpeciesStats>& rows = all.value()[k].rows;
    CHECK(all.value()[k].time == times[k]);
    REQUIRE(rows.size() == 3);
    for (std::size_t r = 0; r < 3; ++r) {
      CHECK(rows[r].name == expected[r].name);
      CHECK(rows[r].mean_kinetic_energy == expected[r].mean_kinetic_energy);
      CHECK(rows[r].mean_speed_error == expected[r].mean_speed_error);
    }
  }
  auto heavy = species_tables(log, times, 1);
  REQUIRE(heavy);
  REQUIRE(heavy.value()[1].rows.size() == 1);
  CHECK(heavy.value()[1].rows[0].name == "heavy");
  CHECK(heavy.value()[1].rows[0].kT == all.value()[1].rows[1].kT);
}

TEST_CASE("time_grid_to: the grid and its end, never twice", "[analysis][reports]") {
  CHECK(time_grid_to(0, 1, 0.25) == std::vector<double>{0, 0.25, 0.5, 0.75, 1});
  CHECK(time_grid_to(0, 1, 0.4) == std::vector<double>{0, 0.4, 0.8, 1});
  CHECK(time_grid_to(0.5, 0.5, 0.1) == std::vector<double>{0.5});
  CHECK(time_grid_to(0, 1, 1e-9, 1000).empty());
}

TEST_CASE("energy_curve: the default grid, E(0), conservation when elastic", "[analysis][reports]") {
  const Log& log = relaxed_gas();
  auto c = energy_curve(log);
  REQUIRE(c);
  auto o = log_overview(log);
  REQUIRE(o);
  CHECK(c.value().default_spacing);
  CHECK(c.value().spacing == o.value().mean_free_time() / 20);
  CHECK(c.value().series.time == time_grid_to(0, o.value().end_time, c.value().spacing, 5'000'000));
  CHECK(c.value().restitution == 1);
  CHECK(c.value().initial_energy == c.value().series.kinetic_energy.front());
  CHECK(std::isnan(c.value().haff_tau));
  CHECK(std::isnan(c.value().haff_ratio(0)));
  CHECK(c.value().max_drift() < 1e-13);
  CHECK(c.value().ratio(c.value().series.time.size() - 1) == Approx(1).epsilon(1e-13));
}

TEST_CASE("energy_curve: points, a range, and errors", "[analysis][reports]") {
  const Log& log = cooling_gas();
  const double end = end_of(log);
  EnergyCurveRequest points;
  points.points = 5;
  auto p = energy_curve(log, points);
  REQUIRE(p);
  CHECK(p.value().series.time == std::vector<double>{0, end * 0.25, end * 0.5, end * 0.75, end});
  CHECK(p.value().spacing == 0);

  EnergyCurveRequest whole, part;
  whole.every = part.every = end / 8;
  part.from = end / 2;
  auto w = energy_curve(log, whole), q = energy_curve(log, part);
  REQUIRE(w);
  REQUIRE(q);
  CHECK(q.value().series.time.front() == end / 2);
  CHECK(q.value().series.time.back() == end);
  CHECK(q.value().initial_energy == w.value().initial_energy);  // E(0) at t = 0, not at the range's start
  CHECK(q.value().series.kinetic_energy.front() == w.value().series.kinetic_energy[4]);
  CHECK(q.value().ratio(0) == w.value().ratio(4));

  EnergyCurveRequest bad;
  bad.every = 0;
  CHECK_FALSE(energy_curve(log, bad));
  bad.every = end / 1e6;
  bad.max_points = 1000;
  auto many = energy_curve(log, bad);
  REQUIRE_FALSE(many);
  CHECK(many.error().message.find("more than 1000 points") != std::string::npos);
  EnergyCurveRequest late;
  late.to = 2 * end;
  CHECK_FALSE(energy_curve(log, late));
}

TEST_CASE("energy_curve: Haff's tau from the first grid time past 2 collisions per disk, and the law", "[analysis][reports]") {
  auto c = energy_curve(cooling_gas());
  REQUIRE(c);
  const EnergyCurve& e = c.value();
  CHECK(e.restitution == 0.9);
  REQUIRE(std::isfinite(e.haff_tau));
  std::size_t k = 1;
  while (e.series.collisions_per_particle(k) < 2) ++k;
  const double a = 1 - 0.9 * 0.9, c1 = e.series.collisions_per_particle(k), t1 = e.series.time[k];
  CHECK(e.haff_calibration == c1);
  CHECK(e.haff_tau == 4 / (a * (4 * std::expm1(a * c1 / 4) / (a * t1))));
  // Physics: a dilute gas cools as (1 + t/tau)^-2 (within 10% here, after 30 collisions per disk, where
  // clustering has barely begun and the finite sample's noise is a few percent).
  const std::size_t last = e.series.time.size() - 1;
  CHECK(e.ratio(last) < 0.2);
  CHECK(e.ratio(last) == Approx(e.haff_ratio(last)).epsilon(0.1));
}

TEST_CASE("collision_series: the log's counts, rates per interval, speed classes per time", "[analysis][reports]") {
  const Log& log = relaxed_gas();
  const double end = end_of(log);
  const std::vector<double> times = {0, end / 4, end / 4, end / 2, end};
  auto c = collision_series(log, times);
  REQUIRE(c);
  auto s = log_series(log, times);
  REQUIRE(s);
  CHECK(c.value().series.pair_collisions == s.value().pair_collisions);
  CHECK(c.value().series.wall_collisions == s.value().wall_collisions);
  const auto counts = log.count_events();
  REQUIRE(counts);
  CHECK(c.value().series.pair_collisions.back() == counts.value().of(EventKind::Pair));
  CHECK(std::isnan(c.value().rate[0]));
  CHECK(std::isnan(c.value().rate[2]));  // an empty interval
  const LogSeries& l = c.value().series;
  const double r = (l.collisions_per_particle(3) - l.collisions_per_particle(2)) / (end / 2 - end / 4);
  CHECK(c.value().rate[3] == r);
  CHECK(c.value().mean_free_time[3] == 1 / r);
  const std::vector<GasSnapshot> snaps = snapshots(log, times);
  CHECK(c.value().reference_speed == mean_speed(snaps[0]));
  CHECK(c.value().reference_speed == Approx(1).epsilon(1e-15));
  for (std::size_t k = 0; k < times.size(); ++k) {
    const SpeedClasses expected = speed_classes(snaps[k], c.value().reference_speed);
    CHECK(c.value().classes[k].slow == expected.slow);
    CHECK(c.value().classes[k].fast == expected.fast);
  }
  CHECK(c.value().classes[0].medium == 400);  // all at the reference speed
}

TEST_CASE("collision_series: no collisions give a rate of 0 and an infinite mean free time", "[analysis][reports]") {
  const Log log = public_log("[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n[[species]]\nname = \"gas\"\n"
                             "radius = 0.01\n[species.placement]\nkind = \"explicit\"\npositions = [[0.2, 0.3], "
                             "[0.2, 0.7]]\n[species.velocity]\nkind = \"list\"\nvalues = [[1.0, 0.0], [1.0, 0.0]]\n"
                             "[stop]\ntime = 2.0\n",
                             "reports-free.ede");
  auto c = collision_series(log, {0, 1, 2});
  REQUIRE(c);
  CHECK(c.value().rate[1] == 0);
  CHECK(std::isinf(c.value().mean_free_time[2]));
}
