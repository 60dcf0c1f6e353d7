// Gas observables on hand-made snapshots: per-species counts, masses, means and temperature by hand,
// pooling equal to concatenation, and the GasLab speed classes with their boundaries.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "ede/analysis.hpp"

using namespace ede;

namespace {

// Two species: "light" (m = 1) with speeds 3-4-5 and 0; "heavy" (m = 4) with speed 1 and 2.
GasSnapshot two_species() {
  GasSnapshot s;
  s.species_names = {"light", "heavy"};
  const auto add = [&](double vx, double vy, double m, std::int32_t sp) {
    s.vx.push_back(vx), s.vy.push_back(vy), s.mass.push_back(m), s.species.push_back(sp);
  };
  add(3, 4, 1, 0);
  add(0, 0, 1, 0);
  add(0, -1, 4, 1);
  add(2, 0, 4, 1);
  return s;
}

}  // namespace

TEST_CASE("speeds, energies and masses of a selection", "[analysis]") {
  const GasSnapshot s = two_species();
  CHECK(speeds(s) == std::vector<double>{5, 0, 1, 2});
  CHECK(speeds(s, 1) == std::vector<double>{1, 2});
  CHECK(kinetic_energies(s) == std::vector<double>{12.5, 0, 2, 8});
  CHECK(masses(s, 0) == std::vector<double>{1, 1});
}

TEST_CASE("per-species statistics: N, masses, mean speed, mean kinetic energy, kT", "[analysis]") {
  const std::vector<SpeciesStats> st = species_stats(two_species());
  REQUIRE(st.size() == 3);
  CHECK(st[0].name == "light");
  CHECK(st[0].n == 2);
  CHECK(st[0].mean_speed == 2.5);
  CHECK(st[0].mean_kinetic_energy == 6.25);
  CHECK(st[0].kT == 6.25);  // 2D equipartition: kT = <m v^2 / 2>
  CHECK(st[1].mass_min == 4);
  CHECK(st[1].mean_speed == 1.5);
  CHECK(st[1].mean_kinetic_energy == 5);
  CHECK(st[2].name == "all");
  CHECK(st[2].n == 4);
  CHECK(st[2].mass_min == 1);
  CHECK(st[2].mass_max == 4);
  CHECK(st[2].mean_kinetic_energy == 22.5 / 4);
  // Standard error of the mean speed of light: sample sd of {5, 0} is 5 / sqrt(2), over sqrt(2).
  CHECK(st[0].mean_speed_error == Approx(2.5));
  CHECK(temperature(two_species(), 1) == 5);
  CHECK(mean_speed(two_species()) == 2);
}

TEST_CASE("pooled averages equal those of the concatenated snapshots", "[analysis]") {
  GasSnapshot a = two_species(), b = two_species();
  for (double& v : b.vx) v *= 2;
  GasSnapshot both = a;
  for (std::size_t i = 0; i < b.size(); ++i) {
    both.vx.push_back(b.vx[i]), both.vy.push_back(b.vy[i]);
    both.mass.push_back(b.mass[i]), both.species.push_back(b.species[i]);
  }
  GasAverages pooled;
  pooled.add(a);
  pooled.add(b);
  const std::vector<SpeciesStats> p = pooled.stats(), c = species_stats(both);
  for (std::size_t k = 0; k < p.size(); ++k) {
    CHECK(p[k].n == c[k].n);
    CHECK(p[k].mean_speed == Approx(c[k].mean_speed).epsilon(1e-15));
    CHECK(p[k].mean_kinetic_energy == Approx(c[k].mean_kinetic_energy).epsilon(1e-15));
    CHECK(p[k].mean_kinetic_energy_error == Approx(c[k].mean_kinetic_energy_error).epsilon(1e-12));
  }
}

TEST_CASE("speed classes: slow below 0.5 v_ref, fast above 1.5 v_ref, boundaries medium, sum 100%", "[analysis]") {
  GasSnapshot s;
  s.species_names = {"gas"};
  for (const double v : {0.0, 0.49, 0.5, 1.0, 1.5, 1.51, 3.0}) {
    s.vx.push_back(v), s.vy.push_back(0), s.mass.push_back(1), s.species.push_back(0);
  }
  const SpeedClasses c = speed_classes(s, 1.0);
  CHECK(c.slow == 2);
  CHECK(c.medium == 3);
  CHECK(c.fast == 2);
  CHECK(c.slow_percent + c.medium_percent + c.fast_percent == Approx(100).epsilon(1e-14));
  CHECK(c.fast_percent == Approx(200.0 / 7));
}
