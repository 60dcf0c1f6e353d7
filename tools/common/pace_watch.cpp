// PaceWatch; see pace_watch.hpp.
#include "pace_watch.hpp"

#include <cstdio>

#include "ede/number_text.hpp"

namespace ede::tools {

void PaceWatch::update(double fraction, std::uint64_t events, double wall_seconds) {
  if (done_ || wall_seconds < pilot_seconds_) return;
  done_ = true;
  if (!(fraction > 1e-12)) {  // nothing, or so little that the estimate would be ages
    std::fprintf(stderr,
                 "%s: warning: no measurable progress towards any stop condition after %s s (%llu events): the run "
                 "may never end. Check the [stop] table (an energy_fraction the collisions cannot reach? a time far "
                 "beyond the events?); Ctrl-C stops it and keeps what was done.\n",
                 tool_.c_str(), brief(wall_seconds, 3).c_str(), static_cast<unsigned long long>(events));
    return;
  }
  const double total_seconds = wall_seconds / fraction;
  if (total_seconds < warn_hours_ * 3600) return;
  const double total_events = double(events) / fraction;
  std::fprintf(stderr,
               "%s: warning: at this pace (%s%% after %s s) the run needs about %s hours and %s events to reach its "
               "stop condition. Consider an earlier stop or fewer disks; Ctrl-C stops it and keeps what was done.\n",
               tool_.c_str(), brief(100 * fraction, 2).c_str(), brief(wall_seconds, 3).c_str(),
               brief(total_seconds / 3600, 3).c_str(), brief(total_events, 3).c_str());
}

}  // namespace ede::tools
