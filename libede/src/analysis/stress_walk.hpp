// The walk behind stress_integral (ede/viscosity.hpp): the state at the window's start, then every event to
// its end (transport_stream's batches of columns), with a mirror of the velocities before each event and
// running sums of m v_a v_b and of the momentum, so each event costs O(1) whatever N. Rejected: the pressure
// pass's Replay over the internal reader (pressure_pass.cpp): the public columns carry every position and
// velocity the stress needs, and this walk already exists for the transport analyses.
#pragma once

#include "ede/error.hpp"
#include "ede/log.hpp"
#include "ede/viscosity.hpp"

namespace ede::stress {

// Why this log cannot give an equilibrium stress integral (empty when it can): the refusals of
// ede/viscosity.hpp, each with what to do instead.
std::string refusal(const Log& log);

// Why this Lees-Edwards log cannot give a stress integral relative to its flow (empty when it can).
std::string sheared_stress_refusal(const Log& log);

// The stress integral over `bins` bins of width `bin_width` from `from`, relative to the shear flow in a
// Lees-Edwards log; the caller has checked the log (refusal, or the sheared route's checks) and that
// from + bins * bin_width lies within it.
Result<StressIntegral> integrate(const Log& log, double from, double bin_width, std::size_t bins);

}  // namespace ede::stress
