// A candidate event while predicting one disk's next event, and the total order that picks the winner.
//
// Among candidates at the same time, the lower kind wins (pair before wall), then the lower partner id:
// the result does not depend on the order cells or disks were visited, which keeps runs reproducible
// after the grid is rebuilt (resume) and between the cell and all-pairs engines.
#pragma once

#include <cstdint>

#include "core/event.hpp"
#include "core/geometry.hpp"

namespace ede {

template <class T>
struct Candidate {
  T time = kNever<T>;
  EventKind kind = EventKind::Pair;
  std::int32_t partner = -1;  // disk id (Pair) or WallId (Wall)

  bool before(const Candidate& o) const {
    if (time != o.time) return time < o.time;
    if (kind != o.kind) return kind < o.kind;
    return partner < o.partner;
  }
};

}  // namespace ede
