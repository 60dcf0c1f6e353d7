// measure_distribution (ede/analysis.hpp): the histogram of speeds or energies of a log against
// Maxwell-Boltzmann, from snapshots at t = 0 and at the requested times.
//
// One forward pass of snapshots: t = 0 first (the initial sample, whose histogram sits beside the other
// in the same bins), then the requested times, pooled. kT is measured on the sample itself and the KS test
// runs on energies, so a mixture of masses is tested correctly. Rejected: fitting kT by least squares to
// the histogram, which would make the temperature depend on the binning.
#include <algorithm>

#include "ede/analysis.hpp"

namespace ede {

namespace {

// The values of the selected disks in one snapshot or several pooled; their masses (the same at every time).
struct Sample {
  std::vector<double> values, energies, masses;

  void add(const GasSnapshot& s, std::int32_t species, Quantity q) {
    const std::vector<double> e = kinetic_energies(s, species);
    const std::vector<double> v = q == Quantity::Speed ? speeds(s, species) : e;
    values.insert(values.end(), v.begin(), v.end());
    energies.insert(energies.end(), e.begin(), e.end());
    if (masses.empty()) masses = ede::masses(s, species);
  }
  double kT() const {
    long double sum = 0;
    for (const double e : energies) sum += e;
    return energies.empty() ? 0.0 : double(sum / energies.size());
  }
  double max() const { return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end()); }
};

void add_law(DistributionReport& r, Quantity q, std::size_t curve_points) {
  const std::vector<double>& edges = r.histogram.edges;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) r.law_density.push_back(r.law.bin_density(q, edges[k], edges[k + 1]));
  const double hi = edges.back();
  for (std::size_t k = 0; k <= curve_points; ++k) {
    const double x = hi * double(k) / double(curve_points);
    r.curve_x.push_back(x);
    r.curve_density.push_back(r.law.density(q, x));
  }
}

}  // namespace

Result<DistributionReport> measure_distribution(const Log& log, const DistributionRequest& request) {
  if (request.bins < 1) return Error{"a histogram needs at least one bin"};
  if (request.times.empty()) return Error{"no time to take the distribution at"};
  if (request.curve_points < 1) return Error{"the law's curve needs at least one interval"};
  Sample now, initial;
  std::vector<double> times = {0.0};
  times.insert(times.end(), request.times.begin(), request.times.end());
  bool first = true;
  Status s = for_each_snapshot(log, times, [&](const GasSnapshot& snap) {
    (first ? initial : now).add(snap, request.species, request.quantity);
    first = false;
  });
  if (!s) return s.error();

  DistributionReport r;
  r.kT = now.kT();
  if (!(r.kT > 0))
    return Error{log.info().path + ": the selected disks are at rest (kT = 0): no distribution to compare"};
  r.samples = now.values.size();
  r.disks = r.samples / request.times.size();
  r.ks = ks_test_mb_energies(now.energies, r.kT);
  r.initial_kT = initial.kT();
  if (r.initial_kT > 0) r.initial_ks = ks_test_mb_energies(initial.energies, r.initial_kT);
  r.law = maxwell_boltzmann_for(initial.masses, r.kT);
  const double hi = std::max(now.max(), initial.max());
  const std::vector<double> edges = uniform_edges(0, hi > 0 ? hi : 1, request.bins);
  r.histogram = make_histogram(now.values, edges);
  r.initial = make_histogram(initial.values, edges);
  r.density = densities(r.histogram);
  r.initial_density = densities(r.initial);
  add_law(r, request.quantity, request.curve_points);
  return r;
}

}  // namespace ede
