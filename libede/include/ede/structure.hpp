// Structure of a hard-disk configuration from states (pure functions) and from a log (streaming: one
// State at a time, never every frame): the pair correlation g(r) per species pair, its contact value
// g(sigma) three ways, the static structure factor S(k) on the box's allowed wave vectors, and the local
// bond-orientational order psi6 with its global value and spatial correlation g6(r).
//
// Distances: minimum image in a periodic box (r_max <= min(Lx, Ly) / 2 is required), plain distances with
// walls. Normalisation of g(r) (every formula and its source in docs/analysis.md):
//   g_ab(r) = counts_ab(shell) / (N_a (N_b - delta_ab) / A^2 * integral over the shell of 2 pi r gamma(r) dr)
// with gamma(r) the set covariogram of the region the centres may occupy: gamma = A (periodic, A = Lx Ly);
// with walls the centres fill the rectangle (Lx - 2 r_mean) x (Ly - 2 r_mean) and, for r <= its shorter side,
// gamma(r) = A' - 2 r (Lx' + Ly') / pi + r^2 / pi (the isotropic covariogram of a rectangle), which counts
// exactly the pairs an ideal gas filling that rectangle would have: g -> 1 far from contact, no edge bias.
// Counts are of ordered pairs; frames are averaged by summing counts and normalisations.
// Rejected: normalising by the ideal-gas shell count n 2 pi r dr alone with walls, which reads low by the
// fraction of each shell outside the box (~ 4 r / (pi L)); and holding all frames to average afterwards.
#pragma once

#include <complex>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/log.hpp"
#include "ede/state.hpp"

namespace ede {

// The times a log analysis looks at: `frames` equally spaced times from `from` to `to` (both included;
// frames = 1: `from` alone). Defaults: the end of the log alone.
struct FrameTimes {
  std::optional<double> from, to;
  std::size_t frames = 1;
};
// The times themselves, within the log; fails for a time outside it or frames = 0.
Result<std::vector<double>> frame_times(const Log& log, const FrameTimes& f);

// ==== g(r) ===========================================================================================
struct PairCorrelationOptions {
  double r_max = 0;          // > 0; periodic: <= min(Lx, Ly) / 2
  std::size_t bins = 200;    // equal bins on [r_min, r_max)
  double r_min = 0;
  std::int32_t species_a = -1, species_b = -1;  // -1: every disk
};

struct PairCorrelation {
  std::vector<double> r_lo, r_hi, g;   // per bin
  std::vector<double> count;           // ordered pairs counted per bin (summed over frames)
  std::vector<double> ideal;           // the ideal-gas expectation of count (summed over frames)
  std::vector<double> g6;              // filled by psi6 analyses: Re <psi6_i psi6_j*> per pair in the bin
  std::size_t frames = 0;
  std::size_t n_a = 0, n_b = 0;        // disks of each species (the first frame's)
  double area = 0;                     // the region the centres occupy (A, or A' with walls)
  double density_b = 0;                // n_b = N_b / area
};

// Accumulates one state into `acc` (start with an empty PairCorrelation and the same options each time);
// finish_pair_correlation turns the sums into g. Fails on bad options.
Status add_pair_correlation(const State& s, const PairCorrelationOptions& o, PairCorrelation& acc);
void finish_pair_correlation(PairCorrelation& acc);
// One state.
Result<PairCorrelation> pair_correlation(const State& s, const PairCorrelationOptions& o);
// A log at the given frame times, one state in memory at a time.
Result<PairCorrelation> pair_correlation(const Log& log, const PairCorrelationOptions& o, const FrameTimes& f);

// ==== the contact value g(sigma) ======================================================================
struct ContactValue {
  double value = 0, error = 0;  // g(sigma) and its standard error
  std::string method;           // how it was obtained, in words
};
// g(sigma) by a weighted least-squares quadratic through the bins of g whose centres lie in
// [sigma, sigma + width], extrapolated to r = sigma; weights 1 / var, var = g^2 / count (Poisson counts).
// The error is the intercept's standard error (Poisson only: frames close in time are correlated, so it is
// a lower bound when frames are closer than a collision time); the fit's own bias, the cubic term's
// |g'''| width^3 / 120, is ~0.05 % at phi = 0.4 for width 0.1 sigma. Needs >= 4 such bins with counts.
Result<ContactValue> contact_from_gr(const PairCorrelation& g, double sigma, double width);
// Enskog's collision frequency per disk in 2D, omega = 2 n sigma g(sigma) sqrt(pi kT / m), solved for
// g(sigma) (one species, equal masses): g = omega / (2 n sigma sqrt(pi kT / m)). `collisions_per_disk_rate`
// = 2 * pair collisions / (N * time); its relative error is 1 / sqrt(pair collisions) (Poisson).
ContactValue contact_from_collision_rate(double collisions_per_disk_rate, std::uint64_t pair_collisions,
                                         double n, double sigma, double kT, double mass);
// The 2D virial equation of state Z = 1 + (pi / 2) n sigma^2 g(sigma) solved for g(sigma).
ContactValue contact_from_pressure(double z, double z_error, double n, double sigma);
// The three routes for a monodisperse periodic log over [from, to]: g(r) at `frames` times, the pair
// collision count in the window, the virial pressure (measure_pressure). Fails with walls or mixtures.
struct ContactValues {
  ContactValue from_gr, from_collisions, from_pressure;
  double sigma = 0, density = 0, kT = 0, mass = 0;
};
Result<ContactValues> contact_values(const Log& log, const FrameTimes& f, double fit_width_in_sigma = 0.1,
                                     std::size_t bins_in_fit = 8);

// ==== S(k) ===========================================================================================
// S(k) = |sum_j exp(-i k.r_j)|^2 / N at the box's allowed wave vectors k = 2 pi (p / Lx, q / Ly), integers
// p, q, with 0 < |k| <= k_max (one of each +-k pair: S(k) = S(-k)), and its average over shells of |k|.
struct StructureFactorOptions {
  double k_max = 0;           // > 0
  std::size_t shells = 100;   // equal shells on (0, k_max]
  std::int32_t species = -1;  // -1: every disk
};
struct StructureFactor {
  std::vector<double> kx, ky, s;        // every wave vector (averaged over frames)
  std::vector<double> k_lo, k_hi, s_shell;  // shell averages (NaN: no wave vector in the shell)
  std::vector<std::size_t> shell_vectors;
  std::size_t n = 0, frames = 0;
};
Status add_structure_factor(const State& s, const StructureFactorOptions& o, StructureFactor& acc);
void finish_structure_factor(StructureFactor& acc);
Result<StructureFactor> structure_factor(const State& s, const StructureFactorOptions& o);
Result<StructureFactor> structure_factor(const Log& log, const StructureFactorOptions& o, const FrameTimes& f);

// ==== psi6 ===========================================================================================
// psi6_j = (1/6) sum over j's six nearest neighbours k of exp(6 i theta_jk), theta_jk the angle of r_k - r_j
// (minimum image when periodic). Nearest six by centre distance, found with a cell grid (ties broken by
// id). Global order |<psi6>| = |(1/N) sum_j psi6_j|.
std::vector<std::complex<double>> psi6(const State& s);
struct BondOrder {
  std::vector<std::complex<double>> psi6;  // per disk (the last frame's)
  double global = 0;                       // |<psi6>| averaged over frames
  double mean_local = 0;                   // <|psi6_j|> averaged over frames
  PairCorrelation g6;                      // g(r) and g6(r) = Re <psi6_i psi6_j*> over pairs at r
};
// psi6 per disk, its global value and g6(r) (options as for g(r): species ignored, every disk).
Result<BondOrder> bond_order(const State& s, const PairCorrelationOptions& o);
Result<BondOrder> bond_order(const Log& log, const PairCorrelationOptions& o, const FrameTimes& f);

}  // namespace ede
