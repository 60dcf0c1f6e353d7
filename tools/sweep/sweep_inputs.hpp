// What a sweep checks about its inputs before and while it runs (docs/reliability.md, "Sweeps"):
//
// - every point's scene loads (base scene + the point's overrides, through the library exactly as a run's
//   child will load it), before any run starts: a bad value at one point (restitution 1.5) is refused at
//   once with every bad point listed, instead of failing run by run after the others have run;
// - the sweep file and its base scene stay what they were when the sweep started: a child compares their
//   digest with its parent's and refuses to run if they changed (its run number K would name another run
//   of an edited sweep), and a finished run is reused only if its log holds the scene the run would load
//   now (an edited base scene makes every row of the old one stale);
// - one ede-sweep at a time writes a results folder (an exclusive flock on RESULTS/.ede-sweep.lock, held by
//   the process that hands out the runs): a second one into the same folder would run the same runs and
//   overwrite the first one's rows and tables.
// Rejected: copying the sweep file and the scene into the results folder for the children (the children
// would then run what the parent planned, but a rerun after an edit would silently mix the two) and a
// lock file without flock (a killed sweep's file would block every later one until deleted by hand).
#pragma once

#include <memory>
#include <string>

#include "sweep.hpp"

namespace ede::sweep {

// Every point's scene loads; else one message naming each bad point (the first few) and the fix.
Status check_points(const Sweep& s);

// A digest of the sweep file's and the base scene's bytes (FNV-1a, hex): equal while neither changed.
std::string inputs_digest(const SweepSpec& spec);

// The scene run r loads (base scene + its overrides).
Result<Scene> scene_of(const Sweep& s, const PlannedRun& r);

// The results folder's lock, held while the object lives (the folder must exist).
class ResultsLock {
 public:
  static Result<std::unique_ptr<ResultsLock>> take(const std::string& folder);
  ~ResultsLock();
  ResultsLock(const ResultsLock&) = delete;
  ResultsLock& operator=(const ResultsLock&) = delete;

 private:
  explicit ResultsLock(int fd) : fd_(fd) {}
  int fd_;
};

}  // namespace ede::sweep
