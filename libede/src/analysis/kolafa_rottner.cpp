// Kolafa and Rottner's hard-disk equation of state (ede/kinetic_theory.hpp): a sum of powers of
// x = phi / (1 - phi) with fitted coefficients, evaluated by Horner's rule over k = 0..12 and the two high
// powers apart (x^22, x^57 through std::pow: Horner over 58 mostly zero terms would only add round-off).
//
// The coefficients are those of the paper's fit to rho* <= 0.90 (Mol. Phys. 104, 3435 (2006)). The paper
// itself was not at hand: they were transcribed from a public implementation citing that fit, and are
// trusted because they reproduce, independently of that source, the exact B3 and B4 of hard disks and
// Clisby and McCoy's numerical B5..B10 within those values' stated errors (the paper's fit was built to
// reproduce B2..B10), and agree with Henderson's equation to its known accuracy at phi <= 0.65
// (tests/analysis/test_kolafa_rottner.cpp). C0 = 1 and C1 = 2 are exact (ideal gas and B2).
#include <cmath>
#include <limits>

#include "ede/kinetic_theory.hpp"

namespace ede {

namespace {

constexpr double kLow[] = {1.0,             2.0,              1.12801775,      0.00181895291,  -0.0526134737,
                           0.0504960168,    -0.0325537792,    0.0134578632,    0.00140888182,  -0.00834273601,
                           0.00694127367,   -0.00262254723,   0.000355746352};
constexpr double kC22 = -5.24672938e-9;
constexpr double kC57 = 5.88054639e-23;

}  // namespace

double kolafa_rottner_z(double phi) {
  if (!(phi >= 0 && phi <= kKolafaRottnerPhiMax)) return std::numeric_limits<double>::quiet_NaN();
  const double x = phi / (1 - phi);
  double z = 0;
  for (int k = int(std::size(kLow)) - 1; k >= 0; --k) z = z * x + kLow[k];
  return z + kC22 * std::pow(x, 22) + kC57 * std::pow(x, 57);
}

double kolafa_rottner_contact_value(double phi) {
  if (phi == 0) return 1;  // the limit: Z - 1 = 2 phi + O(phi^2)
  return (kolafa_rottner_z(phi) - 1) / (2 * phi);
}

}  // namespace ede
