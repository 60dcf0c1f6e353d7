// What the analysis commands report, one call each, returning plain structs: the tools print them, and
// the Python module and the live view read the same fields. Each walks or seeks the log through the
// functions of ede/log_series.hpp. Times are doubles within the log, as for log_series; a species is an index into the
// log's species names (species_index), or kAllSpecies.
// Rejected: leaving these compositions in the tools, where every front end would write them again and no
// test could reach them without running a program.
// (One part of ede/analysis.hpp, which includes them all.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ede/distributions.hpp"
#include "ede/error.hpp"
#include "ede/gas_observables.hpp"
#include "ede/kinetic_theory.hpp"
#include "ede/log.hpp"
#include "ede/log_series.hpp"

namespace ede {

// The index of the species called `name`; "" means every disk (kAllSpecies). The error lists the species.
Result<std::int32_t> species_index(const LogInfo& info, const std::string& name);

// The speeds or kinetic energies of the selected disks at the given times (pooled: each time adds its
// disks again), against 2D Maxwell-Boltzmann at the temperature of the sample itself, kT = <m v^2 / 2>,
// with the initial state (t = 0) in the same bins beside it. The KS test runs on kinetic energies
// (exponential with mean kT for any mix of masses). The bins are `bins` equal bins from 0 to the largest
// value of the sample or of the initial state (to 1 if both are 0). kT is fitted from the same sample,
// which makes p somewhat too large; pooled times closer than a few mean free times see nearly the same
// disks, and p is then approximate.
struct DistributionRequest {
  std::vector<double> times;       // one time, or several to pool (non-decreasing, within the log)
  std::int32_t species = kAllSpecies;
  Quantity quantity = Quantity::Speed;
  std::size_t bins = 40;           // at least 1
  std::size_t curve_points = 400;  // intervals of the law's curve for figures
};

struct DistributionReport {
  std::size_t disks = 0;                         // selected disks at one time
  std::size_t samples = 0;                       // values in the histogram: disks x times
  double kT = 0;                                 // of the sample
  KsResult ks;                                   // the sample's energies against exp(-E/kT) / kT
  double initial_kT = 0;                         // of the selected disks at t = 0 (0: at rest, no test)
  KsResult initial_ks;                           // against the law at initial_kT
  MaxwellBoltzmann law;                          // at kT, for the selection's masses
  Histogram histogram, initial;                  // the same bins
  std::vector<double> density, initial_density;  // densities() of the two
  std::vector<double> law_density;               // law.bin_density per bin: what each bin should show
  std::vector<double> curve_x, curve_density;    // the law at curve_points + 1 points from 0 to the last edge
};

// Fails if a time is outside the log, bins is 0, or the selected disks are at rest (kT = 0).
Result<DistributionReport> measure_distribution(const Log& log, const DistributionRequest& request);

// species_stats at each time (one snapshot each): every species, then "all"; or one species alone.
struct SpeciesTable {
  double time = 0;
  std::vector<SpeciesStats> rows;
};
Result<std::vector<SpeciesTable>> species_tables(const Log& log, const std::vector<double>& times,
                                                 std::int32_t species = kAllSpecies);

// The kinetic energy (total and per species) on a grid, with Haff's law for an inelastic run.
//
// The grid runs from `from` to `to` (default: the whole log), both included: every `every` (default 1/20
// of the whole run's mean free time, N t_end / 2 pairs, or 1/1000 of the range without collisions), or at
// `points` evenly spaced times. E(0) is always the energy at t = 0, whatever the range.
// Haff's law for a homogeneous cooling gas of equal disks (2D): each collision loses on average
// (1 - xi^2) kT (the collision-weighted mean of (g.n)^2 is 4 kT / m for Maxwell-Boltzmann velocities), so
// dT/dt = -(1 - xi^2) omega T / 2 with the collision frequency omega proportional to sqrt(T):
//   E(t) / E(0) = (1 + t / tau)^-2,  tau = 4 / ((1 - xi^2) omega0),
// and the collisions per disk grow as C(t) = omega0 tau ln(1 + t / tau). The first grid time t1 > 0 at
// which the log reaches C1 = 2 collisions per disk (about 2N collisions: a 2% statistical error; the last
// grid time if it never does) gives omega0 exactly within the model, with no fitted curve:
//   omega0 = 4 (exp((1 - xi^2) C1 / 4) - 1) / ((1 - xi^2) t1).
struct EnergyCurveRequest {
  std::optional<double> from, to;     // the range (default: 0 and the end of the log)
  std::optional<double> every;        // the spacing (> 0)
  std::optional<std::size_t> points;  // instead of every: this many points (2 at least; fewer count as 2)
  std::size_t max_points = 5'000'000;
};

struct EnergyCurve {
  LogSeries series;                                         // on the grid
  double restitution = std::numeric_limits<double>::quiet_NaN();  // xi of the log's scene; NaN if unreadable
  double spacing = 0;                                       // the grid's spacing (0 with points)
  bool default_spacing = false;                             // chosen by the rule above
  double mean_free_time = 0;                                // of the whole run
  double initial_energy = 0;                                // E(0)
  double haff_tau = std::numeric_limits<double>::quiet_NaN();  // calibrated on C1 (a check); NaN if elastic
  double haff_calibration = 0;                              // C1: the collisions per disk omega0 came from
  // Haff's tau from Enskog's collision rate at t = 0 (ede/kinetic_theory.hpp), computed before looking at
  // the curve, with its stated uncertainty; NaN if elastic or not applicable (a mixture: see enskog_note).
  // haff_ratio uses it when it is finite, else haff_tau.
  double enskog_tau = std::numeric_limits<double>::quiet_NaN();
  double enskog_tau_error = std::numeric_limits<double>::quiet_NaN();
  double enskog_rate0 = std::numeric_limits<double>::quiet_NaN();  // omega_E(0) per disk
  std::string enskog_note;                                  // why there is no enskog_tau

  double ratio(std::size_t k) const;       // E(t_k) / E(0); NaN if E(0) = 0
  double haff_ratio(std::size_t k) const;  // (1 + t_k / tau)^-2 (tau: enskog_tau, else haff_tau); NaN without
  double max_drift() const;                // max over the grid of |E / E(0) - 1| (0 if E(0) = 0)
};

// Fails on a range outside the log, a spacing <= 0, or a grid of more than max_points points.
Result<EnergyCurve> energy_curve(const Log& log, const EnergyCurveRequest& request = {});

// Collisions over time: the counts of log_series; per interval since the time before, the pair collision
// rate per disk, 2 (pairs(t_k) - pairs(t_k-1)) / (N (t_k - t_k-1)), and the mean free time 1 / rate
// (infinity for a rate of 0), both NaN at the first time and after an empty interval; and the speed
// classes at each time against the mean speed at the first time (the initial one when the times start at
// 0). Wall collisions are counted apart and take no part in the rate (kinetic theory's mean free time is
// the time between collisions with other disks).
struct CollisionSeries {
  LogSeries series;
  double reference_speed = 0;
  std::vector<SpeedClasses> classes;
  std::vector<double> rate, mean_free_time;
  // Enskog's rate per disk for each interval (the mean of omega_E at its ends; NaN where rate is, or for
  // a mixture) and the reference at the first time (ede/kinetic_theory.hpp).
  std::vector<double> enskog_rate;
  EnskogReference enskog;
};
Result<CollisionSeries> collision_series(const Log& log, const std::vector<double>& times);

}  // namespace ede
