// The contact value g(sigma) three ways (structure.hpp): extrapolated from g(r), from Enskog's collision
// frequency and from the virial pressure. The last two share one replay of the window (measure_pressure
// counts the pair collisions and the kinetic energy it needs). Rejected: a quadratic fit for the
// extrapolation, whose intercept error is several times larger for the same bins and whose curvature is
// not resolved within 0.1 sigma of contact below phi ~ 0.6.
#include <cmath>
#include <string>

#include "ede/kinetic_theory.hpp"
#include "ede/pressure.hpp"
#include "ede/structure.hpp"

namespace ede {

Result<ContactValue> contact_from_gr(const PairCorrelation& g, double sigma, double width) {
  // Weighted least squares of g = a + b (r - sigma) over the bins inside [sigma, sigma + width].
  double sw = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
  std::size_t used = 0;
  const double slack = 1e-9 * sigma;
  for (std::size_t k = 0; k < g.g.size(); ++k) {
    if (g.r_lo[k] < sigma - slack || g.r_hi[k] > sigma + width + slack || g.count[k] <= 0) continue;
    const double x = 0.5 * (g.r_lo[k] + g.r_hi[k]) - sigma, w = g.count[k] / (g.g[k] * g.g[k]);
    sw += w, sx += w * x, sxx += w * x * x, sy += w * g.g[k], sxy += w * x * g.g[k];
    ++used;
  }
  if (used < 3)
    return Error{"g(sigma) from g(r): fewer than 3 bins with pairs lie within [sigma, sigma + width] = [" +
                 std::to_string(sigma) + ", " + std::to_string(sigma + width) +
                 "]; use more frames or bins that start at sigma"};
  const double det = sw * sxx - sx * sx;
  const double a = (sxx * sy - sx * sxy) / det;
  return ContactValue{a, std::sqrt(sxx / det),
                      "weighted straight-line fit of " + std::to_string(used) + " bins of g(r) in [sigma, sigma + " +
                          std::to_string(width) + "], extrapolated to sigma (Poisson errors)"};
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
