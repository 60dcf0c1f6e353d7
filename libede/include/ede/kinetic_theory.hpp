// Reference laws of kinetic theory for hard disks, and their values for a log: the temperature in the
// centre-of-mass frame, the contact value g(sigma), the Enskog collision rate, Haff's cooling time from it,
// and time averages per species.
//
// Conventions (2D, k = 1). Temperature: kT = K' / f with f quadratic-degree-of-freedom pairs: in a periodic
// box the total momentum P is conserved and carries no heat, so K' = K - P^2 / (2M) (the kinetic energy in
// the centre-of-mass frame) over N - 1 disks' worth of degrees of freedom, 2(N - 1) quadratic ones of kT/2
// each: kT = K' / (N - 1). In a walled box the walls exchange momentum, the box is the rest frame and
// kT = K / N. Density: n = N / A, A = Lx Ly, phi = sum pi r^2 / A (the bulk; walls change the rate near
// them by O(sigma / L)). Contact value: Henderson's g(sigma) = (1 - 7 phi / 16) / (1 - phi)^2, the value
// that makes Z = 1 + 2 phi g(sigma) his equation of state (ede/pressure.hpp henderson_z). Kolafa and
// Rottner's equation of state (below) is the accurate one for the dense fluid.
// Enskog's collision rate per disk: omega_E = 2 n sigma g(sigma) sqrt(pi kT / m), exact in equilibrium given
// the exact g(sigma) (velocities are Maxwellian and independent of positions), so its error is g's:
// Henderson's is within ~1% of simulations for phi <= 0.5. Equal disks only: a mixture needs g_ij per pair
// of species, and the functions of a log say "not applicable" for one.
// Haff's law E(t)/E(0) = (1 + t/tau)^-2 with tau = 4 / ((1 - xi^2) omega_E(0)), omega_E at the start: not
// fitted. Its stated relative uncertainty, kHaffTauRelativeUncertainty = 10%: measured, the cooling is
// slower than this tau says by 6-8% (xi = 0.9, phi = 0.2, N = 2000, three seeds, at every t up to 2 tau):
// a start of one speed for every disk dissipates 11% less per collision than Maxwell's distribution until
// a few collisions mix it, and the homogeneous cooling state's velocity correlations and non-Gaussian
// tail lower the dissipation further; g(sigma) adds ~1%. tests/analysis/test_kinetic_theory.cpp checks it.
// Rejected: fitting tau or omega to the curve (the answer would depend on the range; a reference law must
// be computed before looking at the data it is compared with).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/log.hpp"
#include "ede/state.hpp"

namespace ede {

inline constexpr double kHaffTauRelativeUncertainty = 0.10;

// g(sigma) of the hard-disk fluid from Henderson's equation of state.
double henderson_contact_value(double phi);
// Kolafa and Rottner's equation of state of the hard-disk fluid (J. Kolafa and M. Rottner, "Simulation-based
// equation of state of the hard disk fluid and prediction of higher-order virial coefficients", Mol. Phys.
// 104, 3435 (2006), arXiv:cond-mat/0608356), their fit with rho* = N sigma^2 / A up to 0.90:
// Z = sum_k C_k x^k, x = phi / (1 - phi), k = 0..12, 22 and 57 (kolafa_rottner.cpp lists the C_k and
// where they were taken from). Built from MD pressures up to the hexatic transition and the known virial
// coefficients B2..B10: its expansion in phi gives B3/B2^2 = 4/3 - sqrt(3)/pi and B4/B2^3 = 2 - 9 sqrt(3) /
// (2 pi) + 10/pi^2 exactly (to the C_k's nine digits) and B5..B10 within the errors of Clisby and McCoy
// (J. Stat. Phys. 122, 15 (2006)); tests/analysis/test_kolafa_rottner.cpp checks all of them. Valid for the
// fluid, phi <= kKolafaRottnerPhiMax = pi 0.90 / 4 = 0.7069 (the last interval, phi 0.699-0.707, may hold
// finite-size effects, say the authors); above it the x^57 term takes over and the functions return NaN.
// Henderson's Z is 0.5% above it at phi = 0.5, 1.2% at 0.6, 2.2% at 0.65 and 13% at 0.70.
inline constexpr double kKolafaRottnerPhiMax = 0.70685834705770345;  // pi * 0.90 / 4
double kolafa_rottner_z(double phi);
// g(sigma) = (Z - 1) / (2 phi) from the virial theorem of equal hard disks, Z = 1 + 2 phi g(sigma).
double kolafa_rottner_contact_value(double phi);
// omega_E = 2 n sigma g sqrt(pi kT / m) per disk.
double enskog_collision_rate(double number_density, double sigma, double g_contact, double kT, double mass);
// Enskog's self-diffusion coefficient of hard disks (first Sonine approximation; Gass, J. Chem. Phys. 54,
// 1898 (1971)): D_E = (1 / (2 n sigma g(sigma))) sqrt(kT / (pi m)) = kT / (m omega_E).
double enskog_diffusion(double number_density, double sigma, double g_contact, double kT, double mass);
// Shear viscosity of hard disks (docs/kinetic-theory.md, "Shear viscosity", derives and checks both).
// Dilute (Boltzmann, Chapman-Enskog): eta_0 = s (1 / (2 sigma)) sqrt(m kT / pi), where s = 1 is the first
// Sonine approximation (Gass, J. Chem. Phys. 54, 1898 (1971)) and the series converges to
// s = kViscositySonineFactor = 1.0220 (2nd approximation 1.0200, 7th 1.021969: scripts/sonine_viscosity.py
// computes the bracket integrals of the 2D collision operator and reproduces both).
inline constexpr double kViscositySonineFactor = 1.0220;
double dilute_viscosity(double sigma, double kT, double mass, double sonine = kViscositySonineFactor);
// Enskog's dense-fluid viscosity of hard disks with chi = g(sigma):
//   eta_E = eta_0^(1) [ s (1 + phi chi)^2 / chi + (8 / pi) phi^2 chi ]
//         = eta_0^(1) [ 1/chi + 2 phi + (1 + 8/pi) phi^2 chi ]   (s = 1, Gass's first Sonine form);
// the Sonine factor corrects the kinetic (streaming and collisional-transfer) part, not the last term,
// which comes from the local-equilibrium part of the collision transfer (the 3D analogue: Chapman and
// Cowling's 1.016 (1/chi)(1 + 0.4 b n chi)^2 + 0.7614 (b n)^2 chi in units of the corrected eta_0).
double enskog_viscosity(double phi, double sigma, double g_contact, double kT, double mass,
                        double sonine = kViscositySonineFactor);
// tau = 4 / ((1 - xi^2) omega0); infinity for xi = 1.
double haff_tau(double restitution, double omega0);

struct Temperature {
  double kinetic = 0;     // K = sum m v^2 / 2
  double kinetic_cm = 0;  // K - P^2 / 2M (periodic), K (walls)
  double px = 0, py = 0;  // total momentum
  double degrees = 0;     // N - 1 (periodic) or N (walls): kT = kinetic_cm / degrees
  double kT = 0;
};
Temperature temperature_of(const State& s);

// The Enskog reference of one state.
struct EnskogReference {
  bool applicable = false;     // equal radii and masses
  std::string why_not;         // when not
  double number_density = 0;   // N / (Lx Ly)
  double packing_fraction = 0;
  double sigma = 0, mass = 0;  // diameter and mass of the disks
  double g_contact = 0;        // Henderson
  Temperature temperature;
  double rate = 0;             // omega_E per disk
};
EnskogReference enskog_reference(const State& s);

// The log's state at t through enskog_reference.
Result<EnskogReference> enskog_at(const Log& log, double t);

// Per species, the time average of the mean kinetic energy per disk <m v^2 / 2> over [from, to] on an
// evenly spaced grid of `points` times (log_series: one walk of the events), with the standard error of the
// mean over `blocks` equal blocks of the grid (correlations within a block are absorbed; blocks shorter than
// the energy's correlation time make the error too small). Last row: every disk ("all").
struct SpeciesTimeAverage {
  std::string name;
  std::uint64_t n = 0;
  double mean_kinetic_energy = 0, error = 0;  // per disk, = kT of the species by equipartition
};
Result<std::vector<SpeciesTimeAverage>> species_time_averages(const Log& log, double from, double to,
                                                              std::size_t points = 2000, std::size_t blocks = 20);

}  // namespace ede
