// Transport from the event log, exactly: mean-square displacement with unwrapped periodic coordinates,
// the self-diffusion coefficient with an error, and the velocity autocorrelation function (VACF), all in
// one streaming pass over the events (bounded memory: a few positions per disk, a window of velocity
// segments), never sampling velocities or positions in between.
//
// Unwrapping is exact: a wrap event says which edge a disk crossed, so each disk keeps an image count and
// its unwrapped position at t is x_e + images * L + v (t - t_e), with x_e, v, t_e the position, velocity and
// time of its last event (as logged: no error accumulates over events). Velocities are piecewise constant
// between a disk's events (no gravity), so C(tau) = (1 / (N (T - tau))) sum_i integral over t0 in
// [t_a, t_b - tau] of v_i(t0) . v_i(t0 + tau) is a finite sum of overlaps of constant segments, computed
// exactly at each lag of the grid. Formulas and sources: docs/analysis.md.
// Rejected: sampling states on a time grid and unwrapping by minimum-image jumps between samples (wrong
// when a disk moves more than L/2 between samples; the VACF from samples has a sampling error).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "ede/error.hpp"
#include "ede/log.hpp"

namespace ede {

struct TransportOptions {
  std::optional<double> from, to;  // the window; default: the whole log
  double lag_step = 0;             // > 0: lags 0, dt, 2 dt, ... up to max_lag
  double max_lag = 0;              // > 0, < to - from
  std::size_t origins = 0;         // MSD: time origins, equally spaced in [from, to - max_lag]; 0: 20
  std::int32_t species = -1;       // -1: every disk
  std::size_t groups = 10;         // disks are split into this many groups (by id modulo) for errors
};

struct MeanSquareDisplacement {
  std::vector<double> lag, msd;  // msd[k] = < |r(t0 + lag_k) - r(t0)|^2 >, over disks and origins
  std::vector<double> error;     // standard error over the groups of disks
  std::size_t disks = 0, origins = 0;
  // Diffusion: D from the least-squares slope of msd = 4 D lag + c over the lags in the last half of the
  // range; error: the standard error of D over the groups of disks.
  double diffusion = 0, diffusion_error = 0;
};
Result<MeanSquareDisplacement> mean_square_displacement(const Log& log, const TransportOptions& o);

struct VelocityAutocorrelation {
  std::vector<double> lag, c;  // c[k] = < v(t0) . v(t0 + lag_k) >, exact time average over t0 and disks
  std::vector<double> error;   // standard error over the groups of disks
  std::size_t disks = 0;
  // Green-Kubo: D(t) = (1/2) integral_0^t C (trapezoidal on the lag grid); the last value.
  std::vector<double> green_kubo;
};
Result<VelocityAutocorrelation> velocity_autocorrelation(const Log& log, const TransportOptions& o);

// Enskog's self-diffusion coefficient and Henderson's contact value: ede/kinetic_theory.hpp.

}  // namespace ede
