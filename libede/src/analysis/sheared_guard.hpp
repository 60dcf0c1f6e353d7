// The analyses that pair disks by the periodic nearest image or walk a log without following the sliding
// images (g(sigma) three ways, S(k), psi6, the pressure's virial, impact statistics) or unwrap displacements
// across the edges (MSD, VACF: transport_stream.cpp) refuse a Lees-Edwards log: across its sliding edges
// the image is shifted by the time's offset, and a plain image would give a silently wrong number for every
// pair or crossing there. g(r) follows the sliding image (State::shear_offset, structure_cells.hpp), and
// the stress integral and the viscosity the flow (their own checks: stress_walk.cpp).
// Rejected: handling the sliding image here (each analysis has its own pair walk; the offset would have to
// reach all of them): a refusal with the reason until an analysis is made to follow it.
#pragma once

#include <string>

#include "ede/log.hpp"

namespace ede {

// Empty for a log that is not sheared; else the message, naming the log and the analysis.
inline std::string sheared_refusal(const Log& log, const std::string& what) {
  if (!log.info().lees_edwards) return "";
  return log.info().path + ": " + what +
         ": the log is of a Lees-Edwards (sheared) box, whose images across the sliding edges this analysis "
         "does not follow yet (it would pair disks through the plain periodic image); it needs a walled or "
         "periodic run";
}

}  // namespace ede
