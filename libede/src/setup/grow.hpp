// Lubachevsky-Stillinger growth: dense disordered disks from sparse ones, by an event-driven run of their own.
//
// The disks start where placement put them (radii rho_i, packing fraction phi_0) and every radius grows as
// rho_i a(t), a(t) = 1 + adot t, while they move: pair contact when |dr + dv tau| = s + g tau with
// s = (rho_i + rho_j) a, g = (rho_i + rho_j) adot (grow_predict.hpp), walls likewise. A collision reflects the
// gap's rate of change, so the normal relative speed becomes 2 g - u_n > g and the pair separates; that feeds
// kinetic energy in, which a velocity rescale to kT = 1 takes out every N pair collisions. The reduced
// pressure Z = PA/(NkT) is measured over each of those intervals from the collision virial. The run stops
// at the target packing fraction (radii then set exactly to it) or when Z exceeds the pressure bound
// (jamming). Unit masses: the positions a hard-disk fluid visits do not depend on the masses, and the
// species' own masses and velocities are given to the grown positions afterwards (setup.cpp).
// It is its own small loop (one event per disk in an indexed heap, cells, counters against stale pair
// events) rather than the engine's: the engine is a room above setup, its hot loop would need a growth
// policy that every other scene would carry, and its log must not change. Rejected: reusing the engine
// with shrinking box sizes (the box is the scene's and the log's), and a thermostat drawing fresh velocities
// (needs normal deviates through libm's log, whose last bit differs between systems; a rescale does not).
// Deterministic: double arithmetic in a fixed order, ties broken by disk id, velocities from ede::Rng.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::setup_detail {

struct GrowInput {
  double lx = 1, ly = 1;
  bool periodic = false;
  std::vector<double> x, y, r;  // the placed disks: centres and radii at the start (no overlaps)
  double target_phi = 0;        // 0: none (grow until jammed)
  double pressure = 0;          // stop when Z exceeds it; 0: none
  double rate = 1e-3;           // d(mean diameter)/dt over the thermal speed (kT = m = 1)
  std::uint64_t seed = 1;
};

struct GrowResult {
  std::vector<double> x, y, r;  // the grown disks, in the input's order
  double phi_start = 0, phi = 0;
  double z = 0;                 // reduced pressure over the last measuring interval (0 when none ended)
  bool jammed = false;          // stopped on the pressure bound
  std::uint64_t collisions = 0, events = 0;
  double seconds = 0;           // wall-clock time of the growth (not part of the result's bytes)
};

// Fails (with a message for the scene's author, without a file name) when the box is too small for the
// disks' cell grid, or when the target is not reached because the disks jam first (Z above the pressure
// bound, 10^6 when none is given).
Result<GrowResult> grow_disks(const GrowInput& in);

// The packing fraction at which growth starts: low enough for random placement, min(0.35, target / 2).
double grow_start_phi(double target_phi);

}  // namespace ede::setup_detail
