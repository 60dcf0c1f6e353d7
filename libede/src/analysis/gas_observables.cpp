// Gas observables; see gas_observables.hpp. Sums in long double, so a pooled average over millions of
// disks keeps the digits its standard error does not already blur.
#include "ede/analysis.hpp"

#include <algorithm>
#include <cmath>

namespace ede {

double GasSnapshot::speed(std::size_t i) const { return std::sqrt(vx[i] * vx[i] + vy[i] * vy[i]); }

double GasSnapshot::kinetic_energy(std::size_t i) const { return 0.5 * mass[i] * (vx[i] * vx[i] + vy[i] * vy[i]); }

namespace {

bool selected(const GasSnapshot& s, std::size_t i, std::int32_t species) {
  return species == kAllSpecies || s.species[i] == species;
}

template <class F>
std::vector<double> collect(const GasSnapshot& s, std::int32_t species, F value) {
  std::vector<double> out;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (selected(s, i, species)) out.push_back(value(i));
  return out;
}

// The mean of value(i) over the selected disks (summed in long double), 0 if there are none.
template <class F>
double mean_of(const GasSnapshot& s, std::int32_t species, F value) {
  long double sum = 0;
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (selected(s, i, species)) sum += value(i), ++n;
  return n ? double(sum / n) : 0.0;
}

double standard_error(long double sum, long double sum2, std::uint64_t n) {
  if (n < 2) return 0;
  const long double mean = sum / n;
  const long double var = std::max(0.0L, (sum2 - n * mean * mean) / (n - 1));
  return double(std::sqrt(var / n));
}

}  // namespace

std::vector<double> speeds(const GasSnapshot& s, std::int32_t species) {
  return collect(s, species, [&](std::size_t i) { return s.speed(i); });
}

std::vector<double> kinetic_energies(const GasSnapshot& s, std::int32_t species) {
  return collect(s, species, [&](std::size_t i) { return s.kinetic_energy(i); });
}

std::vector<double> masses(const GasSnapshot& s, std::int32_t species) {
  return collect(s, species, [&](std::size_t i) { return s.mass[i]; });
}

void GasAverages::Sums::add(double m, double v, double e) {
  mass_min = n ? std::min(mass_min, m) : m;
  mass_max = n ? std::max(mass_max, m) : m;
  ++n;
  speed += v;
  speed2 += (long double)v * v;
  energy += e;
  energy2 += (long double)e * e;
}

void GasAverages::add(const GasSnapshot& s) {
  if (names_.size() < s.species_names.size()) {
    names_ = s.species_names;
    per_species_.resize(names_.size());
  }
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double v = s.speed(i), e = s.kinetic_energy(i);
    per_species_[std::size_t(s.species[i])].add(s.mass[i], v, e);
    all_.add(s.mass[i], v, e);
  }
}

std::vector<SpeciesStats> GasAverages::stats() const {
  const auto of = [](const std::string& name, const Sums& s) {
    SpeciesStats r;
    r.name = name;
    r.n = s.n;
    r.mass_min = s.mass_min;
    r.mass_max = s.mass_max;
    if (s.n == 0) return r;
    r.mean_speed = double(s.speed / s.n);
    r.mean_kinetic_energy = double(s.energy / s.n);
    r.kT = r.mean_kinetic_energy;
    r.mean_speed_error = standard_error(s.speed, s.speed2, s.n);
    r.mean_kinetic_energy_error = standard_error(s.energy, s.energy2, s.n);
    return r;
  };
  std::vector<SpeciesStats> out;
  for (std::size_t k = 0; k < names_.size(); ++k) out.push_back(of(names_[k], per_species_[k]));
  out.push_back(of("all", all_));
  return out;
}

std::vector<SpeciesStats> species_stats(const GasSnapshot& s) {
  GasAverages a;
  a.add(s);
  return a.stats();
}

double temperature(const GasSnapshot& s, std::int32_t species) {
  return mean_of(s, species, [&](std::size_t i) { return s.kinetic_energy(i); });
}

double mean_speed(const GasSnapshot& s, std::int32_t species) {
  return mean_of(s, species, [&](std::size_t i) { return s.speed(i); });
}

SpeedClasses speed_classes(const GasSnapshot& s, double reference_speed, std::int32_t species) {
  SpeedClasses c;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!selected(s, i, species)) continue;
    switch (speed_class(s.speed(i), reference_speed)) {
      case SpeedClass::Slow: ++c.slow; break;
      case SpeedClass::Medium: ++c.medium; break;
      case SpeedClass::Fast: ++c.fast; break;
    }
  }
  const double n = double(c.slow + c.medium + c.fast);
  if (n > 0) {
    c.slow_percent = 100.0 * double(c.slow) / n;
    c.medium_percent = 100.0 * double(c.medium) / n;
    c.fast_percent = 100.0 * double(c.fast) / n;
  }
  return c;
}

}  // namespace ede
