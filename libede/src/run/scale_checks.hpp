// Checks before a run that its lengths, speeds, masses, gravity and times fit the scalar type it computes
// in, so that the run is exact to that type's contract or refused before it starts (docs/reliability.md,
// "Extreme scales").
//
// The contract: positions are known to about eps (L + 2 V t), the resolution of a box of size L and of a
// clock at t for disks at speed V, and no two disks overlap by more than a small multiple of it. What
// breaks it silently is a number leaving the type's range inside the arithmetic: v^2 underflowing (the
// contact-time formula then sees no pair approaching, and disks pass through each other), a squared
// length overflowing (the formula gives NaN, read as "never"), times past the largest value (every event
// "never": "no more events" while disks move), or a clock so coarse that it no longer resolves the
// disks. Each check is one inequality between powers of two (log2 of the scales, so no check can itself
// overflow), for the run's type and for double (setup places the disks in double): the box and the
// smallest diameter squared, the products of the contact-time formula (dx.dv, dv.dv at the box's and the
// smallest disk's scale, down to the engine's own round-off floor on approach speeds), the time to cross
// the box and a smallest disk, the impulse of the heaviest pair, gravity, stop.time and the resolution at
// stop.time (at most 1/64 of the smallest diameter). A refusal names the quantity, the disks, and the fix:
// rescaling the units where the scale is absolute, and the narrowest wider type that holds every scale.
// Overflows the finite guard catches at once (an impulse past the range gives infinite velocities, exit 4)
// are left to it. What no check before the run can know (how far a stop.events run's clock goes) is
// caught at its end (run/overlap_scan.hpp).
// Rejected: bounds per type written out by hand (they would drift from the arithmetic they describe), and
// refusing every run whose inputs are subnormal or extreme one by one (a single slow disk among fast ones
// is fine: only the scales the arithmetic combines matter).
#pragma once

#include <string>

#include "core/initial_state.hpp"
#include "ede/error.hpp"
#include "ede/scene.hpp"

namespace ede {

// Before setup: the box and the radii the scene gives (or its packing fractions imply), in double (the
// type setup places disks in) and in the run's type.
Status check_scene_scales(const Scene& scene);

// After setup: every scale of the initial state and the scene, in double and in the run's type.
Status check_state_scales(const Scene& scene, const InitialState& initial);

// The largest share of the smallest diameter the position resolution eps (L + 2 V t) may reach: beyond
// it the run no longer resolves its disks (checked before the run at stop.time, after it at its end).
inline constexpr double kResolvedShareOfDiameter = 1.0 / 64;

// eps of a scalar type, 2^-(digits - 1), and its largest value as text ("3.4e+38").
double scalar_epsilon(ScalarKind kind);
std::string largest_value_text(ScalarKind kind);

}  // namespace ede
