// Progress of a run for people watching it: a bar redrawn in place on a terminal, plain lines every few
// seconds otherwise (logs, CI). Written to stderr so stdout stays clean for --json.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>


namespace ede::tools {

class ProgressReporter {
 public:
  ProgressReporter(bool enabled, std::string label);
  // Called between slices of the run; draws at most a few times a second.
  void update(double fraction, std::uint64_t events, double sim_time);
  void finish();

 private:
  bool enabled_;
  bool terminal_;
  std::string label_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool drawn_ = false;
};

}  // namespace ede::tools
