// Distributions: histograms with given bins, the 2D Maxwell-Boltzmann law, and the Kolmogorov-Smirnov test.
//
// Pure functions of samples (doubles), no log and no state: the analysis tools feed them speeds or
// energies taken from a replayed log. In 2D at temperature kT a disk of mass m has the speed density
// p(v) = (m v / kT) exp(-m v^2 / 2kT) and the kinetic-energy density p(E) = exp(-E/kT) / kT: E = m v^2 / 2
// is exponential with mean kT whatever the mass, so a sample of mixed masses is tested on its energies, and
// for one mass a test on speeds gives the same statistic (KS is invariant under the monotone map v -> E).
// The KS p-value uses the asymptotic Kolmogorov distribution with Stephens' small-n correction; it
// assumes independent samples and a law fixed in advance (see docs/analysis.md for the caveats).
// Rejected: fitting with chi-square on the histogram, whose result depends on the binning the user chose.
// (One part of ede/analysis.hpp, which includes them all.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace ede {

// Counts of samples in bins [edges[k], edges[k+1]); the last bin is closed [edges[K-1], edges[K]].
struct Histogram {
  std::vector<double> edges;         // K + 1 strictly increasing edges
  std::vector<std::uint64_t> count;  // K counts
  std::uint64_t outside = 0;         // samples in no bin (below, above, or NaN)

  std::size_t bins() const { return count.size(); }
  std::uint64_t samples() const;     // every sample given, inside or not
};

// K bins of equal width from lo to hi (K >= 1, lo < hi); the last edge is exactly hi.
std::vector<double> uniform_edges(double lo, double hi, std::size_t bins);
// The histogram of `samples` in the given bins (edges as uniform_edges makes them, or any increasing list).
Histogram make_histogram(const std::vector<double>& samples, std::vector<double> edges);
// count / (samples * width) per bin: integrates to the fraction of samples inside the bins (1 when none
// falls outside); all zero for an empty sample.
std::vector<double> densities(const Histogram& h);

// The 2D Maxwell-Boltzmann law for one mass (kT > 0, m > 0); zero below 0.
double mb_speed_density(double v, double mass, double kT);
double mb_speed_cdf(double v, double mass, double kT);  // 1 - exp(-m v^2 / 2kT)
double mb_energy_density(double e, double kT);          // exp(-E/kT) / kT
double mb_energy_cdf(double e, double kT);              // 1 - exp(-E/kT)

enum class Quantity { Speed, Energy };
const char* to_string(Quantity);

// The Maxwell-Boltzmann law of a population of disks at one temperature: for speeds, a mixture of the
// single-mass densities weighted by the fraction of disks of each mass; for energies, exponential.
struct MaxwellBoltzmann {
  struct Share {
    double mass = 1;
    double fraction = 1;
  };
  double kT = 1;
  std::vector<Share> masses;  // fractions sum to 1

  double density(Quantity q, double x) const;
  double cdf(Quantity q, double x) const;
  // The mean density over [lo, hi]: (cdf(hi) - cdf(lo)) / (hi - lo), what a histogram bin should show.
  double bin_density(Quantity q, double lo, double hi) const;
};
// The law for a sample whose disks have these masses (one entry per disk), grouped by distinct mass.
MaxwellBoltzmann maxwell_boltzmann_for(const std::vector<double>& masses, double kT);

// P(K > lambda) for the Kolmogorov distribution: 2 sum_{j>=1} (-1)^(j-1) exp(-2 j^2 lambda^2), with the
// Jacobi-transformed series for small lambda where that one converges slowly.
double kolmogorov_q(double lambda);

struct KsResult {
  double statistic = 0;  // D = sup |F_n(x) - F(x)|
  double p_value = 1;    // asymptotic, with Stephens' correction
  std::size_t n = 0;
};

// The exact KS statistic of a sample against a continuous CDF (the sample is copied and sorted).
double ks_statistic(std::vector<double> sample, const std::function<double(double)>& cdf);
// Q((sqrt(n) + 0.12 + 0.11 / sqrt(n)) D) (Stephens 1970); 1 for n = 0.
double ks_p_value(double statistic, std::size_t n);
KsResult ks_test(std::vector<double> sample, const std::function<double(double)>& cdf);
// Kinetic energies against the exponential law of mean kT: the MB test for any mix of masses.
KsResult ks_test_mb_energies(std::vector<double> energies, double kT);

}  // namespace ede
