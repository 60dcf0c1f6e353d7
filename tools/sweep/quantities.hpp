// The quantities a sweep collects per run, by name (docs/sweeps.md): the run summary's fields, and
// ede-stats / ede-crater quantities at given times, computed from the run's log with the library's
// analysis functions, so a quantity is the same number the tool prints for that log.
//
//   summary: events, pair_collisions, wall_collisions, collisions_per_particle, sim_time, energy_initial,
//            energy_final, energy_ratio
//   energy@T (mean kinetic energy per disk at T), collisions@T (collisions per particle up to T)
//   crater.METRIC or crater.METRIC@T (ede-crater's metrics: depth, width, area, ...; default time: when
//            10% of the energy is left, as ede-crater measures)
//   pressure.NAME (z_virial, z_wall, virial, wall, kT, packing_fraction, and z_henderson, z_kolafa_rottner:
//            those equations' Z at the run's packing fraction, the latter NaN above its range phi 0.707;
//            NAME_error the standard error over the blocks, ede-stats pressure's)
//   structure.psi6 or structure.psi6@T (the global bond order |<psi6_j>| of ede-stats psi6 at T, default: the
//            log's end)
//   viscosity.NAME[_error] or viscosity.NAME[_error]@T0 (a sheared run: sheared_viscosity from T0, default
//            the log's start, as ede-stats viscosity --from T0: eta, eta_reduced, rate_reduced, kT,
//            shear_stress, enskog, enskog_reduced, packing_fraction; _error for eta, eta_reduced, kT and
//            shear_stress, 0 for the rest)
// Names are checked before any run starts. Rejected: a plug-in list of quantity objects (the names map to
// a handful of library calls; a table of functions per name would be longer than the switch).
#pragma once

#include <string>
#include <vector>

#include "ede/ede.hpp"

namespace ede::sweep {

// Fails naming the first unknown quantity and the known ones.
Status check_quantities(const std::vector<std::string>& names);

// One value per name (NaN where a quantity has no value, e.g. no crater); fails on a log the analyses
// cannot read.
Result<std::vector<double>> collect_quantities(const std::vector<std::string>& names, const RunSummary& summary,
                                               const Log& log);

}  // namespace ede::sweep
