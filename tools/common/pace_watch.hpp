// A warning, a few seconds into a run, when the run will take very long: the first seconds are a pilot,
// and the progress fraction they reached (towards the nearest stop condition: time, events, collisions,
// energy) extrapolates to the whole run. Said once, with the estimate and what to change; the run goes on
// (Ctrl-C keeps everything done and can be resumed). Also when the run made no measurable progress at all
// (an energy stop that the collisions do not approach, samples far denser than events).
// Rejected: refusing on the estimate (a run's pace changes: a cooling gas slows down, a crater speeds up)
// and static bounds alone (the events to a stop time depend on the physics; the pilot measures them).
#pragma once

#include <cstdint>
#include <string>

namespace ede::tools {

class PaceWatch {
 public:
  PaceWatch(std::string tool, double pilot_seconds = 3.0, double warn_hours = 6.0)
      : tool_(std::move(tool)), pilot_seconds_(pilot_seconds), warn_hours_(warn_hours) {}
  // From the progress callback; prints the warning at most once.
  void update(double fraction, std::uint64_t events, double wall_seconds);

 private:
  std::string tool_;
  double pilot_seconds_, warn_hours_;
  bool done_ = false;
};

}  // namespace ede::tools
