// stall_text: what the engine says when time stops advancing (RunStatus::Stalled), naming the cause that
// applies to the run at hand. Engine::check_stops gathers the facts and calls it; stall_message() returns it.
//
// Two causes, told apart by the run's physics: in a run with inelastic collisions, inelastic collapse
// (disks in a cluster, or settling under gravity, colliding ever faster; the remedy is the TC model); in
// an elastic run there is no collapse, and time stalls because the events come closer together than the
// clock resolves at its current value (eps t: a float run under strong gravity, where a disk bouncing low
// on the floor hits it every 2 v / g, below that step), so the remedy is a wider type or other units.
// Rejected: one message for both (it sent elastic runs to the TC model, which changes nothing for them),
// and building the text inside the event loop's class (the loop's file is long enough; this is words).
#pragma once

#include <cstdint>
#include <sstream>
#include <string>

namespace ede {

struct StallFacts {
  double time = 0;                  // when time stopped
  std::uint64_t same_time_events = 0;
  bool elastic = true;              // no restitution below 1 anywhere
  bool gravity = false;
  bool tc_model = false;
  double tc = 0;
  const char* scalar = "double";    // the engine's scalar type, as a scene names it
  double epsilon = 0;               // its eps
};

inline std::string stall_text(const StallFacts& f) {
  std::ostringstream m;
  m << "the simulation stalled at t = " << f.time << ": " << f.same_time_events
    << " consecutive events without time advancing";
  if (f.elastic) {
    m << ". This is not inelastic collapse (every collision of this run is elastic): the events come closer "
         "together than the clock can tell apart, and with engine.scalar = \""
      << f.scalar << "\" the clock at t = " << f.time << " moves in steps of about " << f.epsilon * f.time << ". ";
    if (f.gravity)
      m << "Under gravity a disk bouncing low on the floor or on another disk hits it every 2 v / g, which the "
           "scale of gravity against the speeds and the box can put below that step. ";
    m << "Fix: use a wider scalar type (engine.scalar = \"double\" or \"long double\")"
      << (f.gravity ? ", or make gravity weaker against the speeds and the box (g L / v^2 nearer 1)" : "")
      << ", or stop earlier.";
    return m.str();
  }
  m << " (inelastic collapse). ";
  if (f.gravity)
    m << "Under gravity, disks settling on the floor or on each other bounce ever lower and ever faster: "
         "resting contact is not a state an event-driven run can reach. ";
  if (f.tc_model)
    m << "Increase physics.tc (now " << f.tc << ")"
      << (f.gravity ? " so that settled disks keep hopping elastically at a height of about g tc^2 / 8, and keep "
                      "wall_restitution above 0."
                    : ".");
  else
    m << "Enable the TC model (physics.tc > 0, e.g. 1e-3 of the mean free time) or raise the restitution.";
  return m.str();
}

}  // namespace ede
