// The wall segments' own checks (check_segments: finite, inside the box, not of zero length, walls and
// no gravity) and a state's disks clear of them (check_disks_clear_of_segments). The scene loader makes
// the same checks with the file's line and key; these run again where a state or options reach setup or
// the engine from code, so a hand-built run gets a clear message too.
// O(N S) with N disks and S segments: a state is checked once per run, and a scene with 10^6 disks and
// 100 segments takes ~0.1 s. Rejected: a grid of segments here (setup/placement_grid's cells are sized
// for disks; the engine's segment_cells.hpp sits a room above).
#include <cmath>

#include "core/segment.hpp"
#include "setup/placement_grid.hpp"
#include "setup/setup.hpp"

namespace ede {

namespace {
using setup_detail::number_text;

std::string point_text(double x, double y) { return "(" + number_text(x) + ", " + number_text(y) + ")"; }
std::string segment_name(std::size_t k, const SegmentSpec& s) {
  return "wall segment " + std::to_string(k) + " from " + point_text(s.from[0], s.from[1]) + " to " +
         point_text(s.to[0], s.to[1]);
}
}  // namespace

Status check_segments(const std::vector<SegmentSpec>& segments, double lx, double ly, BoundaryKind boundary,
                      bool gravity, const std::string& source) {
  if (segments.empty()) return Ok{};
  if (boundary == BoundaryKind::Periodic)
    return Error{source + ": wall segments need box.boundary = \"walls\" (a segment across a periodic edge has "
                          "no defined image); use walls, or remove [walls]"};
  if (gravity)
    return Error{source + ": wall segments with gravity are not supported yet (a parabola against a slanted "
                          "segment needs a quartic root); remove physics.gravity or the segments"};
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const SegmentSpec& s = segments[k];
    for (double v : {s.from[0], s.from[1], s.to[0], s.to[1], s.restitution})
      if (!std::isfinite(v)) return Error{source + ": " + segment_name(k, s) + " has a non-finite number"};
    if (s.from == s.to)
      return Error{source + ": " + segment_name(k, s) + " has zero length; give two different end points"};
    if (!(s.restitution >= 0 && s.restitution <= 1))
      return Error{source + ": " + segment_name(k, s) + " has restitution " + number_text(s.restitution) +
                   "; use a value from 0 to 1"};
    for (const auto& p : {s.from, s.to})
      if (p[0] < 0 || p[0] > lx || p[1] < 0 || p[1] > ly)
        return Error{source + ": " + segment_name(k, s) + " leaves the box [0, " + number_text(lx) + "] x [0, " +
                     number_text(ly) + "]; move its end points inside"};
  }
  return Ok{};
}

Status check_disks_clear_of_segments(const InitialState& state, const std::vector<SegmentSpec>& segments,
                                     const std::string& source) {
  std::vector<Segment<double>> segs;
  for (const SegmentSpec& s : segments) segs.push_back(make_segment(s.from[0], s.from[1], s.to[0], s.to[1], s.restitution));
  for (std::size_t i = 0; i < state.size(); ++i)
    for (std::size_t k = 0; k < segs.size(); ++k) {
      const double d = segment_distance(segs[k], state.x[i], state.y[i]);
      if (d < state.radius[i] * (1 - 1e-12))
        return Error{source + ": disk " + std::to_string(i) + " at " + point_text(state.x[i], state.y[i]) +
                     " with radius " + number_text(state.radius[i]) + " crosses " + segment_name(k, segments[k]) +
                     " (its centre is " + number_text(d) + " from it); move the disk or the segment, or place "
                     "the species in a region clear of the segments"};
    }
  return Ok{};
}

}  // namespace ede
