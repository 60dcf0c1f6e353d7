// LogStates: the states a picture shows, read from a log by replay, as plain doubles (a Frame).
//
// A log holds float, double or long double; a picture needs doubles. LogStates hides the scalar type
// behind a small interface chosen once per log (open), so the drawing, colouring and movie code is written
// once, not instantiated three times. Times cross the interface as long double, which holds every float,
// double and long double exactly; they are parsed in the log's own type (like ede-replay: `--at 0.1` in a
// float log is the float nearest 0.1) and converted back without loss. One Replay per LogStates, used
// forward: a movie's frames cost one pass over the log's events, not one seek per frame from a keyframe.
// The initial state (the log's first keyframe) is kept for displacements and the initial mean speed.
// Rejected: templating every file on T (three copies of the cairo code) and converting the log to CSV first
// (ede-replay state) and drawing from that (a movie would replay from the nearest keyframe at every frame).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::render {

// A state as drawn: positions at `time` (periodic: wrapped into the box), per disk.
struct Frame {
  double time = 0;
  double lx = 1, ly = 1;
  bool periodic = false;
  std::vector<std::string> species_names;
  std::vector<double> x, y, r, speed;
  std::vector<double> displacement;  // from the initial state (periodic: the nearest image's distance)
  std::vector<int> species;
  double initial_mean_speed = 0;     // v̄0: the mean speed of the log's initial state

  std::size_t size() const { return x.size(); }
};

// A time on the command line: a number or "end".
struct TimePoint {
  long double t = 0;  // exactly a value of the log's scalar type
  bool end = false;   // the end of the log (an incomplete log: after its last event)
};

class LogStates {
 public:
  static Result<std::unique_ptr<LogStates>> open(const std::string& path);
  virtual ~LogStates() = default;

  // `text` is a finite number >= 0 read in the log's type, or "end"; after the end of the log is refused.
  virtual Result<TimePoint> parse_time(const std::string& text, const char* what) const = 0;
  // The time `fraction` (in [0, 1]) of the way from a to b, rounded to the log's type, within [a, b].
  virtual TimePoint between(const TimePoint& a, const TimePoint& b, long double fraction) const = 0;
  // Moves to a time; a movie calls it with increasing times (forward seeks continue where they are).
  virtual Status seek(const TimePoint& t) = 0;
  virtual Frame frame() const = 0;
  virtual std::string time_text(long double t) const = 0;  // exact, in the log's type
};

}  // namespace ede::render
