// Kinetic-theory references (ede/kinetic_theory.hpp): pure formulas, then their values for a state or log.
#include "ede/kinetic_theory.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "ede/analysis.hpp"

namespace ede {

double henderson_contact_value(double phi) { return (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi)); }

double enskog_diffusion(double n, double sigma, double g_contact, double kT, double mass) {
  return 1 / (2 * n * sigma * g_contact) * std::sqrt(kT / (std::numbers::pi * mass));
}

double dilute_viscosity(double sigma, double kT, double mass, double sonine) {
  return sonine / (2 * sigma) * std::sqrt(mass * kT / std::numbers::pi);
}

double enskog_viscosity(double phi, double sigma, double chi, double kT, double mass, double sonine) {
  const double streaming = (1 + phi * chi) * (1 + phi * chi) / chi;
  return dilute_viscosity(sigma, kT, mass, 1) * (sonine * streaming + 8 / std::numbers::pi * phi * phi * chi);
}

double enskog_collision_rate(double n, double sigma, double g, double kT, double m) {
  return 2 * n * sigma * g * std::sqrt(std::numbers::pi * kT / m);
}

double haff_tau(double xi, double omega0) {
  const double a = 1 - xi * xi;
  return a > 0 && omega0 > 0 ? 4 / (a * omega0) : std::numeric_limits<double>::infinity();
}

Temperature temperature_of(const State& s) {
  Temperature t;
  long double k = 0, px = 0, py = 0, m = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const long double mi = s.mass.exact(i), vx = s.vx.exact(i), vy = s.vy.exact(i);
    k += mi * (vx * vx + vy * vy) / 2;
    px += mi * vx, py += mi * vy, m += mi;
  }
  t.kinetic = double(k);
  t.px = double(px), t.py = double(py);
  const bool periodic = s.boundary == BoundaryKind::Periodic;
  t.kinetic_cm = periodic && m > 0 ? double(k - (px * px + py * py) / (2 * m)) : double(k);
  t.degrees = periodic ? double(s.size()) - 1 : double(s.size());
  t.kT = t.degrees > 0 ? t.kinetic_cm / t.degrees : 0;
  return t;
}

EnskogReference enskog_reference(const State& s) {
  EnskogReference e;
  e.temperature = temperature_of(s);
  if (s.size() == 0) {
    e.why_not = "the state has no disks";
    return e;
  }
  const double r = s.radius[0], m = s.mass[0];
  long double area_sum = 0;
  bool equal = true;
  for (std::size_t i = 0; i < s.size(); ++i) {
    equal = equal && s.radius[i] == r && s.mass[i] == m;
    area_sum += std::numbers::pi_v<long double> * s.radius.exact(i) * s.radius.exact(i);
  }
  const double area = s.lx * s.ly;
  e.number_density = double(s.size()) / area;
  e.packing_fraction = double(area_sum / area);
  e.sigma = 2 * r;
  e.mass = m;
  e.g_contact = henderson_contact_value(e.packing_fraction);
  if (!equal) {
    e.why_not = "the disks differ in radius or mass: Enskog's rate for a mixture needs g(sigma) for every pair of species";
    return e;
  }
  e.applicable = true;
  e.rate = enskog_collision_rate(e.number_density, e.sigma, e.g_contact, e.temperature.kT, m);
  return e;
}

Result<EnskogReference> enskog_at(const Log& log, double t) {
  auto s = log.state_at(Time(t));
  if (!s) return s.error();
  return enskog_reference(s.value());
}

Result<std::vector<SpeciesTimeAverage>> species_time_averages(const Log& log, double from, double to,
                                                              std::size_t points, std::size_t blocks) {
  if (!(to > from) || points < 2 || blocks < 2 || points < blocks)
    return Error{log.info().path + ": a time average needs to > from, at least 2 blocks and a point per block"};
  std::vector<double> times(points);
  for (std::size_t k = 0; k < points; ++k) times[k] = k + 1 == points ? to : from + (to - from) * double(k) / double(points - 1);
  auto series = log_series(log, times);
  if (!series) return series.error();
  const LogSeries& ls = series.value();
  const std::size_t ns = ls.species_names.size();
  std::vector<SpeciesTimeAverage> out;
  for (std::size_t s = 0; s <= ns; ++s) {
    SpeciesTimeAverage a;
    a.name = s < ns ? ls.species_names[s] : "all";
    a.n = s < ns ? ls.species_count[s] : ls.disks();
    if (a.n == 0) {
      out.push_back(a);
      continue;
    }
    const std::size_t per_block = points / blocks;
    std::vector<double> block(blocks, 0);
    for (std::size_t b = 0; b < blocks; ++b) {
      for (std::size_t k = b * per_block; k < (b + 1) * per_block; ++k)
        block[b] += (s < ns ? ls.species_energy[s][k] : ls.kinetic_energy[k]) / double(a.n);
      block[b] /= double(per_block);
    }
    double mean = 0, var = 0;
    for (const double v : block) mean += v;
    mean /= double(blocks);
    for (const double v : block) var += (v - mean) * (v - mean);
    a.mean_kinetic_energy = mean;
    a.error = std::sqrt(var / double(blocks - 1) / double(blocks));
    out.push_back(a);
  }
  return out;
}

}  // namespace ede
