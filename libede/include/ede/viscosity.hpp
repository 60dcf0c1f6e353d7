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
// Made to be reused for a sheared (Lees-Edwards) box: the kinetic part is taken relative to a streaming
// velocity and the separation through one image-aware function (analysis/stress_walk.cpp), the two places
// a sliding boundary changes.
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
struct StressIntegral {
  double from = 0, bin_width = 0, area = 0;
  std::size_t disks = 0;
  std::vector<double> xx, yy, xy, yx;  // per bin: kinetic integral plus the bin's impulse terms
  // The same over the whole grid, split into the kinetic integral and the impulse sum, in long double.
  long double kinetic_xx = 0, kinetic_yy = 0, kinetic_xy = 0;
  long double impulse_xx = 0, impulse_yy = 0, impulse_xy = 0, impulse_yx = 0;
  std::uint64_t pair_events = 0, step_events = 0;
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

}  // namespace ede
