// LogFrames: the states a picture shows, read from a log through the public API as DiskFrames (plain
// doubles: positions wrapped, speeds, displacements from the log's initial state).
//
// One ede::Log per LogFrames: its replay continues from the last state when the next time is later, so a
// movie's frames cost one pass over the events between them, and an earlier time costs one keyframe. The
// initial state (after 0 events) is kept for displacements and the initial mean speed; --species keeps the
// disks of one species. Times are read exactly in the log's scalar type (time_option.hpp). Rejected:
// templating the drawing on the log's scalar type (three copies of the cairo code) and converting the log
// to CSV first (ede-replay state) to draw from that (a movie would replay from a keyframe at every frame).
#pragma once

#include <string>

#include "ede/ede.hpp"
#include "time_option.hpp"

namespace ede::render {

// A DiskFrame plus |psi6_j| per drawn disk (ede::psi6 over the whole state, nearest six neighbours of every
// species, then the drawn species' entries), filled only when the colouring asks for it.
struct Frame : DiskFrame {
  std::vector<double> psi6;
};

class LogFrames {
 public:
  // `species`: "" for every disk, else the name of the species to draw.
  static Result<LogFrames> open(const std::string& path, const std::string& species);

  // A time typed after `option`: a number exact in the log's type, or `end`.
  Result<tools::TimeOption> read_time(const std::string& text, const std::string& option) const {
    return tools::read_time(log_, text, option);
  }
  // The frame at t, or at the log's end (complete or not).
  Result<Frame> at(const tools::TimeOption& t, bool with_psi6 = false);
  ScalarKind scalar() const { return log_.info().scalar; }
  std::string time_text(Time t) const { return exact_text(t, log_.info().scalar); }  // exact, in the log's type

 private:
  LogFrames(Log log, State initial, std::int32_t species)
      : log_(std::move(log)), initial_(std::move(initial)), species_(species) {}

  Log log_;
  State initial_;
  std::int32_t species_ = kAllSpecies;
  std::vector<std::array<double, 4>> segments_;  // the scene's wall segments, drawn on every frame
};

}  // namespace ede::render
