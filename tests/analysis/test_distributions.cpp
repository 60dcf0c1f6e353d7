// Histograms, the 2D Maxwell-Boltzmann law and the KS test on synthetic samples: exact counts and
// statistics where they can be computed by hand, integrals to 1, reference values of the Kolmogorov
// distribution (scipy.special.kolmogorov), and samples drawn from MB with ede::Rng (fixed seeds: every
// number here is deterministic).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "ede/analysis.hpp"
#include "core/rng.hpp"

using namespace ede;

namespace {

// Simpson's rule on [a, b] with n (even) intervals.
template <class F>
double integrate(F f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int k = 1; k < n; ++k) sum += f(a + k * h) * (k % 2 ? 4 : 2);
  return sum * h / 3;
}

// n kinetic energies of disks drawn from 2D MB at kT: each velocity component ~ N(0, kT/m) (Marsaglia's
// polar method); masses alternate through `masses`.
std::vector<double> mb_energies(std::uint64_t seed, std::size_t n, double kT, const std::vector<double>& masses) {
  Rng rng(seed);
  std::vector<double> e;
  for (std::size_t i = 0; i < n; ++i) {
    const double m = masses[i % masses.size()];
    double z0, z1;
    rng.normal_pair(z0, z1);
    const double s = std::sqrt(kT / m);
    const double vx = s * z0, vy = s * z1;
    e.push_back(0.5 * m * (vx * vx + vy * vy));
  }
  return e;
}

}  // namespace

TEST_CASE("histogram counts samples in half-open bins, the last one closed", "[analysis]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> samples = {0, 0.25, 0.5, 1, 1.5, 1.99, 2, 2.5, -1, 3, nan};
  const Histogram h = make_histogram(samples, uniform_edges(0, 2, 4));
  REQUIRE(h.edges == std::vector<double>{0, 0.5, 1, 1.5, 2});
  CHECK(h.count == std::vector<std::uint64_t>{2, 1, 1, 3});
  CHECK(h.outside == 4);  // 2.5, -1, 3, NaN
  CHECK(h.samples() == samples.size());
  const std::vector<double> d = densities(h);
  CHECK(d[0] == 2.0 / (11 * 0.5));
  CHECK(d[3] == 3.0 / (11 * 0.5));
}

TEST_CASE("histogram with uneven edges, and densities that integrate to 1 when nothing is outside", "[analysis]") {
  const Histogram h = make_histogram({0.1, 0.2, 0.3, 2.5, 9.9, 10}, {0, 1, 3, 10});
  CHECK(h.count == std::vector<std::uint64_t>{3, 1, 2});
  CHECK(h.outside == 0);
  const std::vector<double> d = densities(h);
  double integral = 0;
  for (std::size_t k = 0; k < d.size(); ++k) integral += d[k] * (h.edges[k + 1] - h.edges[k]);
  CHECK(integral == Approx(1).epsilon(1e-15));
  CHECK(densities(make_histogram({}, {0, 1})) == std::vector<double>{0});
}

TEST_CASE("Maxwell-Boltzmann speed and energy densities integrate to 1 and match their CDFs", "[analysis]") {
  for (const auto& mass_and_kT : {std::pair{1.0, 0.5}, {4.0, 2.0}, {1e-3, 7.0}}) {
    const double m = mass_and_kT.first, kT = mass_and_kT.second;  // plain locals: lambdas capture them (Clang 14)
    const double vmax = 12 * std::sqrt(kT / m);  // the tail beyond is below e^-72
    CHECK(integrate([&](double v) { return mb_speed_density(v, m, kT); }, 0, vmax) == Approx(1).epsilon(1e-10));
    CHECK(integrate([&](double v) { return mb_speed_density(v, m, kT); }, 0, vmax / 7) ==
          Approx(mb_speed_cdf(vmax / 7, m, kT)).epsilon(1e-10));
    CHECK(integrate([&](double e) { return mb_energy_density(e, kT); }, 0, 60 * kT) == Approx(1).epsilon(1e-10));
    // The mean energy is kT whatever the mass (2D equipartition).
    CHECK(integrate([&](double v) { return 0.5 * m * v * v * mb_speed_density(v, m, kT); }, 0, vmax) ==
          Approx(kT).epsilon(1e-10));
  }
  CHECK(mb_speed_density(-1, 1, 1) == 0);
  CHECK(mb_energy_cdf(-1, 1) == 0);
}

TEST_CASE("a mixture's MB law weights each mass by its share, bin densities integrate to 1", "[analysis]") {
  const MaxwellBoltzmann mb = maxwell_boltzmann_for({1, 4, 1, 1}, 0.8);
  REQUIRE(mb.masses.size() == 2);
  CHECK(mb.masses[0].mass == 1);
  CHECK(mb.masses[0].fraction == 0.75);
  CHECK(mb.density(Quantity::Speed, 0.7) ==
        Approx(0.75 * mb_speed_density(0.7, 1, 0.8) + 0.25 * mb_speed_density(0.7, 4, 0.8)));
  CHECK(integrate([&](double v) { return mb.density(Quantity::Speed, v); }, 0, 15) == Approx(1).epsilon(1e-10));
  for (const Quantity q : {Quantity::Speed, Quantity::Energy}) {
    const std::vector<double> edges = uniform_edges(0, 40, 57);
    double sum = 0;
    for (std::size_t k = 0; k + 1 < edges.size(); ++k) sum += mb.bin_density(q, edges[k], edges[k + 1]) * (edges[k + 1] - edges[k]);
    CHECK(sum == Approx(1).epsilon(1e-12));
  }
}

TEST_CASE("KS statistic is exact on small samples, ties included", "[analysis]") {
  const auto uniform = [](double x) { return std::clamp(x, 0.0, 1.0); };
  // Sorted 0.1, 0.4, 0.7: D+ = max(1/3 - 0.1, 2/3 - 0.4, 1 - 0.7) = 0.3, D- = max(0.1, 0.4 - 1/3, 0.7 - 2/3).
  CHECK(ks_statistic({0.7, 0.1, 0.4}, uniform) == Approx(0.3).margin(1e-15));
  // Ties: {0.5, 0.5}: the empirical CDF jumps from 0 to 1 at 0.5, so D = 0.5.
  CHECK(ks_statistic({0.5, 0.5}, uniform) == Approx(0.5).margin(1e-15));
  // One point at 0.9: D = max(1 - 0.9, 0.9 - 0) = 0.9.
  CHECK(ks_statistic({0.9}, uniform) == Approx(0.9).margin(1e-15));
  const KsResult r = ks_test({0.2, 0.6}, uniform);
  CHECK(r.n == 2);
  CHECK(r.statistic == Approx(0.4).margin(1e-15));  // max(0.5 - 0.2, 1 - 0.6, 0.2, 0.6 - 0.5)
  CHECK(r.p_value == Approx(kolmogorov_q((std::sqrt(2.0) + 0.12 + 0.11 / std::sqrt(2.0)) * 0.4)));
  CHECK(ks_p_value(0.3, 0) == 1);
}

TEST_CASE("Kolmogorov distribution matches reference values on both series", "[analysis]") {
  // scipy.special.kolmogorov(x)
  CHECK(kolmogorov_q(0.2) == Approx(0.999999999999495).epsilon(1e-12));
  CHECK(kolmogorov_q(0.5) == Approx(0.9639452436648751).epsilon(1e-12));
  CHECK(kolmogorov_q(1.0) == Approx(0.26999967167735456).epsilon(1e-12));
  CHECK(kolmogorov_q(1.36) == Approx(0.049485876755377876).epsilon(1e-12));
  CHECK(kolmogorov_q(2.0) == Approx(0.0006709252557796953).epsilon(1e-12));
  CHECK(kolmogorov_q(0) == 1);
  // Continuous where the two series meet.
  CHECK(kolmogorov_q(1.18 - 1e-12) == Approx(kolmogorov_q(1.18)).epsilon(1e-10));
}

TEST_CASE("KS accepts samples drawn from MB and rejects one speed", "[analysis]") {
  // A correct sample gives p uniform on [0, 1]: p > 0.01 fails for 1% of seeds; the seed is fixed, so
  // this is deterministic, and the threshold only guards against a wrong law or a wrong statistic.
  const std::vector<double> e = mb_energies(2024, 4000, 0.8, {1, 4});  // masses m0 and 4 m0: energies still exp
  CHECK(ks_test_mb_energies(e, 0.8).p_value > 0.01);
  double mean = 0;
  for (const double x : e) mean += x / double(e.size());
  CHECK(ks_test_mb_energies(e, mean).p_value > 0.01);  // kT measured from the sample, as the tool does
  // A clearly wrong distribution: every disk at one speed (energy 0.5 with m = 1), against MB at kT 0.5.
  const KsResult one_speed = ks_test_mb_energies(std::vector<double>(2000, 0.5), 0.5);
  CHECK(one_speed.statistic == Approx(1 - std::exp(-1.0)).epsilon(1e-14));
  CHECK(one_speed.p_value < 1e-100);
}

TEST_CASE("KS p-values of MB samples are calibrated: about 5% fall below 0.05", "[analysis]") {
  int below = 0;
  const int trials = 400;
  for (int k = 0; k < trials; ++k)
    below += ks_test_mb_energies(mb_energies(1000 + k, 200, 1.0, {1}), 1.0).p_value < 0.05 ? 1 : 0;
  // Binomial(400, 0.05): mean 20, sd 4.4; accept 6..40 (beyond 3 sd either way).
  CHECK(below >= 6);
  CHECK(below <= 40);
}
