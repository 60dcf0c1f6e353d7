// Shear viscosity from an equilibrium run, exactly from the events (the Einstein-Helfand route).
//
// The pressure tensor of hard disks is a sum of a kinetic part and impulses: over any interval,
//   integral V P_ab dt = sum_i integral m_i c_ia c_ib dt + sum over pair (and step) events of r_ij,a dp_i,b,
// with c = v - u the velocity relative to the centre of mass (u = P / M), r_ij = r_i - r_j the nearest-image
// separation at the event and dp_i the impulse on i. Velocities are constant between a disk's events, so
// the first sum is exact from running sums of m v_a v_b; the second is exact from the logged positions and
// velocities. stress_integral gives it per bin of a time grid (no sampling: a bin's value is the integral).
// The Helfand moment G(t) = integral_0^t V P_xy then gives eta = lim <(G(t0 + t) - G(t0))^2> / (2 V kT t),
// with V the area and the average over origins t0 on the bin grid; 2D's two independent traceless
// components, the symmetrised P_xy and (P_xx - P_yy)/2, give the same eta in an isotropic fluid and are
// averaged. The Green-Kubo running integral of the bin-averaged stress autocorrelation comes from the
// same bins. Formulas, errors, references and measurements: docs/analysis.md ("Shear viscosity").
// Refused: walls (they exchange momentum with the gas: the stress autocorrelation of a closed box does not
// give the bulk viscosity), gravity, rough disks (their antisymmetric stress couples to spin), inelastic
// collisions and the Andersen thermostat (no equilibrium dynamics: a thermostat's redraws destroy momentum
// and the stress correlations with it), and a time reversal inside the window.
// A sheared (Lees-Edwards) box changes two places of the stress integral (analysis/stress_walk.cpp): the
// kinetic part is taken relative to the shear flow, and a pair across the sliding edge is separated
// through the sliding image; its viscosity is the mean stress over the rate (sheared_viscosity, below).
// Rejected: the Helfand moment sum_i m x_i v_iy from unwrapped positions (in a periodic box it jumps when a
// disk crosses an edge: Viscardy and Gaspard, PRE 68, 041204 (2003)); sampling the stress on a grid (the
// collisional part is a sum of impulses, not a function of the state).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/log.hpp"

namespace ede {

// The integral of V P_ab over the bins [from + k w, from + (k + 1) w), k = 0 .. bins - 1 (V = Lx Ly).
// In a Lees-Edwards log the kinetic part is taken relative to the shear flow (u_x = shear_rate y) and a
// pair across the sliding edge is separated through the sliding image.
struct StressIntegral {
  double from = 0, bin_width = 0, area = 0;
  double shear_rate = 0;  // the log's (0: not sheared)
  std::size_t disks = 0;
  std::vector<double> xx, yy, xy, yx;  // per bin: kinetic integral plus the bin's impulse terms
  std::vector<double> kinetic;         // per bin: the kinetic integral's trace, integral of sum m c^2 dt
  // The same over the whole grid, split into the kinetic integral and the impulse sum, in long double.
  long double kinetic_xx = 0, kinetic_yy = 0, kinetic_xy = 0;
  long double impulse_xx = 0, impulse_yy = 0, impulse_xy = 0, impulse_yx = 0;
  std::uint64_t pair_events = 0, step_events = 0, thermostat_events = 0;
  std::size_t bins() const { return xy.size(); }
};
// Fails for the logs this analysis refuses (above), naming the log and why.
Result<StressIntegral> stress_integral(const Log& log, double from, double bin_width, std::size_t bins);

struct ViscosityOptions {
  std::optional<double> from, to;  // the window; default: the whole log
  double lag_step = 0;             // > 0: the bin width, and lags dt, 2 dt, ... up to max_lag
  double max_lag = 0;              // >= lag_step, < to - from
  std::size_t blocks = 10;         // origins are split into this many contiguous blocks for the errors
};

struct ShearViscosity {
  std::vector<double> lag;               // lag_step, 2 lag_step, ..., max_lag
  std::vector<double> eta, error;        // Helfand eta(t), both components averaged; standard error over blocks
  std::vector<double> eta_xy, eta_normal;  // each component: symmetrised P_xy, and (P_xx - P_yy) / 2
  std::vector<double> acf;               // (V / kT) <P(0) P(t)> of the bin-averaged stress, both components
  std::vector<double> green_kubo, green_kubo_error;  // its running integral, trapezoidal on the bin grid
  // The estimate: the least-squares slope of the Helfand moment <dG^2> over the last half of the lags,
  // divided by 2 V kT (eta(t) itself approaches it only as 1/t: eta(t) = eta - (integral of t C(t)) / t);
  // error: the standard error of the blocks' slopes.
  double viscosity = 0, viscosity_error = 0;
  std::size_t disks = 0, bins = 0, origins = 0, blocks = 0;
  double bin_width = 0, area = 0;
  double kT = 0;        // the window's time average of K' / (N - 1) (centre-of-mass frame)
  double pressure = 0;  // (P_xx + P_yy) / 2 over the window
  double mean_shear_stress = 0, mean_shear_stress_error = 0;    // P_xy (0 in equilibrium)
  double mean_normal_stress = 0, mean_normal_stress_error = 0;  // (P_xx - P_yy) / 2 (0 in equilibrium)
  // Enskog's 2D viscosity at the window's kT, phi and Henderson's g(sigma) (kinetic_theory.hpp), and the
  // dilute one; NaN where they do not apply (say `enskog_note`: mixtures, square wells).
  double packing_fraction = 0, g_contact = 0;
  double enskog = 0, dilute = 0;
  std::string enskog_note;
};
Result<ShearViscosity> shear_viscosity(const Log& log, const ViscosityOptions& o);

// Shear viscosity from a sheared run (a Lees-Edwards log, in its steady state): eta = -<P_xy> / gamma,
// the mean shear stress over the window from the same exact stress integral (kinetic part relative to the
// flow u_x = gamma y, impulses through the sliding image). The steady state needs the viscous heating
// removed: by the thermostat about the flow, or by inelastic collisions (then it is a granular gas's
// viscosity, not comparable with Enskog's). The rate dependence (shear thinning) is taken out by
// zero_shear_viscosity over runs at several rates. Errors: contiguous blocks of the window (each much
// longer than the stress's correlation time, a few collision times), standard error of their means.
// Refused: logs that are not sheared (use shear_viscosity), without a scene (the rate is unknown), with
// rough disks or steps (which a Lees-Edwards box does not run).
struct ShearedOptions {
  std::optional<double> from, to;  // the window; default: the whole log (skip the start-up with `from`)
  std::size_t blocks = 10;         // >= 2
};
struct ShearedViscosity {
  double shear_rate = 0;
  double from = 0, to = 0, area = 0;
  std::size_t disks = 0, blocks = 0;
  std::uint64_t pair_events = 0, thermostat_events = 0;
  // Per block: mid-time, P_xy (symmetrised), kT relative to the flow, and eta = -P_xy / gamma.
  std::vector<double> block_time, block_shear_stress, block_kT, block_viscosity;
  double shear_stress = 0, shear_stress_error = 0;            // <P_xy> (< 0 under shear)
  double kinetic_shear_stress = 0, collisional_shear_stress = 0;  // its two parts over the window
  double normal_stress_difference = 0, normal_stress_difference_error = 0;  // <P_xx - P_yy>
  double pressure = 0;                                         // (P_xx + P_yy) / 2
  double kT = 0, kT_error = 0;  // sum m c^2 / (2 (N - 1)), time average (c relative to the flow and the mean)
  double viscosity = 0, viscosity_error = 0;  // -<P_xy> / gamma
  // Reduced by the disks' diameter sigma, mass m and the window's kT (equal disks only; else NaN):
  // gamma* = gamma sigma sqrt(m / kT), eta* = eta sigma / sqrt(m kT). Hard disks have no energy scale but
  // kT, so eta* depends on phi and gamma* alone: runs at different rates and temperatures compare in them.
  double sigma = 0, reduced_rate = 0, reduced_viscosity = 0, reduced_viscosity_error = 0;
  // Enskog's 2D viscosity at the window's kT, and reduced (NaN, and why in enskog_note, where it does not
  // apply).
  double packing_fraction = 0, g_contact = 0, enskog = 0, dilute = 0, enskog_reduced = 0;
  std::string enskog_note;
};
Result<ShearedViscosity> sheared_viscosity(const Log& log, const ShearedOptions& o = {});

// The zero-shear viscosity: a weighted least-squares fit eta* = eta0* + b gamma*^2 over runs at several
// rates (each point weighted by 1 / its error squared). The viscosity is even in gamma (reversing the
// shear is a reflection), so its expansion starts at gamma^2; in 2D the long-time tail adds a term in
// ln gamma, small at low and moderate density and not fitted (chi2 says when the form fails).
// Needs at least two runs of equal disks at one packing fraction (within 1e-9).
struct ZeroShearFit {
  std::size_t points = 0;
  double reduced_viscosity = 0, reduced_viscosity_error = 0;  // eta0* and its standard error
  double slope = 0, slope_error = 0;                           // b
  double chi2 = 0;                                             // of the fit, points - 2 degrees of freedom
  double packing_fraction = 0;
  double enskog_reduced = 0;  // Enskog's eta sigma / sqrt(m kT) at that phi (NaN where it does not apply)
};
Result<ZeroShearFit> zero_shear_viscosity(const std::vector<ShearedViscosity>& runs);

}  // namespace ede
