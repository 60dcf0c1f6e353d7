// The crater view of a log: for a crater scene (a bed of disks and a projectile), each frame can carry the
// bed's surface profile at its time against the one at the log's start, with the crater's depth, width and
// area, computed by the library's crater analysis (ede/crater.hpp: select_bed, analyze_crater with its
// default settings), so the page shows exactly what `ede-crater measure LOG --at T` prints and writes.
// A log is a crater scene when it has a species named "bed", or a species of one disk (a projectile)
// beside the bed ede-crater would choose. Rejected: computing the profiles in the page (a second
// implementation of the surface rule to keep in step) and measure_crater per frame (it replays the log
// from its start for the energy curve: seconds per frame on a long log, where this costs one pass).
#pragma once

#include <optional>
#include <string>

#include "ede/crater.hpp"
#include "ede/ede.hpp"

namespace ede::view {

// What every crater frame of one log shares: the bed, the state it is compared with, the box.
struct CraterBase {
  BedSelection bed;
  DiskPositions before;  // the log's start, or the state at the time asked for (with_before)
  double before_time = 0;
  CraterBox box;
};

// The crater base of a log, or nothing when the log is not a crater scene (or cannot be read).
std::optional<CraterBase> crater_base(const Log& log);

// The same base compared with the state at `before` instead (ede-crater --before: under gravity, the bed
// once it has settled, before the impact); fails with the log's message for a time past its end.
Result<CraterBase> with_before(const CraterBase& base, const Log& log, Time before);

// ,"crater":{...} for FrameExtras::json_fields: the profiles (bin width, heights before and after), the
// metrics and how many bed disks moved; or ,"crater":{"error":...} when the analysis fails.
std::string crater_field(const CraterBase& base, const State& state);

// ,"crater":{"bed":[...],"reason":...} for a log's summary, or "" when it is not a crater scene.
std::string crater_info_field(const std::optional<CraterBase>& base);

}  // namespace ede::view
