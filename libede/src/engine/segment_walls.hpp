// The state of an engine WithSegments (effects.hpp): the wall segments in the run's scalar type, in the
// scene's order, and the segments each cell looks at (segment_cells.hpp). NoSegments holds NoSegmentWalls.
#pragma once

#include <vector>

#include "core/segment.hpp"
#include "engine/segment_cells.hpp"

namespace ede {

struct NoSegmentWalls {};

template <class T>
struct SegmentWalls {
  std::vector<Segment<T>> seg;
  SegmentCells cells;
  std::size_t memory_bytes() const { return seg.capacity() * sizeof(Segment<T>) + cells.memory_bytes(); }
};

}  // namespace ede
