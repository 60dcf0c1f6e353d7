// The contact value g(sigma) three ways (structure.hpp): extrapolated from g(r), from Enskog's collision
// frequency and from the virial pressure. The last two share one replay of the window (measure_pressure
// counts the pair collisions and the kinetic energy it needs). The extrapolation is a weighted quadratic
// through the bins of [sigma, sigma + w], w = 0.1 sigma: g(r) is curved there (at phi = 0.4,
// g'' sigma^2 ~ 10), and a straight line over that window reads g(sigma) low by g'' w^2 / 12, 0.3 % at
// phi = 0.4, several times the statistical error of a long run (issue 38). The quadratic's bias is the
// cubic term's, |g'''| w^3 / 120, ~0.05 % at phi = 0.4 (docs/analysis.md), for an intercept error 1.5
// times the line's. Rejected: a straight line over a narrower window (as good at phi = 0.4 for
// w ~ 0.04 sigma, but its bias follows g'', so the window would have to follow the density) and a fit of
// log g (less curved, still ~0.15 % low at phi = 0.4).
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "ede/kinetic_theory.hpp"
#include "ede/pressure.hpp"
#include "ede/structure.hpp"
#include "analysis/sheared_guard.hpp"

namespace ede {

namespace {

// The inverse of the symmetric 3 x 3 matrix m (by cofactors), or nothing if it is singular.
std::optional<std::array<double, 9>> inverse3(const std::array<double, 9>& m) {
  const double c00 = m[4] * m[8] - m[5] * m[7], c01 = m[5] * m[6] - m[3] * m[8], c02 = m[3] * m[7] - m[4] * m[6];
  const double det = m[0] * c00 + m[1] * c01 + m[2] * c02;
  if (!(std::abs(det) > 0)) return std::nullopt;
  return std::array<double, 9>{c00 / det,
                               (m[2] * m[7] - m[1] * m[8]) / det,
                               (m[1] * m[5] - m[2] * m[4]) / det,
                               c01 / det,
                               (m[0] * m[8] - m[2] * m[6]) / det,
                               (m[2] * m[3] - m[0] * m[5]) / det,
                               c02 / det,
                               (m[1] * m[6] - m[0] * m[7]) / det,
                               (m[0] * m[4] - m[1] * m[3]) / det};
}

}  // namespace

Result<ContactValue> contact_from_gr(const PairCorrelation& g, double sigma, double width) {
  // Weighted least squares of g = a + b x + c x^2, x = r - sigma, over the bins inside [sigma, sigma + width]:
  // the normal equations M (a, b, c) = v, M = sum w (1, x, x^2)^T (1, x, x^2), v = sum w g (1, x, x^2).
  std::array<double, 9> m{};
  std::array<double, 3> v{};
  std::size_t used = 0;
  const double slack = 1e-9 * sigma;
  for (std::size_t k = 0; k < g.g.size(); ++k) {
    if (g.r_lo[k] < sigma - slack || g.r_hi[k] > sigma + width + slack || g.count[k] <= 0) continue;
    const double x = 0.5 * (g.r_lo[k] + g.r_hi[k]) - sigma, w = g.count[k] / (g.g[k] * g.g[k]);
    const double p[3] = {1, x, x * x};
    for (int i = 0; i < 3; ++i) {
      v[i] += w * p[i] * g.g[k];
      for (int j = 0; j < 3; ++j) m[3 * i + j] += w * p[i] * p[j];
    }
    ++used;
  }
  if (used < 4)
    return Error{"g(sigma) from g(r): fewer than 4 bins with pairs lie within [sigma, sigma + width] = [" +
                 std::to_string(sigma) + ", " + std::to_string(sigma + width) +
                 "]; use more frames or bins that start at sigma"};
  const auto inv = inverse3(m);
  if (!inv) return Error{"g(sigma) from g(r): the bins within [sigma, sigma + width] do not determine a quadratic"};
  const double a = (*inv)[0] * v[0] + (*inv)[1] * v[1] + (*inv)[2] * v[2];
  return ContactValue{a, std::sqrt((*inv)[0]),
                      "weighted quadratic fit of " + std::to_string(used) + " bins of g(r) in [sigma, sigma + " +
                          std::to_string(width) + "], extrapolated to sigma (Poisson errors; bias ~0.05 % at phi = 0.4)"};
}

ContactValue contact_from_collision_rate(double rate, std::uint64_t pairs, double n, double sigma, double kT,
                                         double mass) {
  const double g = rate / enskog_collision_rate(n, sigma, 1, kT, mass);  // omega_E is linear in g
  return ContactValue{g, pairs ? g / std::sqrt(double(pairs)) : NAN,
                      "Enskog collision frequency omega = 2 n sigma g(sigma) sqrt(pi kT / m) (Poisson error of the "
                      "collision count)"};
}

ContactValue contact_from_pressure(double z, double z_error, double n, double sigma) {
  const double b = M_PI / 2 * n * sigma * sigma;
  return ContactValue{(z - 1) / b, z_error / b, "virial Z = 1 + (pi / 2) n sigma^2 g(sigma) (block error of Z)"};
}

Result<ContactValues> contact_values(const Log& log, const FrameTimes& f, double fit_width_in_sigma,
                                     std::size_t bins_in_fit) {
  if (std::string why = sheared_refusal(log, "g(sigma) three ways"); !why.empty()) return Error{why};
  auto first = log.state_at(f.from.value_or(double(log.info().start_time)));
  if (!first) return first.error();
  const State& s = first.value();
  const std::string where = log.info().path + ": g(sigma) three ways: ";
  if (s.boundary != BoundaryKind::Periodic)
    return Error{where + "needs a periodic box (with walls the density is not uniform near them)"};
  if (s.size() < 2) return Error{where + "needs at least 2 disks"};
  for (std::size_t i = 1; i < s.size(); ++i)
    if (s.radius[i] != s.radius[0] || s.mass[i] != s.mass[0])
      return Error{where + "needs one radius and one mass (the Enskog and virial formulas used are monodisperse)"};
  auto times = frame_times(log, f);
  if (!times) return times.error();
  if (!(times.value().back() > times.value().front()))
    return Error{where + "needs a window (from < to) for the collision rate and pressure"};
  ContactValues out;
  out.sigma = 2 * s.radius[0];
  out.mass = s.mass[0];
  out.density = double(s.size()) / (s.lx * s.ly);
  PairCorrelationOptions go;
  go.r_min = out.sigma;
  go.r_max = out.sigma * (1 + fit_width_in_sigma);
  go.bins = bins_in_fit;
  auto g = pair_correlation(log, go, f);
  if (!g) return g.error();
  auto fit = contact_from_gr(g.value(), out.sigma, out.sigma * fit_width_in_sigma);
  if (!fit) return Error{where + fit.error().message};
  out.from_gr = fit.value();
  PressureOptions po;
  po.from = times.value().front();
  po.to = times.value().back();
  auto p = measure_pressure(log, po);
  if (!p) return p.error();
  const PressureReport& r = p.value();
  out.kT = r.kT.stats.mean;
  const double rate = 2.0 * double(r.totals.pair_collisions) / (double(s.size()) * (r.t1 - r.t0));
  out.from_collisions =
      contact_from_collision_rate(rate, r.totals.pair_collisions, out.density, out.sigma, out.kT, out.mass);
  out.from_pressure = contact_from_pressure(r.z_virial.stats.mean, r.z_virial.stats.error, out.density, out.sigma);
  return out;
}

}  // namespace ede
