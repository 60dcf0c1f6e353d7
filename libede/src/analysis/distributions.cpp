// Histograms, the 2D Maxwell-Boltzmann law and the KS test; see distributions.hpp.
// Bin lookup is a binary search on the edges, so a sample on an edge lands in the bin the edges say, with
// no rounding of (x - lo) / width to disagree with them.
#include "ede/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace ede {

std::uint64_t Histogram::samples() const {
  std::uint64_t n = outside;
  for (const std::uint64_t c : count) n += c;
  return n;
}

std::vector<double> uniform_edges(double lo, double hi, std::size_t bins) {
  std::vector<double> edges(bins + 1);
  for (std::size_t k = 0; k <= bins; ++k) edges[k] = lo + (hi - lo) * (double(k) / double(bins));
  edges.back() = hi;
  return edges;
}

Histogram make_histogram(const std::vector<double>& samples, std::vector<double> edges) {
  Histogram h;
  h.edges = std::move(edges);
  h.count.assign(h.edges.size() < 2 ? 0 : h.edges.size() - 1, 0);
  if (h.count.empty()) {
    h.outside = samples.size();
    return h;
  }
  const double lo = h.edges.front(), hi = h.edges.back();
  for (const double x : samples) {
    if (!(x >= lo && x <= hi)) {
      ++h.outside;
      continue;
    }
    const auto it = std::upper_bound(h.edges.begin(), h.edges.end(), x);
    const std::size_t k = std::min(std::size_t(it - h.edges.begin()) - 1, h.count.size() - 1);
    ++h.count[k];
  }
  return h;
}

std::vector<double> densities(const Histogram& h) {
  std::vector<double> d(h.bins(), 0.0);
  const double n = double(h.samples());
  if (n == 0) return d;
  for (std::size_t k = 0; k < h.bins(); ++k) d[k] = double(h.count[k]) / (n * (h.edges[k + 1] - h.edges[k]));
  return d;
}

double mb_speed_density(double v, double mass, double kT) {
  if (v < 0) return 0;
  return mass * v / kT * std::exp(-mass * v * v / (2 * kT));
}

double mb_speed_cdf(double v, double mass, double kT) {
  if (v <= 0) return 0;
  return -std::expm1(-mass * v * v / (2 * kT));
}

double mb_energy_density(double e, double kT) {
  if (e < 0) return 0;
  return std::exp(-e / kT) / kT;
}

double mb_energy_cdf(double e, double kT) {
  if (e <= 0) return 0;
  return -std::expm1(-e / kT);
}

const char* to_string(Quantity q) { return q == Quantity::Speed ? "speed" : "energy"; }

double MaxwellBoltzmann::density(Quantity q, double x) const {
  if (q == Quantity::Energy) return mb_energy_density(x, kT);
  double sum = 0;
  for (const Share& s : masses) sum += s.fraction * mb_speed_density(x, s.mass, kT);
  return sum;
}

double MaxwellBoltzmann::cdf(Quantity q, double x) const {
  if (q == Quantity::Energy) return mb_energy_cdf(x, kT);
  double sum = 0;
  for (const Share& s : masses) sum += s.fraction * mb_speed_cdf(x, s.mass, kT);
  return sum;
}

double MaxwellBoltzmann::bin_density(Quantity q, double lo, double hi) const {
  return (cdf(q, hi) - cdf(q, lo)) / (hi - lo);
}

MaxwellBoltzmann maxwell_boltzmann_for(const std::vector<double>& masses, double kT) {
  std::map<double, std::size_t> count;
  for (const double m : masses) ++count[m];
  MaxwellBoltzmann mb;
  mb.kT = kT;
  for (const auto& [m, c] : count) mb.masses.push_back({m, double(c) / double(masses.size())});
  return mb;
}

double kolmogorov_q(double lambda) {
  if (!(lambda > 0)) return 1;
  constexpr double pi = 3.14159265358979323846;
  if (lambda < 1.18) {
    // P(K <= lambda) = sqrt(2 pi) / lambda * sum_{j>=1} exp(-(2j - 1)^2 pi^2 / (8 lambda^2))
    const double a = pi * pi / (8 * lambda * lambda);
    double sum = 0;
    for (int j = 1; j <= 50; ++j) {
      const double term = std::exp(-double((2 * j - 1) * (2 * j - 1)) * a);
      sum += term;
      if (term < 1e-17 * sum) break;
    }
    return 1 - std::sqrt(2 * pi) / lambda * sum;
  }
  double sum = 0;
  for (int j = 1; j <= 50; ++j) {
    const double term = std::exp(-2.0 * j * j * lambda * lambda);
    sum += (j % 2 ? term : -term);
    if (term < 1e-17 * sum) break;
  }
  return std::clamp(2 * sum, 0.0, 1.0);
}

double ks_statistic(std::vector<double> sample, const std::function<double(double)>& cdf) {
  std::sort(sample.begin(), sample.end());
  const double n = double(sample.size());
  double d = 0;
  for (std::size_t i = 0; i < sample.size(); ++i) {
    const double f = cdf(sample[i]);
    d = std::max({d, double(i + 1) / n - f, f - double(i) / n});
  }
  return d;
}

double ks_p_value(double statistic, std::size_t n) {
  if (n == 0) return 1;
  const double rn = std::sqrt(double(n));
  return kolmogorov_q((rn + 0.12 + 0.11 / rn) * statistic);
}

KsResult ks_test(std::vector<double> sample, const std::function<double(double)>& cdf) {
  KsResult r;
  r.n = sample.size();
  r.statistic = ks_statistic(std::move(sample), cdf);
  r.p_value = ks_p_value(r.statistic, r.n);
  return r;
}

KsResult ks_test_mb_energies(std::vector<double> energies, double kT) {
  return ks_test(std::move(energies), [kT](double e) { return mb_energy_cdf(e, kT); });
}

}  // namespace ede
