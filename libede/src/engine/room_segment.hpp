// The segment room: a disk hitting a wall segment (core/segment.hpp) on its body or at an end point, in an
// engine WithSegments. Its prediction is from the disk's record alone (the time does not depend on now:
// replay predicts it from the same record) against the segments listed in the disk's cell
// (segment_cells.hpp); its resolution applies the segment's rule (collide.hpp) at the disk's position, which
// tells body from end point. Like a wall, a segment leaves no partner to skip.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "engine/collide.hpp"
#include "engine/engine_state.hpp"

namespace ede {

// Segments with their cell lists: a cell lists those within the largest small radius of it (with a margin
// for a centre a hair past its cell's side); a big disk, whose reach is wider, tries them all.
template <class S>
void setup_segments(S& s, const PhysicsSpec& ph, const InitialState& init, const GridShape& shape) {
  using T = typename S::Scalar;
  std::vector<std::array<double, 4>> ends;
  for (const SegmentSpec& g : ph.segments) {
    s.walls.seg.push_back(make_segment(T(g.from[0]), T(g.from[1]), T(g.to[0]), T(g.to[1]), T(g.restitution)));
    ends.push_back({g.from[0], g.from[1], g.to[0], g.to[1]});
  }
  double largest = 0;  // the largest radius in the cell lists (every disk when none is big)
  for (const double r : init.radius)
    if (r <= shape.split.big_radius) largest = std::max(largest, r);
  const double reach = largest * (1 + 1e-6) + 1e-9 * std::max(double(s.lx), double(s.ly));
  s.walls.cells.build(ends, s.grid.nx(), s.grid.ny(), double(s.lx), double(s.ly), reach);
}

// Disk d's earliest segment hit, from its record, against the segments of `cell` (every one for a big disk).
template <class S, class T = typename S::Scalar>
void scan_segments(const S& s, const Disk<T>& d, std::int32_t cell, bool big, Candidate<T>& best) {
  const auto consider = [&](std::int32_t k) {
    const T dt = segment_contact_time(s.walls.seg[std::size_t(k)], d.x, d.y, d.vx, d.vy, d.r, s.b_noise2);
    if (dt == kNever<T>) return;
    T t = d.t + dt;
    if (t < s.now) t = s.now;
    const Candidate<T> c{t, EventKind::Segment, k};
    if (c.before(best)) best = c;
  };
  if (big) {
    for (std::size_t k = 0; k < s.walls.seg.size(); ++k) consider(std::int32_t(k));
    return;
  }
  for (const std::int32_t* k = s.walls.cells.begin(cell); k != s.walls.cells.end(cell); ++k) consider(*k);
}

template <class S>
void resolve_segment(S& s, std::int32_t i, std::int32_t k) {
  using T = typename S::Scalar;
  const RecordBefore<T> before = record_before(s.p.disk[i]);
  s.advance(i);
  Disk<T>& d = s.p.disk[i];
  const T vx0 = d.vx, vy0 = d.vy;
  const bool by_tc = s.tc_elastic(i, -1);
  auto& r = s.dissipation;  // WithSegments engines are Dissipative (engine_factory.hpp)
  const Segment<T>& g = s.walls.seg[std::size_t(k)];
  const double ke_before = s.disk_energy(i);
  collide_segment(g, d.x, d.y, by_tc ? T(2) : g.one_plus_xi, d.vx, d.vy);
  r.ke += s.disk_energy(i) - ke_before;
  r.note_if_too_slow(s.p, i);
  if (r.tc_model) s.p.last_collision[i] = s.now;
  ++d.counter;
  d.last_partner = -1;
  ++s.counts.by_kind[int(EventKind::Segment)];
  if (by_tc) ++s.counts.tc_elastic;
  if (!s.sinks.empty())
    s.emit({s.now, EventKind::Segment, by_tc, i, k, d.vx, d.vy, T(0), T(0), vx0, vy0, T(0), T(0), T(0), T(0), T(0),
            T(0), before, before, false, kRulesAreFormatV2});
  predict_disk(s, i);
}

}  // namespace ede
