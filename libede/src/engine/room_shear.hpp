// The shear room: a Lees-Edwards box's sliding edges (lees_edwards.hpp). Two things happen here:
// - A disk crossing the top (bottom) edge enters through the bottom (top) as the image it has become: y
//   moves by one box height as in a wrap, x by minus (plus) the images' offset now, brought back into the
//   box, and vx by minus (plus) u, the images' velocity. Its physical path goes on unchanged, so the
//   predictions others made of it stay valid and its counter is not touched; it is predicted afresh from
//   its new cell (the cells it neighbours now are not a strip next to the old ones). An event the sinks see
//   and the log records (kind Shear: FORMAT.md). The queue holds it as a wrap (its tag has room for kinds 0
//   to 7 only; the order of kinds at equal times is the wrap's), and the wrap's resolution sends it here.
// - Every half cell the images slide, the disks of the top and bottom rows are predicted again
//   (realign_sliding_rows), since their scans across the edge cover a window of the slid row that is only
//   good for so long. Nothing changes and nothing is logged: like a cell crossing, bookkeeping. The loop
//   takes it by time (engine_core.hpp), after any disk event or action at the same time.
#pragma once

#include <cstdint>

#include "engine/engine_state.hpp"
#include "engine/predict_crossing.hpp"

namespace ede {

// The next realignment (never, in an engine without the sliding edges or when they do not slide).
template <class S>
typename S::Scalar realign_time(const S& s) {
  if constexpr (S::Effects::kSheared)
    return s.shear.next;
  else
    return kNever<typename S::Scalar>;
}

// At a rebuild of the predictions (start, resume, the rebuild interval): the clock starts from now, so a
// run resumed at a rebuild point realigns when the original run did.
template <class S>
void restart_realign_clock(S& s) {
  if constexpr (S::Effects::kSheared) s.shear.next = s.shear.slide > 0 ? s.now + s.shear.period : kNever<typename S::Scalar>;
}

template <class S>
void realign_sliding_rows(S& s, typename S::Scalar t) {
  using T = typename S::Scalar;
  if constexpr (S::Effects::kSheared) {
    s.now = t;
    for (const std::int32_t row : {std::int32_t(0), s.grid.ny() - 1})
      for (std::int32_t c = 0; c < s.grid.nx(); ++c)
        for (std::int32_t k = s.grid.head(s.grid.cell_at(c, row)); k != CellGrid<T>::kNone; k = s.grid.next(k))
          predict_disk(s, k);
    s.shear.next = t + s.shear.period;
  }
}

// Disk i crosses the top (kCrossUp) or bottom (kCrossDown) edge at now.
template <class S>
void resolve_shear(S& s, std::int32_t i, CrossDir dir) {
  using T = typename S::Scalar;
  if constexpr (S::Effects::kSheared) {
    const bool up = dir == kCrossUp;
    Disk<T>& d = s.p.disk[i];
    const RecordBefore<T> before = record_before(d);
    wrap_disk(d, s.now, up ? kWrapTop : kWrapBottom, s.lx, s.ly);
    const T vx0 = d.vx, offset = s.shear.offset(s.now, s.lx);
    const double ke_before = s.disk_energy(i);
    d.x = wrap_into_box(up ? d.x - offset : d.x + offset, s.lx);
    d.vx = up ? d.vx - s.shear.slide : d.vx + s.shear.slide;
    s.dissipation.ke += s.disk_energy(i) - ke_before;
    s.pred[i].clear_fresh();  // its record moved: see Prediction
    ++s.counts.by_kind[int(EventKind::Shear)];
    // The outcome's vjx carries i's new x (FORMAT.md: the log stores it as it is).
    if (!s.sinks.empty())
      s.emit({s.now, EventKind::Shear, false, i, up ? kWrapTop : kWrapBottom, d.vx, d.vy, d.x, T(0), vx0, d.vy, T(0),
              T(0), T(0), T(0), T(0), T(0), before, before, false, false});
    const std::int32_t column = s.grid.cell_x(s.grid.cell_containing(d.x, d.y));
    s.grid.move(i, s.grid.cell_at(column, up ? 0 : s.grid.ny() - 1));
    predict_disk(s, i);
  }
}

}  // namespace ede
