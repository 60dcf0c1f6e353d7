// Why a run stopped (or that it has not).
#pragma once

namespace ede {

enum class RunStatus {
  Running,            // run() returned because its event budget was used; call it again
  ReachedTime,        // stop.time reached (the state is reported at exactly that time)
  ReachedEvents,      // stop.events processed
  ReachedCollisions,  // stop.collisions_per_particle reached
  ReachedEnergy,      // kinetic energy fell to stop.energy_fraction of the initial
  NoMoreEvents,       // nothing will ever happen again (every disk at rest, or moving freely forever)
  Stalled,            // time stopped advancing: inelastic collapse; see stall_message()
  CameToRest,         // an inelastic run cooled below the speeds T resolves; see stall_message()
};
const char* to_string(RunStatus);
bool is_finished(RunStatus);

}  // namespace ede
