// sheared_viscosity and zero_shear_viscosity (ede/viscosity.hpp): the shear viscosity of a steadily sheared
// gas, eta = -<P_xy> / gamma, from the exact stress integral (stress_walk.cpp) over a few long blocks of
// the window, and its limit gamma -> 0 over runs at several rates. With W_b the integral of V P_ab over
// block b (width w) and K_b that of sum m c^2:
//   P_xy,b = (W_xy,b + W_yx,b) / (2 V w),   kT_b = K_b / (2 (N - 1) w),   eta_b = -P_xy,b / gamma,
// and every mean comes with the standard error of its block values (block_stats, ede/block_average.hpp;
// blocks far longer than the stress's correlation time, a few collision times, are nearly independent). Reduced units use the disks' diameter
// and mass: hard disks have no energy scale but kT, so eta sigma / sqrt(m kT) is a function of phi and
// gamma sigma sqrt(m / kT) alone, and runs whose steady temperatures differ (a thermostat holds the
// temperature only up to the heating it removes) still fall on one curve. Formulas, the thermostat's
// bias and measurements: docs/analysis.md, "Shear viscosity from a sheared run".
#include <cmath>
#include <limits>

#include "analysis/enskog_reference.hpp"
#include "analysis/stress_walk.hpp"
#include "ede/block_average.hpp"
#include "ede/kinetic_theory.hpp"
#include "ede/number_text.hpp"
#include "ede/viscosity.hpp"

namespace ede {

Result<ShearedViscosity> sheared_viscosity(const Log& log, const ShearedOptions& o) {
  const LogInfo& info = log.info();
  const std::string where = info.path + ": sheared viscosity: ";
  if (!info.lees_edwards)
    return Error{where + "the box is not sheared (not a Lees-Edwards log); for an equilibrium run in a periodic box "
                         "use the equilibrium route (shear_viscosity, ede-stats viscosity --max-lag)"};
  if (const std::string why = stress::sheared_stress_refusal(log); !why.empty()) return Error{where + why};
  const double gamma = info.shear_rate;
  if (!(gamma > 0)) return Error{where + "the shear rate is 0: there is no mean stress to divide by it"};
  const double from = o.from.value_or(info.start_time), to = o.to.value_or(double(info.end_time));
  if (!(from >= info.start_time && to <= double(info.end_time) && from < to))
    return Error{where + "the window " + brief(from) + " to " + brief(to) + " is not a non-empty part of the log's " +
                 brief(info.start_time) + " to " + brief(double(info.end_time))};
  if (o.blocks < 2) return Error{where + "at least 2 blocks are needed for an error"};
  const double width = (to - from) / double(o.blocks);
  auto integral = stress::integrate(log, from, width, o.blocks);
  if (!integral) return integral.error();
  const StressIntegral& w = integral.value();
  if (w.disks < 2) return Error{where + "needs at least 2 disks"};

  ShearedViscosity out;
  out.shear_rate = gamma, out.from = from, out.to = to, out.area = w.area, out.disks = w.disks, out.blocks = o.blocks;
  out.pair_events = w.pair_events, out.thermostat_events = w.thermostat_events;
  const double to_stress = 1 / (w.area * width), dof = 2 * double(w.disks - 1);
  std::vector<double> normal(o.blocks);
  for (std::size_t b = 0; b < o.blocks; ++b) {
    out.block_time.push_back(from + width * (double(b) + 0.5));
    out.block_shear_stress.push_back(0.5 * (w.xy[b] + w.yx[b]) * to_stress);
    out.block_kT.push_back(w.kinetic[b] / (dof * width));
    out.block_viscosity.push_back(-out.block_shear_stress[b] / gamma);
    normal[b] = (w.xx[b] - w.yy[b]) * to_stress;
  }
  const double span = to - from;
  const BlockStats stress = block_stats(out.block_shear_stress), difference = block_stats(normal);
  const BlockStats temperature = block_stats(out.block_kT);
  out.shear_stress = stress.mean, out.shear_stress_error = stress.error;
  out.kinetic_shear_stress = double(w.kinetic_xy / (long double)(w.area * span));
  out.collisional_shear_stress = double((w.impulse_xy + w.impulse_yx) / 2 / (long double)(w.area * span));
  out.normal_stress_difference = difference.mean, out.normal_stress_difference_error = difference.error;
  out.pressure = double((w.kinetic_xx + w.kinetic_yy + w.impulse_xx + w.impulse_yy) / 2 / (long double)(w.area * span));
  out.kT = temperature.mean, out.kT_error = temperature.error;
  if (!(out.kT > 0)) return Error{where + "the disks do not move relative to the flow (kT = 0)"};
  out.viscosity = -out.shear_stress / gamma, out.viscosity_error = out.shear_stress_error / gamma;

  auto start = log.state_at(from);
  if (!start) return start.error();
  const stress::EnskogReference e = stress::enskog_reference(log, start.value(), w.area, out.kT);
  out.packing_fraction = e.packing_fraction, out.g_contact = e.g_contact;
  out.enskog = e.enskog, out.dilute = e.dilute, out.enskog_note = e.note, out.sigma = e.sigma;
  out.enskog_reduced = e.enskog == e.enskog ? enskog_viscosity(e.packing_fraction, 1, e.g_contact, 1, 1)
                                            : std::numeric_limits<double>::quiet_NaN();
  if (e.sigma == e.sigma) {
    out.reduced_rate = gamma * e.sigma * std::sqrt(e.mass / out.kT);
    out.reduced_viscosity = out.viscosity * e.sigma / std::sqrt(e.mass * out.kT);
    std::vector<double> reduced(o.blocks);
    for (std::size_t b = 0; b < o.blocks; ++b)
      reduced[b] = out.block_viscosity[b] * e.sigma / std::sqrt(e.mass * out.block_kT[b]);
    out.reduced_viscosity_error = block_stats(reduced).error;
  } else {
    out.reduced_rate = out.reduced_viscosity = out.reduced_viscosity_error = std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

Result<ZeroShearFit> zero_shear_viscosity(const std::vector<ShearedViscosity>& runs) {
  const std::string where = "zero-shear viscosity: ";
  if (runs.size() < 2) return Error{where + "needs runs at two rates at least (got " + std::to_string(runs.size()) + ")"};
  ZeroShearFit f;
  f.points = runs.size();
  f.packing_fraction = runs[0].packing_fraction;
  double s = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const ShearedViscosity& r = runs[k];
    const std::string which = "run " + std::to_string(k + 1) + " (rate " + brief(r.shear_rate) + ")";
    if (!(r.reduced_viscosity == r.reduced_viscosity))
      return Error{where + which + " is not of equal disks, so it has no reduced viscosity to fit"};
    if (!(r.reduced_viscosity_error > 0)) return Error{where + which + " has no error to weight it by"};
    if (std::fabs(r.packing_fraction - f.packing_fraction) > 1e-9 * f.packing_fraction)
      return Error{where + which + " is at packing fraction " + brief(r.packing_fraction) + ", run 1 at " +
                   brief(f.packing_fraction) + ": fit runs at one density"};
    const double x = r.reduced_rate * r.reduced_rate, y = r.reduced_viscosity;
    const double wt = 1 / (r.reduced_viscosity_error * r.reduced_viscosity_error);
    s += wt, sx += wt * x, sxx += wt * x * x, sy += wt * y, sxy += wt * x * y;
  }
  const double det = s * sxx - sx * sx;
  if (!(det > 1e-12 * s * sxx))
    return Error{where + "the runs' reduced rates are (nearly) the same: give runs at different shear rates"};
  f.reduced_viscosity = (sxx * sy - sx * sxy) / det, f.slope = (s * sxy - sx * sy) / det;
  f.reduced_viscosity_error = std::sqrt(sxx / det), f.slope_error = std::sqrt(s / det);
  for (const ShearedViscosity& r : runs) {
    const double d = (r.reduced_viscosity - f.reduced_viscosity - f.slope * r.reduced_rate * r.reduced_rate) /
                     r.reduced_viscosity_error;
    f.chi2 += d * d;
  }
  f.enskog_reduced = runs[0].enskog_reduced;
  return f;
}

}  // namespace ede
