// The wrap room: a disk crossing a periodic edge of the box. Its stored position moves by one box length
// (a state change, so it is an event the sinks see and the log records), then it crosses into the cell on
// the other side like any crossing (room_crossing.hpp). Its prediction is the crossing's.
#pragma once

#include <cstdint>

#include "engine/engine_state.hpp"
#include "engine/room_crossing.hpp"

namespace ede {

template <class S>
void resolve_wrap(S& s, std::int32_t i, CrossDir dir) {
  using T = typename S::Scalar;
  static constexpr std::int32_t kWrapOf[] = {kWrapRight, kWrapLeft, kWrapTop, kWrapBottom};
  Disk<T>& d = s.p.disk[i];
  const RecordBefore<T> before = record_before(d);
  wrap_disk(d, s.now, kWrapOf[dir], s.lx, s.ly);
  s.pred[i].clear_fresh();  // its record moved: see Prediction
  if (!s.sinks.empty())
    s.emit({s.now, EventKind::Wrap, false, i, kWrapOf[dir], d.vx, d.vy, T(0), T(0), d.vx, d.vy, T(0), T(0), T(0), T(0),
            T(0), T(0), before, before, false, false});
  cross_cell(s, i, dir, EventKind::Wrap);
}

}  // namespace ede
