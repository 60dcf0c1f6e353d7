// Kolafa and Rottner's equation of state (ede/kinetic_theory.hpp): its low-density expansion against the
// exact virial coefficients of hard disks and Clisby and McCoy's numerical ones, its agreement with
// Henderson's equation where that one is known to hold, and its range.
//
// Convention: Z = 1 + sum_n b_n phi^(n-1), n >= 2, phi the packing fraction; B_n / B2^(n-1) = b_n / 2^(n-1)
// (B2 = 2 phi / n, the disks' excluded area over two). The b_n are read off the function itself by fitting
// a degree-10 polynomial through Z(k h) - 1, k = 1..10, h = 0.01: the fit's own error, found by doing the
// same to a polynomial of known coefficients, is below 1e-9 relative for b3, 3e-8 for b4, 2e-6 for b5 and
// 5e-5 for b6, so the tolerances below are those plus the values' own uncertainty.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "ede/kinetic_theory.hpp"
#include "ede/pressure.hpp"

using namespace ede;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Solves the n x n system A b = y by Gaussian elimination with partial pivoting.
std::vector<double> solve(std::vector<std::vector<double>> a, std::vector<double> y) {
  const std::size_t n = y.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    std::swap(a[c], a[p]);
    std::swap(y[c], y[p]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c) continue;
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
      y[r] -= f * y[c];
    }
  }
  std::vector<double> b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = y[i] / a[i][i];
  return b;
}

// Coefficients of phi^1 .. phi^10 of Z(phi) - 1: b[0] is b_2, b[1] is b_3, ...
std::vector<double> low_density_series() {
  const int m = 10;
  const double h = 0.01;
  std::vector<std::vector<double>> a(m, std::vector<double>(m));
  std::vector<double> y(m);
  for (int k = 1; k <= m; ++k) {
    for (int n = 1; n <= m; ++n) a[k - 1][n - 1] = std::pow(k * h, n);
    y[k - 1] = kolafa_rottner_z(k * h) - 1;
  }
  return solve(a, y);
}

}  // namespace

TEST_CASE("Kolafa-Rottner: virial coefficients B2, B3, B4 exact and B5, B6 as Clisby-McCoy", "[analysis][eos]") {
  const std::vector<double> b = low_density_series();
  const double b2 = b[0], b3 = b[1] / 4, b4 = b[2] / 8, b5 = b[3] / 16, b6 = b[4] / 32;  // B_n / B2^(n-1)
  CHECK(b2 == Approx(2.0).epsilon(1e-9));
  CHECK(b3 == Approx(4.0 / 3 - std::sqrt(3.0) / kPi).epsilon(1e-8));
  CHECK(b4 == Approx(2 - 9 * std::sqrt(3.0) / (2 * kPi) + 10 / (kPi * kPi)).epsilon(1e-6));
  // Clisby and McCoy, J. Stat. Phys. 122, 15 (2006), Table 1, D = 2: 0.33355604(1), 0.1988425(42).
  CHECK(b5 == Approx(0.33355604).epsilon(1e-5));
  CHECK(b6 == Approx(0.1988425).epsilon(1.5e-4));
  // A wrong coefficient shows here: Henderson's equation, exact to B3 only, fails the B4 check.
  const double h4 = (1 + 0.01 * 0.01 / 8) / ((1 - 0.01) * (1 - 0.01));
  CHECK(std::abs(kolafa_rottner_z(0.01) - h4) > 1e-7);
}

TEST_CASE("Kolafa-Rottner: within Henderson's known accuracy up to phi 0.65, apart at the transition", "[analysis][eos]") {
  for (double phi : {0.1, 0.2, 0.3, 0.4, 0.5}) {
    INFO("phi = " << phi);
    CHECK(std::abs(kolafa_rottner_z(phi) / henderson_z(phi) - 1) < 0.005);
  }
  for (double phi : {0.55, 0.6, 0.65}) {
    INFO("phi = " << phi);
    CHECK(std::abs(kolafa_rottner_z(phi) / henderson_z(phi) - 1) < 0.03);
    CHECK(kolafa_rottner_z(phi) < henderson_z(phi));  // Henderson overestimates the dense fluid
  }
  // At phi = 0.70 (the fluid's edge) Henderson is 10-15% too high.
  const double r = henderson_z(0.70) / kolafa_rottner_z(0.70) - 1;
  CHECK(r > 0.10);
  CHECK(r < 0.15);
  // Values of the fit at rho* = 4 phi / pi = 0.5 and 0.8 (Z = 2.8.., 6.8..): monotone, finite.
  double last = 1;
  for (double phi = 0; phi <= kKolafaRottnerPhiMax; phi += 0.01) {
    CHECK(kolafa_rottner_z(phi) > last - 1e-15);
    last = kolafa_rottner_z(phi);
  }
}

TEST_CASE("Kolafa-Rottner: g(sigma) = (Z - 1) / (2 phi), NaN outside the fit's range", "[analysis][eos]") {
  CHECK(kolafa_rottner_contact_value(0) == 1);
  CHECK(kolafa_rottner_contact_value(1e-6) == Approx(1).epsilon(1e-5));
  CHECK(kolafa_rottner_contact_value(0.5) == Approx((kolafa_rottner_z(0.5) - 1) / 1.0).epsilon(1e-15));
  CHECK(kolafa_rottner_contact_value(0.4) == Approx(henderson_contact_value(0.4)).epsilon(0.005));
  CHECK(std::isnan(kolafa_rottner_z(0.72)));
  CHECK(std::isnan(kolafa_rottner_z(-0.1)));
  CHECK(std::isnan(kolafa_rottner_contact_value(0.8)));
  CHECK(std::isfinite(kolafa_rottner_z(kKolafaRottnerPhiMax)));
}
